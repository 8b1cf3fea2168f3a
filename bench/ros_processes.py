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
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass  # already gone: its failure is reported by the caller


def report(table, markdown_path):
    """Prints a Markdown table and, if a path is given, writes it there too."""
    print(table)
    if markdown_path:
        with open(markdown_path, "w") as f:
            f.write(table + "\n")


def start_frozen_human(root, env, caller, start_phase=1.0, motion_file=None):
    """Human 0 (namespace human_0, frames suffixed _0) frozen in one pose of the shipped walk, or
    of `motion_file` (replayed, mode replay, at speed_factor 0 from the node's start_phase, radians
    of the cycle; in walk mode speed 0 would make it stand, whatever the phase): its
    robot_description on the master of `env`, and its skeleton_publisher process, started.
    `caller`: this program's name on the master."""
    import rosgraph  # after ROS_MASTER_URI is known to this process
    import time
    master = rosgraph.Master(caller, master_uri=env["ROS_MASTER_URI"])
    text = subprocess.run([os.path.join(root, "scripts", "suffix_urdf.py"), os.path.join(root, "urdf", "human.urdf"),
                           "0"], check=True, stdout=subprocess.PIPE, universal_newlines=True).stdout
    master.setParam("/human_0/robot_description", text)
    process = start([os.path.join(root, "build", "devel", "lib", "dressed_human", "skeleton_publisher"),
                     "__ns:=/human_0",
                     "_motion_file:=" + (motion_file or os.path.join(root, "config", "motions", "walk.yaml")),
                     "_mode:=replay", "_speed_factor:=0.0", "_start_phase:=%g" % start_phase, "_publish_joint_states:=false"], env)
    time.sleep(2)
    if process.poll() is not None:
        raise RuntimeError("the frozen human's skeleton_publisher exited (status %s); is the workspace's "
                           "setup.bash sourced (rospack must find dressed_human)?" % process.returncode)
    return process
