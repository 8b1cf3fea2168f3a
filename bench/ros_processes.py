"""Process handling shared by the ROS-side benchmarks: start a program in its own process group
with a ROS environment, stop it (and its children) cleanly."""
import os
import signal
import subprocess


def ros_environment(master_port):
    """This environment with a private master on `master_port`, Debian's python first."""
    env = dict(os.environ, ROS_HOSTNAME="localhost", ROS_MASTER_URI="http://localhost:%d" % master_port)
    env["PATH"] = "/usr/bin:" + env.get("PATH", "")
    return env


def start(command, env):
    return subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            preexec_fn=os.setsid)


def stop(process):
    try:
        os.killpg(process.pid, signal.SIGINT)
        process.wait(timeout=15)
    except (ProcessLookupError, subprocess.TimeoutExpired):
        os.killpg(process.pid, signal.SIGKILL)


def report(table, markdown_path):
    """Prints a Markdown table and, if a path is given, writes it there too."""
    print(table)
    if markdown_path:
        with open(markdown_path, "w") as f:
            f.write(table + "\n")
