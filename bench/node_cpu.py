#!/usr/bin/python3
"""CPU of skeleton_publisher against robot_state_publisher, in one run, at 100 Hz and 1 kHz.

Both publish TF for the same URDF at the same rate: our node from its Fourier motion; RSP from a
JointState stream at that rate (produced by a second skeleton_publisher whose own TF goes nowhere;
its CPU is not counted). Each TF stream has one subscriber. CPU is read from /proc (user+system
time) over the same window, several windows per rate; medians are reported.

Usage: bench/node_cpu.py [--seconds 10] [--windows 3] [--markdown docs/node_cpu.md]
Needs the package built (build/devel/setup.bash) and a free ROS master port.
"""
import argparse
import os
import statistics
import subprocess
import sys
import time

import rosgraph

from ros_processes import report, ros_environment, start, stop

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MOTION = os.path.join(ROOT, "config", "motions", "walk.yaml")


def cpu_seconds(pid):
    """CPU time of the process so far, from the scheduler's nanosecond counter (all threads)."""
    total = 0
    for thread in os.listdir("/proc/%d/task" % pid):
        with open("/proc/%d/task/%s/schedstat" % (pid, thread)) as f:
            total += int(f.read().split()[0])
    return total * 1e-9




def measure(rate, seconds, windows, env, urdf):
    node = os.path.join(ROOT, "build", "devel", "lib", "dressed_human", "skeleton_publisher")
    rsp = "/usr/lib/robot_state_publisher/robot_state_publisher"
    processes = []
    try:
        master = rosgraph.Master("/node_cpu_benchmark", master_uri=env["ROS_MASTER_URI"])
        master.setParam("/robot_description", urdf)
        master.setParam("/rsp/robot_description", urdf)
        ours = start([node, "__name:=ours", "_rate:=%g" % rate, "_publish_joint_states:=false",
                      "_motion_file:=" + MOTION], env)
        source = start([node, "__name:=joint_source", "_rate:=%g" % rate, "_motion_file:=" + MOTION, "/tf:=/unused_tf",
                        "/tf_static:=/unused_tf_static"], env)
        theirs = start([rsp, "__ns:=/rsp", "_publish_frequency:=%g" % rate, "joint_states:=/joint_states",
                        "/tf:=/rsp/tf", "/tf_static:=/rsp/tf_static"], env)
        listeners = [start(["rostopic", "hz", topic], env) for topic in ("/tf", "/rsp/tf")]
        processes = [ours, source, theirs] + listeners
        time.sleep(4.0)  # connections settle
        samples = {"skeleton_publisher": [], "robot_state_publisher": []}
        for _ in range(windows):
            begin = {name: cpu_seconds(p.pid) for name, p in (("skeleton_publisher", ours), ("robot_state_publisher", theirs))}
            t0 = time.monotonic()
            time.sleep(seconds)
            elapsed = time.monotonic() - t0
            for name, p in (("skeleton_publisher", ours), ("robot_state_publisher", theirs)):
                samples[name].append(100.0 * (cpu_seconds(p.pid) - begin[name]) / elapsed)
        for process in processes:
            if process.poll() is not None:
                raise RuntimeError("%s exited early with code %s" % (process.args[0], process.returncode))
        return {name: statistics.median(values) for name, values in samples.items()}, samples
    finally:
        for process in processes:
            stop(process)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--windows", type=int, default=3)
    parser.add_argument("--rates", type=float, nargs="+", default=[100.0, 1000.0])
    parser.add_argument("--markdown", default="")
    args = parser.parse_args()

    env = ros_environment(11411)
    with open(os.path.join(ROOT, "urdf", "human.urdf")) as f:
        urdf = f.read()
    master = start(["roscore", "-p", "11411"], env)
    try:
        time.sleep(4.0)
        rows = []
        for rate in args.rates:
            medians, samples = measure(rate, args.seconds, args.windows, env, urdf)
            ratio = medians["skeleton_publisher"] / medians["robot_state_publisher"]
            rows.append((rate, medians["skeleton_publisher"], medians["robot_state_publisher"], ratio))
            print("rate %g Hz: samples %s" % (rate, samples), file=sys.stderr)
    finally:
        stop(master)

    cpu = os.popen("grep -m1 'model name' /proc/cpuinfo").read().split(":")[-1].strip()
    lines = ["| TF rate | skeleton_publisher CPU | robot_state_publisher CPU | ratio |",
             "|---|---|---|---|"]
    for rate, ours, theirs, ratio in rows:
        lines.append("| %g Hz | %.2f %% | %.2f %% | %.2f |" % (rate, ours, theirs, ratio))
    lines.append("")
    lines.append("Median of %d windows of %g s, %% of one core, on %s (%d cores); `bench/node_cpu.py`."
                 % (args.windows, args.seconds, cpu, os.cpu_count()))
    report("\n".join(lines), args.markdown)


if __name__ == "__main__":
    main()
