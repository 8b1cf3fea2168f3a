#!/usr/bin/python3
"""How closely dressed humans follow real pedestrians (issue 36), and what following them costs.

Accuracy: src/tools/track_following.cpp on recorded crowds nobody here made (the shared Jülich
recordings, and any others given): each recording resampled at an input rate (2.5, 10, 25 Hz: an
ETH/UCY annotation, a typical tracker, a camera), fed to the core's TrackedCrowd as a tracker's
messages would come, the walkers ticking at 30 Hz; each walker's root against the recording at the
render time, its heading against the recording's direction of travel over a stride, the feet's
slide per stance, the lowest sole; for each smoothing window of the sweep.

Cost: the crowd_publisher node of people.launch following trajectories.launch's player on the
bottleneck recording (75 people at once), its CPU in % of one core over --seconds, at the
recording's 25 Hz and at 10 Hz (frame_rate:=10: the recording in slow motion, 10 messages a
second).

Usage: bench/track_following.py --tool BUILD/devel/lib/dressed_human/track_following
       [--recordings FILE...] [--seconds 30] [--markdown F] [--csv F] [--chart F]
"""
import argparse
import csv
import io
import os
import subprocess
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ros_processes import report, ros_environment, start, stop  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.path.join(os.path.dirname(ROOT), "shared", "data", "people")
RATES = [2.5, 10.0, 25.0]
SMOOTHINGS = [0.0, 0.15, 0.3, 0.4, 0.5]
DEFAULT_SMOOTHING = 0.4  # PersonTrackSettings::smoothing, people.launch's default
GOALS = "root within 0.10 m median, 0.30 m 95th percentile; heading within 25° (95th percentile, above 0.5 m/s); " \
        "foot slide per stance <= 5 mm median; every track of 1 s drawn; none left 1.5 s after its end"


def run_tool(tool, recordings):
    output = subprocess.run([tool, ROOT] + recordings + ["--rates"] + [str(r) for r in RATES] +
                            ["--smoothing"] + [str(s) for s in SMOOTHINGS],
                            check=True, capture_output=True, text=True).stdout
    return list(csv.DictReader(io.StringIO(output)))


def cpu_seconds(pid):
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def node_pid(name, launch):
    """The pid of the child of `launch` (roslaunch) running node `name`, or None."""
    for _ in range(30):
        found = subprocess.run(["pgrep", "-P", str(launch.pid), "-f", "__name:=%s( |$)" % name], capture_output=True,
                               text=True).stdout.split()
        if found:
            return int(found[0])
        time.sleep(1.0)
    return None


def node_cpu(recording, frame_rate, seconds, env):
    """crowd_publisher's CPU (% of one core) following trajectories.launch (no rviz), and the most
    humans it published at once."""
    launch = start(["roslaunch", "--wait", "dressed_human", "trajectories.launch", "file:=" + recording,
                    "rviz:=false", "frame_rate:=%g" % frame_rate], env)
    try:
        pid = node_pid("people_crowd", launch)
        if pid is None:
            raise RuntimeError("people_crowd did not start")
        time.sleep(5.0)  # every track seen, the walkers placed
        before, wall = cpu_seconds(pid), time.time()
        count = subprocess.run([sys.executable, "-c", COUNT_HUMANS], env=env, capture_output=True, text=True,
                               timeout=60).stdout.strip()
        time.sleep(max(0.0, seconds - (time.time() - wall)))
        percent = 100.0 * (cpu_seconds(pid) - before) / (time.time() - wall)
        return percent, int(count or 0)
    finally:
        stop(launch)


# The most humans in the /crowd messages over 5 s (rospy, Debian's python).
COUNT_HUMANS = """
import rospy
from dressed_human.msg import Crowd
most = [0]
rospy.init_node("count_humans", anonymous=True)
rospy.Subscriber("/crowd", Crowd, lambda m: most.__setitem__(0, max(most[0], len(m.humans))))
rospy.sleep(5.0)
print(most[0])
"""


def chart(rows, path):
    files = sorted(set(r["file"] for r in rows))
    figure, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    for f, name in enumerate(files):
        style = ["-", "--", ":"][f % 3]
        short = name.replace(".txt", "").replace("juelich_", "")
        for smoothing in SMOOTHINGS:
            points = sorted((float(r["rate_hz"]), r) for r in rows if r["file"] == name and float(r["smoothing_s"]) == smoothing)
            rates = [p[0] for p in points]
            label = "%s, ±%g s" % (short, smoothing)
            width = 2.5 if smoothing == DEFAULT_SMOOTHING else 1.0
            axes[0].plot(rates, [100 * float(p[1]["root_median_m"]) for p in points], style, marker="o", lw=width, label=label)
            axes[1].plot(rates, [100 * float(p[1]["root_p95_m"]) for p in points], style, marker="o", lw=width)
            axes[2].plot(rates, [float(p[1]["heading_p95_deg"]) for p in points], style, marker="o", lw=width)
    for axis, title, goal, unit in ((axes[0], "root error, median", 10, "cm"), (axes[1], "root error, 95th percentile", 30, "cm"),
                                    (axes[2], "heading error, 95th percentile (> 0.5 m/s)", 25, "degrees")):
        axis.axhline(goal, color="red", lw=0.8)
        axis.set_title(title + " (goal: red)")
        axis.set_xlabel("input rate (Hz)")
        axis.set_ylabel(unit)
        axis.set_xscale("log")
        axis.set_xticks(RATES)
        axis.set_xticklabels(["%g" % r for r in RATES])
        axis.set_ylim(bottom=0)
    axes[0].legend(fontsize=7, ncol=2)
    slide = max(float(r["slide_p95_mm"]) for r in rows)
    figure.suptitle("Walkers following recorded pedestrians, per input rate and smoothing window (thick: the default); "
                    "foot slide per stance at most %.1f mm (95th percentile) in every case (bench/track_following.py)"
                    % slide, fontsize=10)
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    plt.close(figure)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tool", required=True)
    parser.add_argument("--recordings", nargs="+", default=[os.path.join(SHARED, f) for f in
                                                             ("juelich_uni_corr_500_01.txt", "juelich_bottleneck_040_c_56_h-.txt")])
    parser.add_argument("--seconds", type=float, default=30.0)
    parser.add_argument("--markdown", default="")
    parser.add_argument("--csv", default="")
    parser.add_argument("--chart", default="")
    args = parser.parse_args()

    rows = run_tool(args.tool, args.recordings)
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            writer.writeheader()
            writer.writerows(rows)
    if args.chart:
        chart(rows, args.chart)

    env = ros_environment(11923)
    core = start(["roscore", "-p", "11923"], env)
    costs = []
    try:
        time.sleep(4.0)
        bottleneck = [r for r in args.recordings if "bottleneck" in r] or args.recordings[:1]
        for frame_rate in (25.0, 10.0):
            percent, humans = node_cpu(bottleneck[0], frame_rate, args.seconds, env)
            costs.append((frame_rate, percent, humans))
    finally:
        stop(core)

    lines = ["| recording | input | smoothing (delay) | tracks of >= 1 s drawn | latest appearance / leaving | "
             "root error median / 95 % | heading error 95 % | foot slide per stance median / 95 % | lowest sole |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if float(r["smoothing_s"]) != DEFAULT_SMOOTHING:
            continue
        lines.append("| %s | %g Hz | ±%g s (%.2f s) | %s/%s | %.2f s / %.2f s | %.3f m / %.3f m | %.1f° | %.1f / %.1f mm | %.1f mm |" % (
            r["file"], float(r["rate_hz"]), float(r["smoothing_s"]), float(r["delay_s"]), r["tracks_1s_drawn"],
            r["tracks_1s"], float(r["latest_appearance_s"]), float(r["latest_leave_s"]), float(r["root_median_m"]),
            float(r["root_p95_m"]), float(r["heading_p95_deg"]), float(r["slide_median_mm"]), float(r["slide_p95_mm"]),
            float(r["lowest_sole_mm"])))
    lines.append("")
    lines.append("Goals: %s. The default smoothing window (±%g s) shown; every window of the sweep (%s s) is in "
                 "the chart and the CSV. The recordings resampled at each input rate, the walkers at 30 Hz; "
                 "`src/tools/track_following.cpp`, `bench/track_following.py`." % (
                     GOALS, DEFAULT_SMOOTHING, ", ".join("%g" % s for s in SMOOTHINGS)))
    lines.append("")
    for frame_rate, percent, humans in costs:
        lines.append("- crowd_publisher following `trajectories.launch` on the bottleneck recording at %g Hz%s: "
                     "**%.1f %%** of one core with up to %d humans at once (goal: <= 50 %% for 50 tracks at 10 Hz)." % (
                         frame_rate, "" if frame_rate == 25.0 else " (frame_rate:=10, the recording slowed down)",
                         percent, humans))
    report("\n".join(lines), args.markdown)


if __name__ == "__main__":
    main()
