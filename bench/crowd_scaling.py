#!/usr/bin/python3
"""A crowd in rviz from one publisher (issue 35): frame rate and rviz CPU per human per frame for
N walking humans drawn by one DressedHuman display from crowd_publisher's dressed_human/Crowd
messages ("Humans: From Topic"), against spencer's walking-man meshes (the crowd peer: its
TrackedPersons display, "Person meshes") fed one TrackedPersons message for all persons at the
same rate, in the same run, at the same places; then rviz's resident memory over minutes with the
shipped `crowd.launch count:=40` and its rviz config.

Scene points (bench/rviz_display_scaling.cpp does the rviz side): the humans walk on treadmills
(crowd file `treadmill: true`, 1.2 m/s, 30 Hz messages) in rows of 10, 1 m apart, rows 3.5 m apart,
the camera --points' distance from the middle of the nearest row (pitched 0.25 rad for one row,
0.7 rad for more, as bench/rviz_scaling.py's views), every other row farther off. Each point saves
a screenshot when its measurement starts and one when it ends and fails unless every one of its
N figures is drawn in both (rviz_scaling.drawn): at least MIN_BOX_SHARE of the box its place projects to (0.6 m wide
across the row, where neighbours stand 1 m apart; rows far enough apart that no box overlaps the
next row's on screen) covered by figure pixels. rviz CPU per human
per frame = (rviz CPU per frame - rviz drawing only its grid) / N, the grid's cost the median of
every grid run at that N, each measured while one subject's publisher runs (ours and the peer's
alike). The crowd publisher's own CPU is measured while ours are.

Memory: `roslaunch dressed_human crowd.launch count:=40`, as a user starts it (rviz's default
anti-aliasing, as in the harness, which does not disable it), on its own virtual X server for
--memory-minutes, rviz's resident memory sampled every 10 s, screenshots judged as the on-screen
rostests judge them (each human's root frame body_<id> from TF, its box grown by the body's
reach) at minute 1 and at the end.

Usage: bench/crowd_scaling.py [--seconds 15] [--points 10@12 20@12 ...] [--peer-workspace DIR]
       [--memory-minutes 5] [--memory-count 40] [--markdown F] [--csv F] [--chart F] [--screenshots DIR]
Exits 1 if a point did not draw all its humans or the memory run did not show all of them.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy

import rviz_scaling as rs
from ros_processes import report, ros_environment, start, stop

sys.path.insert(0, os.path.join(rs.ROOT, "test", "ros"))
from on_screen import OrbitView  # noqa: E402

OURS = ("DressedHuman from one crowd message", "dressed_human/DressedHuman",
        ["--set", "Robot Description=robot_description", "--set", "Humans=From Topic", "--set", "Topic=/crowd"])
PEER = rs.PEER
PUBLISH_HZ = 30.0
ROW_SPACING = 3.5  # m: the boxes of one row and the next do not overlap on screen, even from 30 m at 0.7 rad
DEFAULT_POINTS = ["10@12", "20@12", "30@12", "40@12", "10@30", "20@30", "40@30", "100@30"]


def parse_points(texts):
    points = []
    for text in texts:
        count, distance = text.split("@")
        points.append((int(count), float(distance)))
    return points


def positions(count):
    """(x, y) of each human: rows of rs.row_length(count), 1 m apart, ROW_SPACING apart, centred on the view."""
    return [(x * ROW_SPACING / rs.ROW_SPACING, y) for x, y in rs.positions(count)]


def front_row_x(count):
    """The x of the row nearest the camera (the orbit's eye is on the +x side): the view's focal
    point is that row's middle, `distance` away, and every other row stands farther off."""
    return max(x for x, _ in positions(count))


def view(count, distance):
    """The orbit view of `count` humans from `distance`: focal point the front row's middle."""
    return OrbitView(distance, rs.YAW, rs.pitch(count), (front_row_x(count), 0.0, rs.FOCAL_Z))


def crowd_file(places, directory):
    path = os.path.join(directory, "treadmill_crowd_%d.yaml" % len(places))
    with open(path, "w") as f:
        f.write("humans:\n")
        for i, (x, y) in enumerate(places):
            f.write('  "%d": {route: [[%g, %g], [%g, %g]], treadmill: true, speed: 1.2, start_phase: %g}\n'
                    % (i, x, y, x + 1.0, y, (0.37 * i) % 1.0))
    return path


def cpu_seconds(pid):
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def measure(subject, count, distance, args, shots, env, env_script=None):
    label, display_class, extra = subject
    name = re.sub(r"[^a-z]+", "_", label.lower()).strip("_")
    screenshot = os.path.join(shots, "%s_%d_%gm.png" % (name, count, distance))
    # One display draws them all: the view is the one for `count` humans, not for one.
    front = front_row_x(count)
    view_arguments = ["--view", "Pitch=%g" % rs.pitch(count), "--focal", "%g;0;%g" % (front, rs.FOCAL_Z)]
    point = rs.harness(display_class, 1, args.seconds, extra + view_arguments, screenshot, env, distance, 0.0,
                       env_script)
    orbit = view(count, distance)
    places = positions(count)
    point["drawn"] = min(rs.drawn(screenshot[:-4] + "_start.png", places, orbit), rs.drawn(screenshot, places, orbit))
    point["screenshot"] = os.path.relpath(screenshot, rs.ROOT)
    print(label, count, distance, point, file=sys.stderr)
    return point


def measure_ours(count, distances, args, shots, directory, env):
    """One run per distance, after one grid run, while crowd_publisher runs."""
    places = positions(count)
    publisher = start([os.path.join(rs.DEVEL, "lib", "dressed_human", "crowd_publisher"),
                       "_crowd_file:=" + crowd_file(places, directory), "_rate:=%g" % PUBLISH_HZ], env)
    try:
        time.sleep(3)
        if publisher.poll() is not None:
            raise RuntimeError("crowd_publisher exited (status %s)" % publisher.returncode)
        runs = {}
        publisher_cpu = []
        grid = rs.harness("rviz/Grid", 0, args.seconds, [], os.path.join(shots, "grid_ours_%d.png" % count), env)
        for distance in distances:
            cpu_start, wall_start = cpu_seconds(publisher.pid), time.time()
            point = measure(OURS, count, distance, args, shots, env)
            publisher_cpu.append(100.0 * (cpu_seconds(publisher.pid) - cpu_start) / (time.time() - wall_start))
            point["grid_ms"] = grid["cpu_ms_per_frame"]
            runs[distance] = point
    finally:
        stop(publisher)
    return runs, max(publisher_cpu)


def measure_peer(count, distances, args, shots, env):
    """One run per distance, after one grid run, while the peer's publisher runs."""
    setup = os.path.join(args.peer_workspace, "devel")
    places = ["%g,%g" % place for place in positions(count)]
    publisher = start(["/bin/bash", "-c", ". %s/setup.bash && exec /usr/bin/python3 %s %g %s" % (
        setup, os.path.join(rs.ROOT, "bench", "peer_rows.py"), PUBLISH_HZ, " ".join(places))], env)
    env_script = os.path.join(setup, "env.sh")
    try:
        time.sleep(4)
        runs = {}
        grid = rs.harness("rviz/Grid", 0, args.seconds, [], os.path.join(shots, "grid_peer_%d.png" % count), env,
                          env_script=env_script)
        for distance in distances:
            point = measure(PEER, count, distance, args, shots, env, env_script)
            point["grid_ms"] = grid["cpu_ms_per_frame"]
            runs[distance] = point
    finally:
        stop(publisher)
    return runs


def summary(points, count, grid_ms, publisher_cpu):
    """The repetitions of one point: medians, the per-human cost against `grid_ms` and its range,
    the fewest drawn."""
    for point in points:
        point["per_human_ms"] = (point["cpu_ms_per_frame"] - grid_ms) / count
    median = lambda key: float(numpy.median([p[key] for p in points]))  # noqa: E731
    result = {key: median(key) for key in ("fps", "cpu_percent", "cpu_ms_per_frame", "per_human_ms")}
    result["grid_ms"] = grid_ms
    result["grid_range"] = (min(p["grid_ms"] for p in points), max(p["grid_ms"] for p in points))
    result["per_human_range"] = (min(p["per_human_ms"] for p in points), max(p["per_human_ms"] for p in points))
    result["fps_range"] = (min(p["fps"] for p in points), max(p["fps"] for p in points))
    result["drawn"] = min(p["drawn"] for p in points)
    result["screenshot"] = points[-1]["screenshot"]
    result["publisher_cpu"] = publisher_cpu
    result["repeats"] = len(points)
    return result


def rviz_pid(marker):
    """The rviz process whose command line names `marker` (its config), or None."""
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/cmdline" % entry, "rb") as f:
                command = f.read().decode(errors="replace").split("\0")
        except OSError:
            continue
        if command and os.path.basename(command[0]) == "rviz" and any(marker in part for part in command):
            return int(entry)
    return None


def resident_mb(pid):
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return -1.0


def measure_memory(count, minutes, shots, env):
    """rviz's resident memory over `minutes` of the shipped crowd launch, and the humans shown."""
    import rospy
    import tf2_ros
    from on_screen import Launch, LoopingTfListener, observe
    display = ":%d" % (90 + os.getpid() % 100)
    xvfb = subprocess.Popen(["Xvfb", display, "-screen", "0", "1280x1024x24"], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    os.environ.update(env)
    os.environ["DISPLAY"] = display
    directory = os.path.join(shots, "memory_%d" % count)
    os.makedirs(directory, exist_ok=True)
    samples = []
    verdicts = []
    launch = Launch("crowd.launch", ["count:=%d" % count], os.path.join(directory, "launch.log"))
    try:
        rospy.init_node("crowd_scaling", anonymous=True, disable_signals=True)
        buffer = tf2_ros.Buffer(rospy.Duration(10.0))
        listener = LoopingTfListener(buffer)  # noqa: F841 (fills the buffer)
        view = OrbitView.from_config(os.path.join(rs.ROOT, "rviz", "crowd.rviz"))
        humans = {"body_%d" % i: ["body_%d" % i] for i in range(count)}
        pid = None
        deadline = time.time() + 120
        while pid is None and time.time() < deadline:
            time.sleep(1.0)
            pid = rviz_pid("crowd.rviz")
        if pid is None:
            raise RuntimeError("rviz did not start:\n" + launch.output()[-2000:])
        start_time = time.time()
        judged_at = [60.0, minutes * 60.0]
        while True:
            elapsed = time.time() - start_time
            samples.append((elapsed, resident_mb(pid)))
            if judged_at and elapsed >= judged_at[0]:
                # Root frames only (skeleton_tf off, as users run it): each box grown by the whole
                # body's reach about the pelvis.
                result = observe(launch, buffer, view, humans, os.path.join(directory, "minute_%d" % round(elapsed / 60)),
                                 0.0, 1.0, 1.0)[0]
                verdicts.append((elapsed, result))
                judged_at.pop(0)
            if elapsed >= minutes * 60.0:
                break
            time.sleep(10.0)
    finally:
        launch.stop()
        xvfb.terminate()
    return samples, verdicts


def chart(results, points, memory, memory_count, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(1, 3, figsize=(18, 4.8))
    distances = sorted(set(d for _, d in points))
    for label, _, _ in (OURS, PEER):
        for distance in distances:
            counts = [n for n, d in points if d == distance and (label, n, d) in results]
            if not counts:
                continue
            style = "o-" if distance == distances[0] else "s--"
            axes[0].plot(counts, [results[(label, n, distance)]["fps"] for n in counts], style,
                         label="%s, %g m" % (label, distance))
            medians = [results[(label, n, distance)]["per_human_ms"] for n in counts]
            ranges = numpy.array([[m - results[(label, n, distance)]["per_human_range"][0],
                                   results[(label, n, distance)]["per_human_range"][1] - m]
                                  for m, n in zip(medians, counts)]).T
            axes[1].errorbar(counts, medians, yerr=ranges, fmt=style, capsize=3, label="%s, %g m" % (label, distance))
    axes[0].axhline(30.0, color="grey", lw=0.8, ls="--")
    axes[0].set_ylabel("frames per second (rviz caps at 30)")
    axes[1].set_ylabel("rviz CPU per human per frame (ms)\n(rviz CPU per frame - grid with the publisher) / N")
    for ax in axes[:2]:
        ax.set_xlabel("walking humans in view")
        ax.set_ylim(bottom=0)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    if memory:
        samples, _ = memory
        axes[2].plot([t / 60.0 for t, _ in samples], [m for _, m in samples], "o-", ms=3)
        axes[2].set_xlabel("minutes since rviz started (crowd.launch count:=%d)" % memory_count)
        axes[2].set_ylabel("rviz resident memory (MB)")
        axes[2].grid(True, alpha=0.3)
    figure.suptitle("A crowd from one publisher, rviz on Mesa llvmpipe, %d cores (bench/crowd_scaling.py)"
                    % os.cpu_count())
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    plt.close(figure)


def memory_growth(samples, from_s, to_s):
    """Resident memory at `to_s` less at `from_s` (the samples nearest each)."""
    nearest = lambda t: min(samples, key=lambda s: abs(s[0] - t))[1]  # noqa: E731
    return nearest(to_s) - nearest(from_s)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seconds", type=float, default=15.0)
    parser.add_argument("--repeats", type=int, default=2, help="runs per point, each after a grid run")
    parser.add_argument("--points", nargs="+", default=DEFAULT_POINTS, help="COUNT@DISTANCE ...")
    parser.add_argument("--peer-workspace", default="")
    parser.add_argument("--memory-minutes", type=float, default=5.0, help="0: no memory run")
    parser.add_argument("--memory-count", type=int, default=40)
    parser.add_argument("--markdown", default="")
    parser.add_argument("--csv", default="")
    parser.add_argument("--chart", default="")
    parser.add_argument("--screenshots", default="")
    args = parser.parse_args()
    points = parse_points(args.points)
    shots = args.screenshots or tempfile.mkdtemp()
    os.makedirs(shots, exist_ok=True)
    directory = tempfile.mkdtemp()
    env = ros_environment(11917)
    processes = [start(["roscore", "-p", "11917"], env)]
    results = {}
    memory = None
    try:
        time.sleep(4)
        import rosgraph  # after ROS_MASTER_URI is known to this process
        master = rosgraph.Master("/crowd_scaling", master_uri=env["ROS_MASTER_URI"])
        with open(os.path.join(rs.ROOT, "urdf", "human.urdf")) as f:
            master.setParam("/robot_description", f.read())
        for count in sorted(set(n for n, _ in points)):
            distances = [d for n, d in points if n == count]
            # The subjects take turns, one run of each per repeat: a drift of the machine over the
            # minutes a crowd size takes then falls on both alike, not on whichever went last.
            ours = {d: [] for d in distances}
            peer = {d: [] for d in distances} if args.peer_workspace else {}
            publisher_cpu = 0.0
            for _ in range(args.repeats):
                runs, cpu = measure_ours(count, distances, args, shots, directory, env)
                publisher_cpu = max(publisher_cpu, cpu)
                for distance, point in runs.items():
                    ours[distance].append(point)
                if args.peer_workspace:
                    for distance, point in measure_peer(count, distances, args, shots, env).items():
                        peer[distance].append(point)
            # One baseline for both subjects: rviz drawing its grid measured alike with either
            # publisher running (10.5-11.3 ms against 11.0-11.4 ms, 4 runs each, 10 humans), while
            # single grid runs of one evaluation differed by 4 ms: subtracting each subject's own
            # grid run moved its per-human cost by up to 0.4 ms at 10 humans.
            grids = [run["grid_ms"] for subject in (ours, peer) for runs in subject.values() for run in runs]
            grid_ms = float(numpy.median(grids))
            for distance, runs in ours.items():
                results[(OURS[0], count, distance)] = summary(runs, count, grid_ms, publisher_cpu)
            for distance, runs in peer.items():
                results[(PEER[0], count, distance)] = summary(runs, count, grid_ms, -1.0)
                # Runs taken in turns pair up: their difference is free of the drift between pairs.
                results[(OURS[0], count, distance)]["paired_ms"] = [
                    (a["cpu_ms_per_frame"] - b["cpu_ms_per_frame"]) / count for a, b in zip(ours[distance], runs)]
        if args.memory_minutes > 0:
            memory = measure_memory(args.memory_count, args.memory_minutes, shots, env)
    finally:
        for process in reversed(processes):
            stop(process)

    failed = ["%s x %d at %g m" % key for key, p in results.items() if p["drawn"] < key[1]]
    lines = ["| humans | distance | display | drawn | fps | rviz CPU | rviz CPU per frame (grid: median of both "
             "subjects' runs; this subject's) | rviz CPU per human per frame (range) | crowd_publisher CPU (most) |",
             "|---|---|---|---|---|---|---|---|---|"]
    rows = ["display,humans,distance_m,drawn,fps,cpu_percent,cpu_ms_per_frame,grid_ms,per_human_ms,publisher_cpu,"
            "screenshot"]
    for count, distance in points:
        for label in (OURS[0], PEER[0]):
            p = results.get((label, count, distance))
            if p is None:
                continue
            drawn_text = "%d/%d" % (p["drawn"], count) + ("" if p["drawn"] == count else " **FAILED**")
            publisher = "%.1f %%" % p["publisher_cpu"] if p["publisher_cpu"] >= 0 else "—"
            fps_text = "%.1f" % p["fps"] + ("" if p["fps_range"][1] - p["fps_range"][0] < 0.5 else " (%.1f–%.1f)" % p["fps_range"])
            lines.append("| %d | %g m | %s | %s | %s | %.0f %% | %.1f ms (%.1f ms; %.1f–%.1f) | %.2f ms (%.2f–%.2f) | %s |" % (
                count, distance, label, drawn_text, fps_text, p["cpu_percent"], p["cpu_ms_per_frame"], p["grid_ms"],
                p["grid_range"][0], p["grid_range"][1], p["per_human_ms"], p["per_human_range"][0], p["per_human_range"][1], publisher))
            rows.append("%s,%d,%g,%d,%.2f,%.1f,%.3f,%.3f,%.3f,%.1f,%s" % (
                label, count, distance, p["drawn"], p["fps"], p["cpu_percent"], p["cpu_ms_per_frame"], p["grid_ms"],
                p["per_human_ms"], p["publisher_cpu"], p["screenshot"]))
    paired = ["%d at %g m: %s" % (count, distance, ", ".join("%+.2f" % d for d in results[(OURS[0], count, distance)]["paired_ms"]))
              for count, distance in points if "paired_ms" in results.get((OURS[0], count, distance), {})]
    if paired:
        lines.append("")
        lines.append("Ours less the peer, rviz CPU per human per frame, pair by pair (ms; a run of each, taken in turns; "
                     "below zero: ours cost less): " + "; ".join(paired) + ".")
    lines.append("")
    lines.append("Medians of %d runs per point, the subjects taking turns (a run of ours, then one of the peer's); rviz CPU per human per frame = (rviz CPU per frame - the grid's) / N, "
                 "the grid's the median of every grid run at that N, ours and the peer's (each run measures rviz drawing "
                 "only its grid while that subject's publisher runs: the grid column shows that median and, in brackets, "
                 "the lowest and highest of the subject's own grid runs); the range: lowest and highest run. " % args.repeats +
                 "Humans on treadmills (1.2 m/s) in rows of %d (at most %d rows: longer rows beyond %d humans), 1 m apart, rows %g m apart, the distance from the camera to "
                 "the middle of the nearest row (the others farther off); one message for all at "
                 "%g Hz (ours: crowd_publisher's dressed_human/Crowd, with each root frame on /tf; the peer: "
                 "TrackedPersons from bench/peer_rows.py); %g s per point after 5 s of warm-up; rviz CPU in %% of one "
                 "core, Mesa llvmpipe on %d cores, rviz's default anti-aliasing; \"drawn\": figures in both the screenshot at the "
                 "start and at the end of the point (`%s/`). `bench/crowd_scaling.py`."
                 % (rs.ROW_LENGTH, rs.MAX_ROWS, rs.ROW_LENGTH * rs.MAX_ROWS, ROW_SPACING, PUBLISH_HZ, args.seconds, os.cpu_count(),
                    os.path.relpath(shots, rs.ROOT)))
    if memory:
        samples, verdicts = memory
        growth = memory_growth(samples, 60.0, args.memory_minutes * 60.0)
        shown = ["minute %.0f: %d of %d humans drawn in their boxes%s" % (
            t / 60.0, sum(1 for h in v["humans"].values() if h["state"] == "in" and h["ok"]),
            args.memory_count, "" if v["ok"] else " (**FAILED**: %s)" % {k: h for k, h in v["humans"].items()
                                                                         if not h["ok"]}) for t, v in verdicts]
        if any(not v["ok"] for _, v in verdicts):
            failed.append("the memory run's screenshots")
        lines.append("")
        lines.append("rviz's resident memory with `crowd.launch count:=%d` (its own rviz config, rviz's defaults): "
                     "%.0f MB at minute 1, %.0f MB at minute %g: **%+.0f MB** from minute 1 to minute %g (%s)."
                     % (args.memory_count, min(samples, key=lambda s: abs(s[0] - 60))[1], samples[-1][1],
                        args.memory_minutes, growth, args.memory_minutes, "; ".join(shown)))
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("\n".join(rows) + "\n")
    if args.chart:
        chart(results, points, memory, args.memory_count, args.chart)
    report("\n".join(lines), args.markdown)
    if failed:
        print("crowd_scaling.py: not every human drawn in %s" % ", ".join(failed), file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
