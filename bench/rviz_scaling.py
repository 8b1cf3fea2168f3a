#!/usr/bin/python3
"""rviz with 1, 5 and 10 walking humans: DressedHuman displays against the same number of
RobotModel displays of the same URDF, in one run (bench/rviz_display_scaling.cpp does the rviz
side). Each human is its own skeleton_publisher (namespace human_<i>, frames suffixed _<i>, 1 m
apart). Reports fps (rviz's target is 30), rviz CPU and, from the difference to an empty rviz, the
display CPU per human per frame.

Usage: bench/rviz_scaling.py [--seconds 15] [--counts 1 5 10] [--markdown docs/rviz_scaling.md]
Needs the package built in build/ and xvfb-run.
"""
import argparse
import os
import re
import subprocess
import sys
import time

from ros_processes import report, ros_environment, start, stop

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEVEL = os.path.join(ROOT, "build", "devel")
CLASSES = ["dressed_human/DressedHuman", "rviz/RobotModel"]




def harness(display_class, count, seconds, env):
    command = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", os.path.join(DEVEL, "env.sh"),
               os.path.join(DEVEL, "lib", "dressed_human", "rviz_display_scaling"), display_class, str(count),
               str(seconds)]
    output = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, timeout=seconds + 120).stdout
    match = re.search(r"fps=([\d.]+) cpu_percent=([\d.]+) cpu_ms_per_frame=([\d.]+) display_ms=([-\d.]+)", output)
    if not match:
        raise RuntimeError("harness failed for %s x %d:\n%s" % (display_class, count, output[-2000:]))
    return tuple(float(v) for v in match.groups())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seconds", type=float, default=15.0)
    parser.add_argument("--counts", type=int, nargs="+", default=[1, 5, 10])
    parser.add_argument("--markdown", default="")
    args = parser.parse_args()

    env = ros_environment(11911)
    node = os.path.join(DEVEL, "lib", "dressed_human", "skeleton_publisher")
    motion = os.path.join(ROOT, "config", "motions", "walk.yaml")
    urdf = os.path.join(ROOT, "urdf", "human.urdf")
    processes = [start(["roscore", "-p", "11911"], env)]
    try:
        time.sleep(4)
        import rosgraph  # after ROS_MASTER_URI is known to this process
        master = rosgraph.Master("/rviz_scaling", master_uri=env["ROS_MASTER_URI"])
        for i in range(max(args.counts)):
            text = subprocess.run([os.path.join(ROOT, "scripts", "suffix_urdf.py"), urdf, str(i)], check=True,
                                  stdout=subprocess.PIPE, universal_newlines=True).stdout
            master.setParam("/human_%d/robot_description" % i, text)
            processes.append(start([node, "__ns:=/human_%d" % i, "_motion_file:=" + motion,
                                    "_origin_y:=%g" % float(i), "_publish_joint_states:=false"], env))
        time.sleep(2)
        baseline = harness("rviz/Grid", 0, args.seconds, env)
        results = {}
        for count in args.counts:
            for display_class in CLASSES:
                results[(display_class, count)] = harness(display_class, count, args.seconds, env)
                print(display_class, count, results[(display_class, count)], file=sys.stderr)
    finally:
        for process in reversed(processes):
            stop(process)

    lines = ["| humans | DressedHuman fps | DressedHuman rviz CPU | RobotModel fps | RobotModel rviz CPU | CPU ratio | "
             "DressedHuman CPU per human per frame |", "|---|---|---|---|---|---|---|"]
    for count in args.counts:
        dressed, robot = results[(CLASSES[0], count)], results[(CLASSES[1], count)]
        per_human = dressed[3]  # measured by each display on rviz's thread (thread CPU time)
        lines.append("| %d | %.1f | %.0f %% | %.1f | %.0f %% | %.2f | %.3f ms |" % (
            count, dressed[0], dressed[1], robot[0], robot[1], dressed[1] / robot[1], per_human))
    lines.append("")
    lines.append("Empty rviz (grid only): %.1f fps, %.0f %% CPU, %.3f ms per frame. %g s per point; rviz CPU in %% of "
                 "one core, Mesa llvmpipe (software rendering) on %d cores; `bench/rviz_scaling.py`."
                 % (baseline[0], baseline[1], baseline[2], args.seconds, os.cpu_count()))
    report("\n".join(lines), args.markdown)


if __name__ == "__main__":
    main()
