#!/usr/bin/python3
"""Memory per additional human in rviz, measured so that TF traffic is not counted as humans.

rviz's resident memory at the end of a run grows with time while TF streams in (with N
skeleton_publishers at 100 Hz, even with only a Grid display), so the end-of-point memory of
bench/rviz_scaling.py counts the publishers' traffic with the displays. Here the same N humans
publish in every run, and runs of the same length differ only in what rviz draws:
  Grid only (0 displays), 1 DressedHuman display (human 0), N DressedHuman displays, and one
  DressedHuman display drawing every human in TF;
memory per additional human = (N displays - 1 display) / (N - 1), and the same for the one crowd
display against 1 display. A Grid-only run twice as long gives the growth per second that TF alone
causes. Every DressedHuman run must draw all its humans (checked by a screenshot, as in
bench/rviz_scaling.py).

Usage: bench/rviz_memory.py [--humans 10] [--seconds 15] [--markdown docs/rviz_memory.md]
Needs the package built in build/ and xvfb-run.
"""
import argparse
import os
import sys
import tempfile
import time

import rviz_scaling as rs
from ros_processes import report, ros_environment, start, stop


def run(display_class, displays, seconds, extra, shots, name, env, humans, shown):
    """rviz's resident memory (MB) at the end of a run that must draw the first `shown` humans."""
    screenshot = os.path.join(shots, name + ".png")
    point = rs.harness(display_class, displays, seconds, extra, screenshot, env)
    places = rs.positions(humans)[:shown]
    orbit = rs.view(humans, 12.0)
    drawn = min(rs.drawn(screenshot[:-4] + "_start.png", places, orbit), rs.drawn(screenshot, places, orbit))
    if drawn < shown:
        raise RuntimeError("%s: %d of %d humans drawn" % (name, drawn, shown))
    print(name, point, file=sys.stderr)
    return point["rss_mb"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--humans", type=int, default=10)
    parser.add_argument("--seconds", type=float, default=15.0)
    parser.add_argument("--markdown", default="")
    args = parser.parse_args()
    if args.humans < 2 or args.humans > rs.ROW_LENGTH:
        sys.exit("rviz_memory.py: --humans must be 2 to %d (one row in view)" % rs.ROW_LENGTH)
    shots = tempfile.mkdtemp()
    env = ros_environment(11914)
    node = os.path.join(rs.DEVEL, "lib", "dressed_human", "skeleton_publisher")
    motion = rs.walk_in_place_motion(shots)
    processes = [start(["roscore", "-p", "11914"], env)]
    n = args.humans
    try:
        time.sleep(4)
        import rosgraph  # after ROS_MASTER_URI is known to this process
        master = rosgraph.Master("/rviz_memory", master_uri=env["ROS_MASTER_URI"])
        nodes = rs.start_humans(n, node, motion, os.path.join(rs.ROOT, "urdf", "human.urdf"), master, env)
        try:
            grid = run("rviz/Grid", 0, args.seconds, [], shots, "grid", env, n, 0)
            grid_long = run("rviz/Grid", 0, 2 * args.seconds, [], shots, "grid_long", env, n, 0)
            one = run("dressed_human/DressedHuman", 1, args.seconds, [], shots, "one", env, n, 1)
            many = run("dressed_human/DressedHuman", n, args.seconds, [], shots, "many", env, n, n)
            crowd = run("dressed_human/DressedHuman", 1, args.seconds, ["--set", "Humans=Every Human in TF"], shots,
                        "crowd", env, n, n)
        finally:
            for process in nodes:
                stop(process)
    finally:
        for process in reversed(processes):
            stop(process)
    lines = ["| rviz drawing (%d humans publishing TF at 100 Hz throughout) | resident memory at the end |" % n,
             "|---|---|",
             "| Grid only, %g s | %.0f MB |" % (args.seconds, grid),
             "| Grid only, %g s | %.0f MB |" % (2 * args.seconds, grid_long),
             "| 1 DressedHuman display, %g s | %.0f MB |" % (args.seconds, one),
             "| %d DressedHuman displays, %g s | %.0f MB |" % (n, args.seconds, many),
             "| 1 DressedHuman display drawing every human in TF, %g s | %.0f MB |" % (args.seconds, crowd),
             "",
             "Memory per additional human: %.1f MB with a display each ((%d displays - 1) / %d), %.1f MB with one "
             "display for all; TF traffic alone grows rviz by %.1f MB per second (Grid only, %g s against %g s). "
             "Harness runs as in `bench/rviz_scaling.py` (5 s of warm-up, humans walking in place 12 m away, each "
             "drawn in a screenshot at the start and the end); `bench/rviz_memory.py`."
             % ((many - one) / (n - 1), n, n - 1, (crowd - one) / (n - 1), (grid_long - grid) / args.seconds,
                2 * args.seconds, args.seconds)]
    report("\n".join(lines), args.markdown)


if __name__ == "__main__":
    main()
