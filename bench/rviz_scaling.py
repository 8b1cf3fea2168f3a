#!/usr/bin/python3
"""rviz with N walking humans in view: DressedHuman displays (vertices evaluated by the vertex
shader, the default, and by the CPU) against the same number of RobotModel displays of the same
URDF, in one run (bench/rviz_display_scaling.cpp does the rviz side).

Every human stays in view for the whole measurement: each is its own skeleton_publisher
(namespace human_<i>, frames suffixed _<i>) walking in place (a copy of walk.yaml with
forward_speed 0), the humans 1 m apart in a row, the camera 12 m in front of the row's middle.
Each point saves a screenshot when its measurement starts and one when it ends, and fails unless
every one of its N humans is drawn in both (figure pixels inside the box its position projects
to). Reports fps (rviz's cap is 30), rviz CPU, and rviz CPU per human per frame: (rviz CPU per
frame - the empty scene's) / N; also what the DressedHuman display measures of its own update().

Usage: bench/rviz_scaling.py [--seconds 15] [--counts 1 5 10] [--markdown docs/rviz_scaling.md]
       [--csv out.csv] [--chart docs/rviz_scaling.png] [--screenshots docs/rviz_scaling]
Needs the package built in build/ and xvfb-run. Exits 1 if a point did not draw all its humans.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy
from PIL import Image

from ros_processes import report, ros_environment, start, stop

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "test", "ros"))
from on_screen import OrbitView, figure_pixels_in_box  # noqa: E402

DEVEL = os.path.join(ROOT, "build", "devel")
# (label, display class, extra harness arguments)
SUBJECTS = [("DressedHuman (GPU vertices)", "dressed_human/DressedHuman", []),
            ("DressedHuman (CPU vertices)", "dressed_human/DressedHuman", ["--set", "Vertex Evaluation=CPU"]),
            ("RobotModel", "rviz/RobotModel", [])]
DISTANCE, YAW, PITCH, FOCAL_Z = 12.0, 0.0, 0.25, 0.9
# rviz_display_scaling's render panel; rviz's default vertical field of view.
VIEW = OrbitView(DISTANCE, YAW, PITCH, (0.0, 0.0, FOCAL_Z))
MIN_FIGURE_PIXELS = 150  # a human at 12 m covers about 2,000 (DressedHuman) or 700 (RobotModel)


def row_offsets(count):
    """y of each human: 1 m apart, centred on the view."""
    return [i - (count - 1) / 2.0 for i in range(count)]


def drawn(path, offsets):
    """How many of the humans at `offsets` show in the screenshot at `path`."""
    image = numpy.asarray(Image.open(path).convert("RGB")).astype(numpy.float64)
    return sum(1 for y in offsets
               if figure_pixels_in_box(image, VIEW, (-0.5, y - 0.45, -0.05), (0.5, y + 0.45, 1.9)) >= MIN_FIGURE_PIXELS)


def harness(display_class, count, seconds, extra, screenshot, env):
    command = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", os.path.join(DEVEL, "env.sh"),
               os.path.join(DEVEL, "lib", "dressed_human", "rviz_display_scaling"), display_class, str(count),
               str(seconds), "--distance", str(DISTANCE), "--focal", "0;0;%g" % FOCAL_Z, "--view", "Yaw=%g" % YAW,
               "--view", "Pitch=%g" % PITCH, "--view", "Target Frame=<Fixed Frame>", "--screenshot", screenshot] + extra
    output = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, timeout=seconds + 180).stdout
    match = re.search(r"fps=([\d.]+) cpu_percent=([\d.]+) cpu_ms_per_frame=([\d.]+) display_ms=([-\d.]+)", output)
    if not match:
        raise RuntimeError("harness failed for %s x %d:\n%s" % (display_class, count, output[-2000:]))
    for line in output.splitlines():
        if line.startswith("status "):
            print("  %s x %d: %s" % (display_class, count, line), file=sys.stderr)
    return dict(zip(("fps", "cpu_percent", "cpu_ms_per_frame", "display_ms"), (float(v) for v in match.groups())))


def chart(results, counts, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    for label, _, _ in SUBJECTS:
        points = [results[(label, n)] for n in counts]
        axes[0].plot(counts, [p["fps"] for p in points], "o-", label=label)
        axes[1].plot(counts, [p["per_human_ms"] for p in points], "o-", label=label)
    axes[0].axhline(30.0, color="grey", lw=0.8, ls="--")
    axes[0].set_ylabel("frames per second (rviz caps at 30)")
    axes[1].set_ylabel("rviz CPU per human per frame (ms)\n(rviz CPU per frame - empty scene) / N")
    for ax in axes:
        ax.set_xlabel("humans in view")
        ax.set_xticks(counts)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    figure.suptitle("Walking humans in view at 12 m, rviz on Mesa llvmpipe, %d cores (bench/rviz_scaling.py)"
                    % os.cpu_count())
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    plt.close(figure)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seconds", type=float, default=15.0)
    parser.add_argument("--counts", type=int, nargs="+", default=[1, 5, 10])
    parser.add_argument("--markdown", default="")
    parser.add_argument("--csv", default="")
    parser.add_argument("--chart", default="")
    parser.add_argument("--screenshots", default="")
    args = parser.parse_args()
    shots = args.screenshots or tempfile.mkdtemp()
    os.makedirs(shots, exist_ok=True)

    env = ros_environment(11911)
    node = os.path.join(DEVEL, "lib", "dressed_human", "skeleton_publisher")
    with open(os.path.join(ROOT, "config", "motions", "walk.yaml")) as f:
        motion_text = f.read()
    in_place, replaced = re.subn(r"(\n\s*forward_speed:\s*)[-+0-9.eE]+", r"\g<1>0.0", motion_text)
    if replaced != 1:
        raise RuntimeError("config/motions/walk.yaml: expected one root forward_speed to set to 0")
    motion = os.path.join(tempfile.mkdtemp(), "walk_in_place.yaml")
    with open(motion, "w") as f:
        f.write(in_place)
    urdf = os.path.join(ROOT, "urdf", "human.urdf")
    most = max(args.counts)
    processes = [start(["roscore", "-p", "11911"], env)]
    results = {}
    try:
        time.sleep(4)
        import rosgraph  # after ROS_MASTER_URI is known to this process
        master = rosgraph.Master("/rviz_scaling", master_uri=env["ROS_MASTER_URI"])
        baseline = harness("rviz/Grid", 0, args.seconds, [], os.path.join(shots, "empty.png"), env)
        for count in args.counts:
            # Humans 0..count-1 of a row centred on the view: restarted per count, so that
            # display i always finds human i at its place in this count's row.
            nodes = []
            for i, y in enumerate(row_offsets(count)):
                text = subprocess.run([os.path.join(ROOT, "scripts", "suffix_urdf.py"), urdf, str(i)], check=True,
                                      stdout=subprocess.PIPE, universal_newlines=True).stdout
                master.setParam("/human_%d/robot_description" % i, text)
                nodes.append(start([node, "__ns:=/human_%d" % i, "_motion_file:=" + motion, "_origin_y:=%g" % y,
                                    "_publish_joint_states:=false"], env))
            time.sleep(2)
            try:
                for label, display_class, extra in SUBJECTS:
                    name = re.sub(r"[^a-z]+", "_", label.lower()).strip("_")
                    screenshot = os.path.join(shots, "%s_%d.png" % (name, count))
                    point = harness(display_class, count, args.seconds, extra, screenshot, env)
                    start_shot = screenshot[:-4] + "_start.png"
                    point["drawn"] = min(drawn(start_shot, row_offsets(count)), drawn(screenshot, row_offsets(count)))
                    point["per_human_ms"] = (point["cpu_ms_per_frame"] - baseline["cpu_ms_per_frame"]) / count
                    point["screenshot"] = os.path.relpath(screenshot, ROOT)
                    results[(label, count)] = point
                    print(label, count, point, file=sys.stderr)
            finally:
                for process in nodes:
                    stop(process)
    finally:
        for process in reversed(processes):
            stop(process)

    failed = [(label, n) for (label, n), p in results.items() if p["drawn"] < n]
    lines = ["| humans | display | drawn | fps | rviz CPU | rviz CPU per human per frame | display's own update per "
             "human per frame |", "|---|---|---|---|---|---|---|"]
    rows = ["display,humans,drawn,fps,cpu_percent,cpu_ms_per_frame,per_human_ms,display_ms,screenshot"]
    for count in args.counts:
        for label, _, _ in SUBJECTS:
            p = results[(label, count)]
            own = "%.3f ms" % p["display_ms"] if p["display_ms"] >= 0 else "—"
            drawn_text = "%d/%d" % (p["drawn"], count) + ("" if p["drawn"] == count else " **FAILED**")
            lines.append("| %d | %s | %s | %.1f | %.0f %% | %.2f ms | %s |" % (
                count, label, drawn_text, p["fps"], p["cpu_percent"], p["per_human_ms"], own))
            rows.append("%s,%d,%d,%.2f,%.1f,%.3f,%.3f,%.3f,%s" % (label, count, p["drawn"], p["fps"], p["cpu_percent"],
                                                                p["cpu_ms_per_frame"], p["per_human_ms"],
                                                                p["display_ms"], p["screenshot"]))
    lines.append("")
    lines.append("Empty scene: %.1f fps, %.0f %% CPU, %.2f ms per frame. Humans walking in place 1 m apart, camera "
                 "%g m in front of the row; %g s per point after 5 s of warm-up; rviz CPU in %% of one core, Mesa "
                 "llvmpipe (software rendering) on %d cores; \"drawn\": humans visible in both the screenshot at the "
                 "start and at the end of the point (`%s/`); `bench/rviz_scaling.py`."
                 % (baseline["fps"], baseline["cpu_percent"], baseline["cpu_ms_per_frame"], DISTANCE, args.seconds,
                    os.cpu_count(), os.path.relpath(shots, ROOT)))
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("\n".join(rows) + "\n")
    if args.chart:
        chart(results, args.counts, args.chart)
    report("\n".join(lines), args.markdown)
    if failed:
        print("rviz_scaling.py: not every human drawn in %s" % ", ".join("%s x %d" % f for f in failed), file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
