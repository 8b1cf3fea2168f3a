#!/usr/bin/python3
"""rviz with N walking humans in view: DressedHuman displays (vertices evaluated by the vertex
shader and by the CPU, the default's choice on a software renderer) against the same number of RobotModel displays of the same
URDF, in one run (bench/rviz_display_scaling.cpp does the rviz side).

Every human stays in view for the whole measurement: each is its own skeleton_publisher
(namespace human_<i>, frames suffixed _<i>) walking in place (a copy of walk.yaml with
forward_speed 0). Up to 10 humans stand in one row 1 m apart, the camera 12 m (--distances) in
front of the row's middle, pitched down 0.25 rad; more stand in rows of 10, each row 3 m behind
the previous and shifted 0.5 m sideways, seen from 0.7 rad above so that the rows do not hide
one another. Each point saves a screenshot when its measurement starts and one when it ends, and
fails unless every one of its N humans is drawn in both (drawn_places: figure pixels nearest
its place, inside the box its position projects to). Reports fps (rviz's cap is 30), rviz CPU, and rviz CPU per human per
frame: (rviz CPU per frame - the empty scene's) / N; also what the DressedHuman display measures
of its own update(). With several --distances, the --distance-count humans are also measured at
each distance (cost against distance).

Each point is measured --repeats times (default 3), every repeat against its own empty-scene
run; the tables give the median and the range (lowest, highest run).

Usage: bench/rviz_scaling.py [--repeats 3] [--seconds 15] [--counts 1 5 10] [--distances 12]
       [--distance-count 10] [--markdown docs/rviz_scaling.md] [--csv out.csv]
       [--chart docs/rviz_scaling.png] [--screenshots docs/rviz_scaling] [--peer-workspace DIR]
With --peer-workspace (built by ../shared/peers/spencer/build.sh), spencer's walking-man meshes (the
crowd peer) are measured in the same run, from the peer's own publisher, up to 10 persons.
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
from on_screen import OrbitView, figure_mask, pixel_owners  # noqa: E402

DEVEL = os.path.join(ROOT, "build", "devel")
# (label, display class, extra harness arguments)
SUBJECTS = [("DressedHuman (GPU vertices)", "dressed_human/DressedHuman", ["--set", "Vertex Evaluation=GPU"]),
            ("DressedHuman (CPU vertices)", "dressed_human/DressedHuman", ["--set", "Vertex Evaluation=CPU"]),
            ("RobotModel", "rviz/RobotModel", [])]
# The crowd peer (../shared/peers/spencer: its build.sh makes the workspace given as --peer-workspace).
PEER = ("spencer walking-man mesh (peer)", "spencer_tracking_rviz_plugin/TrackedPersons",
        ["--set", "Topic=/tracked_persons", "--set", "Style=Person meshes", "--set", "Tracking frame=world"])
PEER_DIR = os.path.join(os.path.dirname(ROOT), "shared", "peers", "spencer")
YAW, FOCAL_Z = 0.0, 0.9
ROW_LENGTH, ROW_SPACING, ROW_SHIFT, MAX_ROWS = 10, 3.0, 0.5, 4
# Of a 1 m x 0.6 m x 1.95 m box a figure covers a quarter (ours) or a tenth (the peer's), less of
# it coloured enough for the figure mask in dark clothes (a black jacket at 30 m: 4.3 %); a box
# whose human is missing holds none.
MIN_BOX_SHARE = 0.03


def row_length(count):
    """Humans per row: ROW_LENGTH, or more for crowds of over MAX_ROWS rows. Seen from 0.7 rad
    above, a fifth row and beyond stand so far off that each row's heads cover the next row's
    feet on screen (100 in rows of 10 from 30 m): a missing human there could not be told."""
    return max(ROW_LENGTH, -(-count // MAX_ROWS))


def positions(count):
    """(x, y) of each human: rows of row_length(count), 1 m apart, centred on the view."""
    length = row_length(count)
    rows = (count + length - 1) // length
    result = []
    for i in range(count):
        row, column = divmod(i, length)
        in_row = min(length, count - row * length)
        x = -ROW_SPACING * (row - (rows - 1) / 2.0)
        y = column - (in_row - 1) / 2.0 + (ROW_SHIFT if row % 2 else 0.0)
        result.append((x, y))
    return result


def pitch(count):
    return 0.25 if count <= ROW_LENGTH else 0.7


def view(count, distance, focal_y=0.0):
    # rviz_display_scaling's render panel; rviz's default vertical field of view.
    return OrbitView(distance, YAW, pitch(count), (0.0, focal_y, FOCAL_Z))


def peer_positions(count):
    """Where the peer's publisher puts its persons: x = 0, y = 0 .. count - 1 (one row, facing +x)."""
    return [(0.0, float(i)) for i in range(count)]


def drawn_places(path, places, orbit):
    """Which of the humans at `places` show in the screenshot at `path`. Each figure pixel counts
    for one place only: the one whose body axis (a vertical line from the floor to 1.8 m at the
    place) projects nearest to it, among the places whose box holds it (a box 1 m deep, 0.6 m
    across the row, 1.95 m tall); a place is drawn with its pixels over at least MIN_BOX_SHARE of
    its box's screen area. Off the view's axis, seen from above, neighbouring boxes overlap on
    screen (by up to a third of a box in the 30-human point at 12 m): counted by box alone, a
    neighbour's figure stood in for a missing human. tools.drawn_judgement checks empty and erased
    places on the committed screenshots."""
    image = numpy.asarray(Image.open(path).convert("RGB")).astype(numpy.float64)
    mask = figure_mask(image)
    height, width = mask.shape
    regions, axes, areas = [], [], []
    for x, y in places:
        corners = numpy.array([[cx, cy, cz] for cx in (x - 0.5, x + 0.5) for cy in (y - 0.3, y + 0.3)
                               for cz in (-0.05, 1.9)])
        columns, rows, depth, _ = orbit.project(corners, numpy.zeros(3), width, height)
        axis = numpy.array([[x, y, z] for z in numpy.linspace(0.0, 1.8, 19)])
        axis_columns, axis_rows, _, _ = orbit.project(axis, numpy.zeros(3), width, height)
        left, right = int(max(columns.min(), 0)), int(min(columns.max(), width))
        top, bottom = int(max(rows.min(), 0)), int(min(rows.max(), height))
        if (depth <= orbit.near).any() or right <= left or bottom <= top:
            regions.append((slice(0, 0), slice(0, 0)))  # behind the camera or off screen: not drawn
        else:
            regions.append((slice(top, bottom), slice(left, right)))
        axes.append(numpy.stack([axis_columns, axis_rows], axis=1))
        areas.append((columns.max() - columns.min()) * (rows.max() - rows.min()))
    owners = pixel_owners(mask, regions, axes)
    owned = numpy.bincount(owners[owners >= 0], minlength=len(places))
    return [bool(owned[i] >= max(15.0, MIN_BOX_SHARE * areas[i])) for i in range(len(places))]


def drawn(path, places, orbit):
    """How many of the humans at `places` show in the screenshot at `path` (drawn_places)."""
    return sum(drawn_places(path, places, orbit))


def harness(display_class, count, seconds, extra, screenshot, env, distance=12.0, focal_y=0.0, env_script=None,
            target_frame=None):
    """`target_frame`: the orbit view circles that frame's origin (else the point (0, focal_y,
    FOCAL_Z) of the fixed frame)."""
    # stdbuf: the peer's plugin aborts in a destructor as the harness exits, after its figures.
    command = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", env_script or os.path.join(DEVEL, "env.sh"),
               "stdbuf", "-oL", os.path.join(DEVEL, "lib", "dressed_human", "rviz_display_scaling"), display_class,
               str(count), str(seconds), "--distance", str(distance),
               "--focal", "0;0;0" if target_frame else "0;%g;%g" % (focal_y, FOCAL_Z), "--view", "Yaw=%g" % YAW,
               "--view", "Pitch=%g" % pitch(count), "--view", "Target Frame=" + (target_frame or "<Fixed Frame>"), "--screenshot",
               screenshot] + extra
    output = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, timeout=seconds + 180).stdout
    match = re.search(r"fps=([\d.]+) cpu_percent=([\d.]+) cpu_ms_per_frame=([\d.]+) display_ms=([-\d.]+)", output)
    if not match:
        raise RuntimeError("harness failed for %s x %d:\n%s" % (display_class, count, output[-2000:]))
    point = dict(zip(("fps", "cpu_percent", "cpu_ms_per_frame", "display_ms"), (float(v) for v in match.groups())))
    extra = re.search(r"rss_mb=([-\d.]+) first_frame_s=([-\d.]+)", output)
    point["rss_mb"], point["first_frame_s"] = (float(v) for v in extra.groups()) if extra else (-1.0, -1.0)
    vertex_status = re.search(r"^vertex_evaluation (.*)$", output, re.MULTILINE)
    point["vertex_evaluation"] = vertex_status.group(1) if vertex_status else ""
    for line in output.splitlines():
        if line.startswith("status ") or line.startswith("surfaces "):
            print("  %s x %d: %s" % (display_class, count, line), file=sys.stderr)
    return point


def chart(results, counts, distances, distance_count, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = 3 if len(distances) > 1 else 2
    figure, axes = plt.subplots(1, panels, figsize=(6 * panels, 4.5))
    near = distances[0]
    for label, _, _ in SUBJECTS + [PEER]:
        shown = [n for n in counts if (label, n, near) in results]
        if not shown:
            continue
        points = [results[(label, n, near)] for n in shown]
        axes[0].plot(shown, [p["fps"] for p in points], "o-", label=label)
        medians = [p["per_human_ms"] for p in points]
        spread = [[m - p["per_human_range"][0] for m, p in zip(medians, points)],
                  [p["per_human_range"][1] - m for m, p in zip(medians, points)]]
        axes[1].errorbar(shown, medians, yerr=spread, fmt="o-", capsize=3, label=label)
        if panels == 3 and all((label, distance_count, d) in results for d in distances):
            axes[2].plot(distances, [results[(label, distance_count, d)]["per_human_ms"] for d in distances], "o-",
                         label=label)
    axes[0].axhline(30.0, color="grey", lw=0.8, ls="--")
    axes[0].set_ylabel("frames per second (rviz caps at 30)")
    axes[1].set_ylabel("rviz CPU per human per frame (ms)\n(rviz CPU per frame - empty scene) / N")
    for ax in axes[:2]:
        ax.set_xlabel("humans in view (camera at %g m)" % near)
        ax.set_xticks(counts)
    if panels == 3:
        axes[2].set_ylabel("rviz CPU per human per frame (ms)")
        axes[2].set_xlabel("camera distance (m), %d humans" % distance_count)
        axes[2].set_xticks(distances)
    for ax in axes:
        ax.grid(True, alpha=0.3)
        ax.set_ylim(bottom=0)
        ax.legend(fontsize=8)
    figure.suptitle("Walking humans in view, rviz on Mesa llvmpipe, %d cores (bench/rviz_scaling.py)" % os.cpu_count())
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    plt.close(figure)


def walk_in_place_motion(directory):
    """A copy of config/motions/walk.yaml with forward_speed 0, in `directory`; returns its path."""
    with open(os.path.join(ROOT, "config", "motions", "walk.yaml")) as f:
        in_place, replaced = re.subn(r"(\n\s*forward_speed:\s*)[-+0-9.eE]+", r"\g<1>0.0", f.read())
    if replaced != 1:
        raise RuntimeError("config/motions/walk.yaml: expected one root forward_speed to set to 0")
    motion = os.path.join(directory, "walk_in_place.yaml")
    with open(motion, "w") as f:
        f.write(in_place)
    return motion


def start_humans(count, node, motion, urdf, master, env):
    """One skeleton_publisher per human at positions(count); returns the processes."""
    nodes = []
    for i, (x, y) in enumerate(positions(count)):
        text = subprocess.run([os.path.join(ROOT, "scripts", "suffix_urdf.py"), urdf, str(i)], check=True,
                              stdout=subprocess.PIPE, universal_newlines=True).stdout
        master.setParam("/human_%d/robot_description" % i, text)
        nodes.append(start([node, "__ns:=/human_%d" % i, "_motion_file:=" + motion, "_origin_x:=%g" % x,
                            "_origin_y:=%g" % y, "_publish_joint_states:=false"], env))
    time.sleep(2 + 0.1 * count)
    return nodes


def measure_peer(count, distance, args, screenshot, env):
    """spencer's TrackedPersons display (Person meshes) with `count` persons from the peer's own
    publisher, seen as the humans are: the same view of a row of the same length."""
    peer_env = dict(env)
    setup = os.path.join(args.peer_workspace, "devel")
    publisher = start(["/bin/bash", "-c", ". %s/setup.bash && exec /usr/bin/python3 %s %d" % (
        setup, os.path.join(PEER_DIR, "publish_persons.py"), count)], peer_env)
    try:
        time.sleep(3)
        focal_y = (count - 1) / 2.0
        point = harness(PEER[1], 1, args.seconds, PEER[2], screenshot, peer_env, distance, focal_y,
                        os.path.join(setup, "env.sh"))
        orbit = view(count, distance, focal_y)
        point["drawn"] = min(drawn(screenshot[:-4] + "_start.png", peer_positions(count), orbit),
                             drawn(screenshot, peer_positions(count), orbit))
        return point
    finally:
        stop(publisher)


def subjects(args, count):
    """What is measured at `count` humans: ours and RobotModel; the peer too where its publisher's
    one row fits the view (up to ROW_LENGTH), if its workspace was given."""
    peer = [PEER] if args.peer_workspace and count <= ROW_LENGTH else []
    return SUBJECTS + peer


def measure(results, count, distance, args, baseline, shots, env):
    for label, display_class, extra in subjects(args, count):
        name = re.sub(r"[^a-z]+", "_", label.lower()).strip("_")
        screenshot = os.path.join(shots, "%s_%d_%gm.png" % (name, count, distance))
        if (label, display_class, extra) == PEER:
            point = measure_peer(count, distance, args, screenshot, env)
        else:
            point = harness(display_class, count, args.seconds, extra, screenshot, env, distance)
            start_shot = screenshot[:-4] + "_start.png"
            orbit = view(count, distance)
            point["drawn"] = min(drawn(start_shot, positions(count), orbit), drawn(screenshot, positions(count), orbit))
        point["per_human_ms"] = (point["cpu_ms_per_frame"] - baseline["cpu_ms_per_frame"]) / count
        point["screenshot"] = os.path.relpath(screenshot, ROOT)
        results[(label, count, distance)] = point
        print(label, count, distance, point, file=sys.stderr)


def automatic_vertex_choice(env, shots):
    """What "Vertex Evaluation: Automatic", the default, picks here: its status names the CPU
    when it chose the CPU ("CPU (Automatic): ..."); without one it chose the vertex shader."""
    point = harness("dressed_human/DressedHuman", 1, 2, [], os.path.join(shots, "automatic_choice.png"), env)
    return ("CPU" if "(Automatic)" in point["vertex_evaluation"] else "GPU"), point["vertex_evaluation"]


def over_runs(runs):
    """One point per key from the same key's point in every run: medians, the lowest and highest
    fps and per-human cost, and the fewest humans drawn (a human missing in any run fails it)."""
    combined = {}
    for key in runs[0]:
        points = [run[key] for run in runs]
        point = dict(points[-1])  # its screenshot: the last run's
        for field in ("fps", "cpu_percent", "cpu_ms_per_frame", "per_human_ms", "display_ms", "rss_mb", "first_frame_s"):
            if field in point:
                point[field] = float(numpy.median([p[field] for p in points]))
        if "per_human_ms" in point:
            point["per_human_range"] = (min(p["per_human_ms"] for p in points), max(p["per_human_ms"] for p in points))
        point["fps_range"] = (min(p["fps"] for p in points), max(p["fps"] for p in points))
        if "drawn" in point:
            point["drawn"] = min(p["drawn"] for p in points)
        combined[key] = point
    return combined


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seconds", type=float, default=15.0)
    parser.add_argument("--repeats", type=int, default=3, help="runs per point, each against its own empty scene")
    parser.add_argument("--counts", type=int, nargs="+", default=[1, 5, 10])
    parser.add_argument("--distances", type=float, nargs="+", default=[12.0])
    parser.add_argument("--distance-count", type=int, default=10)
    parser.add_argument("--markdown", default="")
    parser.add_argument("--csv", default="")
    parser.add_argument("--chart", default="")
    parser.add_argument("--screenshots", default="")
    parser.add_argument("--peer-workspace", default="",
                        help="a catkin workspace built by ../shared/peers/spencer/build.sh: spencer's walking-man "
                             "meshes measured alongside (up to %d persons)" % ROW_LENGTH)
    args = parser.parse_args()
    shots = args.screenshots or tempfile.mkdtemp()
    os.makedirs(shots, exist_ok=True)

    env = ros_environment(11911)
    node = os.path.join(DEVEL, "lib", "dressed_human", "skeleton_publisher")
    motion = walk_in_place_motion(tempfile.mkdtemp())
    urdf = os.path.join(ROOT, "urdf", "human.urdf")
    near = args.distances[0]
    points = [(n, near) for n in args.counts]
    if len(args.distances) > 1:
        points += [(args.distance_count, d) for d in args.distances[1:]]
    processes = [start(["roscore", "-p", "11911"], env)]
    runs = []
    automatic = None
    try:
        time.sleep(4)
        import rosgraph  # after ROS_MASTER_URI is known to this process
        master = rosgraph.Master("/rviz_scaling", master_uri=env["ROS_MASTER_URI"])
        for _ in range(args.repeats):
            run = {}
            baseline = harness("rviz/Grid", 0, args.seconds, [], os.path.join(shots, "empty.png"), env)
            for count in sorted(set(n for n, _ in points)):
                # Restarted per count, so that display i always finds human i at its place.
                nodes = start_humans(count, node, motion, urdf, master, env)
                try:
                    if automatic is None:
                        automatic = automatic_vertex_choice(env, shots)
                    for distance in [d for n, d in points if n == count]:
                        measure(run, count, distance, args, baseline, shots, env)
                finally:
                    for process in nodes:
                        stop(process)
            runs.append((baseline, run))
    finally:
        for process in reversed(processes):
            stop(process)
    results = over_runs([run for _, run in runs])
    baseline = over_runs([{"empty": b} for b, _ in runs])["empty"]

    failed = [(label, n, d) for (label, n, d), p in results.items() if p["drawn"] < n]
    lines = ["| humans | distance | display | drawn | fps | rviz CPU | rviz CPU per human per frame (range) | display's own "
             "update per human per frame | rviz resident memory | all drawn after |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    rows = ["display,humans,distance_m,drawn,fps,fps_low,fps_high,cpu_percent,cpu_ms_per_frame,per_human_ms,"
            "per_human_low,per_human_high,display_ms,rss_mb,first_frame_s,repeats,automatic_choice,screenshot"]
    for count, distance in points:
        for label, _, _ in subjects(args, count):
            p = results[(label, count, distance)]
            own = "%.3f ms" % p["display_ms"] if p["display_ms"] >= 0 else "—"
            drawn_text = "%d/%d" % (p["drawn"], count) + ("" if p["drawn"] == count else " **FAILED**")
            first = "%.2f s" % p["first_frame_s"] if p["first_frame_s"] >= 0 else "—"
            fps_text = "%.1f" % p["fps"] + ("" if p["fps_range"][1] - p["fps_range"][0] < 0.5
                                            else " (%.1f–%.1f)" % p["fps_range"])
            lines.append("| %d | %g m | %s | %s | %s | %.0f %% | %.2f ms (%.2f–%.2f) | %s | %.0f MB | %s |" % (
                count, distance, label, drawn_text, fps_text, p["cpu_percent"], p["per_human_ms"],
                p["per_human_range"][0], p["per_human_range"][1], own, p["rss_mb"], first))
            rows.append("%s,%d,%g,%d,%.2f,%.2f,%.2f,%.1f,%.3f,%.3f,%.3f,%.3f,%.3f,%.1f,%.2f,%d,%s,%s" % (
                label, count, distance, p["drawn"], p["fps"], p["fps_range"][0], p["fps_range"][1], p["cpu_percent"],
                p["cpu_ms_per_frame"], p["per_human_ms"], p["per_human_range"][0], p["per_human_range"][1],
                p["display_ms"], p["rss_mb"], p["first_frame_s"], args.repeats, automatic[0], p["screenshot"]))
    lines.append("")
    lines.append("Medians of %d runs per point, each against its own empty-scene run (the range: lowest and highest "
                 "run). " % args.repeats +
                 "Empty scene: %.1f fps, %.0f %% CPU, %.2f ms per frame. Humans walking in place, up to %d in a row 1 m "
                 "apart (camera pitched 0.25 rad), more in rows %g m apart (camera pitched 0.7 rad); %g s per point "
                 "after 5 s of warm-up; rviz CPU in %% of one core, Mesa llvmpipe (software rendering) on %d cores; "
                 "\"drawn\": humans visible in both the screenshot at the start and at the end of the point (`%s/`); "
                 "resident memory of the rviz process at the end of the point; \"all drawn after\": seconds from the "
                 "rviz process's start until every DressedHuman display had drawn its human (RobotModel does not say); "
                 "`bench/rviz_scaling.py`."
                 % (baseline["fps"], baseline["cpu_percent"], baseline["cpu_ms_per_frame"], ROW_LENGTH, ROW_SPACING,
                    args.seconds, os.cpu_count(), os.path.relpath(shots, ROOT)))
    lines.append("")
    lines.append("`Vertex Evaluation: Automatic`, the default, chose the %s here (%s)." % (
        automatic[0], automatic[1] or "no status: the vertex shader"))
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("\n".join(rows) + "\n")
    if args.chart:
        chart(results, args.counts, args.distances, args.distance_count, args.chart)
    report("\n".join(lines), args.markdown)
    if failed:
        print("rviz_scaling.py: not every human drawn in %s" % ", ".join("%s x %d at %g m" % f for f in failed),
              file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
