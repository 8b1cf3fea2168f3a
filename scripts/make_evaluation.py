#!/usr/bin/python3
"""docs/EVALUATION.md, its charts and the README's Speed section, from one run of
scripts/evaluate.sh (issues 8, 37).

Usage: scripts/make_evaluation.py RUN_DIR   (scripts/evaluate.sh passes build/evaluation/<run>)

RUN_DIR is one run's own folder: run.txt (command, commit, start, host and the line "finished:"
the run writes only when every step passed), bench_*.json (Google Benchmark, repetitions with
aggregates), scene_budget.csv, relief_modes.csv, rviz_scaling.csv, crowd_scaling.csv, and docs/,
everything the run wrote for docs/ (tables, CSVs, charts, screenshots). Only docs/stability.md, a
hand-written explanation, is read from the source tree. This script adds scene_budget.png,
relief_modes.png, skin_map_speed.png and EVALUATION.md to RUN_DIR/docs, then, and only if every
input was there, copies RUN_DIR/docs over docs/ (the screenshot folders replaced whole) and writes
the README's Speed section between its markers. A run that did not finish, an input missing
from the folder, or a commit the source tree does not contain is an error: nothing is written.
"""
import csv
import json
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import shutil
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOURCE_DOCS = os.path.join(ROOT, "docs")
DOCS = None  # the run's docs/ folder, set by main(): every measured input is read from it
# Folders a run writes whole (screenshots): published by replacing docs/' copy, so that no
# screenshot of an older run stays beside this run's.
RUN_FOLDERS = ("rviz_scaling", "crowd_scaling", "relief_modes", "relief_switch")


def need(path):
    if not os.path.exists(path):
        sys.exit("make_evaluation.py: missing input %s (run scripts/evaluate.sh)" % path)
    return path


def run_record(results):
    """run.txt as a dict; refuses a run that did not finish or whose commit is not in this tree."""
    record = {}
    for line in read_text(os.path.join(results, "run.txt")).splitlines():
        key, _, value = line.partition(": ")
        record[key] = value
    for key in ("command", "commit", "started", "host"):
        if key not in record:
            sys.exit("make_evaluation.py: %s/run.txt has no '%s:' line: not a run of scripts/evaluate.sh"
                     % (results, key))
    if "finished" not in record:
        sys.exit("make_evaluation.py: the run in %s did not finish (no 'finished:' line in run.txt: a step failed "
                 "or it was stopped); its figures are partial and are not published" % results)
    known = subprocess.run(["git", "-C", ROOT, "merge-base", "--is-ancestor", record["commit"], "HEAD"])
    if known.returncode != 0:
        sys.exit("make_evaluation.py: the run measured commit %s, which is not in this tree's history"
                 % record["commit"][:7])
    seconds = int(record["finished"].split(", ")[1].split()[0])
    record["duration"] = "%d min %02d s" % divmod(seconds, 60)
    record["machine"] = "%s, commit %s, started %s; the run took %s (`%s`)." % (
        record["host"], record["commit"][:7], record["started"].replace("T", " ").rstrip("Z") + " UTC",
        record["duration"], record["command"])
    return record


def publish(run_docs):
    """Copies the run's docs/ over the source tree's docs/."""
    for folder in RUN_FOLDERS:
        if os.path.isdir(os.path.join(run_docs, folder)):
            shutil.rmtree(os.path.join(SOURCE_DOCS, folder), ignore_errors=True)
    shutil.copytree(run_docs, SOURCE_DOCS, dirs_exist_ok=True)
    for folder, _, files in os.walk(SOURCE_DOCS):
        for name in files:
            if name.endswith((".md", ".csv")):
                path = os.path.join(folder, name)
                with open(path) as f:
                    text = f.read()
                if as_published(text) != text:
                    with open(path, "w") as f:
                        f.write(as_published(text))


def read_text(path):
    with open(need(path)) as f:
        return as_published(f.read().strip())


def as_published(text):
    """The run's own paths (benchmarks name their screenshot folders) as they read once published:
    build/evaluation/<run>/docs/... becomes docs/..."""
    if DOCS is None:
        return text
    return text.replace(os.path.relpath(DOCS, ROOT) + "/", "docs/")


def read_csv(path):
    with open(need(path)) as f:
        return list(csv.DictReader(f))


def benchmark_medians(path):
    """name -> (median real time, unit) from a Google Benchmark JSON with repetitions."""
    with open(need(path)) as f:
        data = json.load(f)
    medians = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name") == "median":
            medians[b["run_name"]] = (b["real_time"], b["time_unit"])
        elif b.get("run_type") == "iteration" and b["name"] not in medians and "repetitions" not in b.get("run_name", "x"):
            medians.setdefault(b["name"], (b["real_time"], b["time_unit"]))
    return medians


def benchmark_counter(path, name, counter):
    """A user counter of one benchmark (the first entry that has it)."""
    with open(need(path)) as f:
        for b in json.load(f)["benchmarks"]:
            if b.get("run_name", b["name"]) == name and counter in b:
                return b[counter]
    sys.exit("make_evaluation.py: %s has no counter %s on %s" % (path, counter, name))


def in_ms(value):
    time, unit = value
    return time * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[unit]


def in_us(value):
    return in_ms(value) * 1e3


def label_points(axes, xs, ys, labels, **style):
    axes.plot(xs, ys, "o", **style)
    for x, y, text in zip(xs, ys, labels):
        axes.annotate(text, (x, y), textcoords="offset points", xytext=(5, 4), fontsize=8)


# ------------------------------------------------------------------------------------ sections
def fourier_section():
    rows = read_csv(os.path.join(DOCS, "fourier_order_sweep_cmu_02_01.csv"))
    by_order = {int(r["order"]): r for r in rows}
    lines = ["| m | angle RMS (°) | joint-position error of the fit (cm) | evaluate (ns) |", "|---|---|---|---|"]
    for m in sorted(by_order):
        r = by_order[m]
        lines.append("| %d | %.2f | %.2f | %.0f |" % (m, float(r["mean_rms_deg"]), float(r["joint_error_samples_mean_cm"]),
                                                 float(r["evaluate_ns"])))
    walk_order = walk_max_order()
    if walk_order not in by_order or max(by_order) <= walk_order:
        sys.exit("make_evaluation.py: the Fourier sweep must reach past walk.yaml's order %d" % walk_order)
    low, mid, top = by_order[min(by_order)], by_order[walk_order], by_order[max(by_order)]
    error = lambda r: float(r["joint_error_samples_mean_cm"])  # noqa: E731
    sentence = ("Going from m = %d to m = %d (the order `config/motions/walk.yaml` is fitted to) costs %.1f× the "
                "evaluation time and cuts the fit's joint-position error %.1f×; the orders above it, up to m = %d, cut "
                "it by a further %.1f %% at %.1f× the time of m = %d." % (
                    min(by_order), walk_order, float(mid["evaluate_ns"]) / float(low["evaluate_ns"]),
                    error(low) / error(mid), max(by_order), 100.0 * (1.0 - error(top) / error(mid)),
                    float(top["evaluate_ns"]) / float(mid["evaluate_ns"]), walk_order))
    return lines, sentence


def walk_max_order():
    """The --max-order config/motions/walk.yaml was fitted with (its header names the command)."""
    with open(os.path.join(ROOT, "config", "motions", "walk.yaml")) as f:
        match = re.search(r"--max-order (\d+)", f.read(2000))
    if not match:
        sys.exit("make_evaluation.py: config/motions/walk.yaml's header names no --max-order")
    return int(match.group(1))


def skeleton_section(results):
    medians = benchmark_medians(os.path.join(results, "bench_skeleton_update.json"))
    rows = sorted((int(name.split("/")[1]), in_us(v)) for name, v in medians.items() if name.startswith("FullUpdate/"))
    return ["| m | full update: Fourier motion + FK of 20 bones (µs, median) |", "|---|---|"] + \
        ["| %d | %.2f |" % (m, t) for m, t in rows]


def tessellation_section():
    rows = read_csv(os.path.join(DOCS, "tessellation_accuracy.csv"))
    skin = [r for r in rows if r["surface"] == "skin"]
    lines = ["| method | setting | triangles | max geometric error (mm) | time (µs) |", "|---|---|---|---|---|"]
    for r in skin:
        lines.append("| %s | %s | %s | %.2f | %.0f |" % (r["method"], r["parameter"], r["triangles"],
                                                     float(r["max_error_mm"]), float(r["tessellate_us"])))
    return lines


def scene_budget_section(results):
    rows = read_csv(os.path.join(results, "scene_budget.csv"))
    for r in rows:
        r["humans"], r["distance_m"] = int(r["humans"]), float(r["distance_m"])
        for key in ("median_update_ms", "max_error_mm", "max_error_px"):
            r[key] = float(r[key])
        r["triangles"] = int(r["triangles"])
        r["label"] = "automatic" if r["lod"] == "automatic" else "level %s" % r["level"]
        if r["vertices"] == "gpu":
            r["label"] += ", GPU vertices"

    figure, axes = plt.subplots(1, 2, figsize=(13, 5))
    for humans, marker in ((1, "o"), (5, "s"), (10, "^")):
        for r in rows:
            if r["humans"] != humans:
                continue
            colour = {"automatic": "tab:green", "automatic, GPU vertices": "tab:purple"}.get(
                r["label"], "tab:blue" if r["level"] == "4" else "tab:red")
            short = {"automatic": "auto", "automatic, GPU vertices": "GPU"}.get(r["label"], "L" + r["level"])
            text = "%s %d×%gm" % (short, humans, r["distance_m"])
            for ax, x in ((axes[0], r["triangles"]), (axes[1], r["median_update_ms"])):
                ax.plot(x, max(r["max_error_px"], 1e-3), marker, color=colour)
                ax.annotate(text, (x, max(r["max_error_px"], 1e-3)), textcoords="offset points", xytext=(4, 3),
                            fontsize=7)
    for ax, xlabel in ((axes[0], "triangles per frame"),
                       (axes[1], "update per frame: pose + tessellate, or pose + layout with GPU vertices\n(ms, one core, median)")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel("max tessellation error on screen (pixels, bound)")
        ax.axhline(1.0, color="grey", lw=0.8, ls="--")
        ax.grid(True, which="both", alpha=0.3)
    figure.suptitle("Scene budget: automatic level of detail (auto, green; GPU vertex evaluation, purple) vs fixed "
                    "level 4 (L4, blue) and 8 (L8, red); n×d: n humans at d m")
    figure.tight_layout()
    figure.savefig(os.path.join(DOCS, "scene_budget.png"), dpi=110)
    plt.close(figure)

    lines = ["| humans | distance | level of detail | triangles | update (ms, median) | max error (mm) | max error on screen (px) |",
             "|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %d | %g m | %s | %d | %.3f | %.2f | %.2f |" % (r["humans"], r["distance_m"], r["label"],
                                                                     r["triangles"], r["median_update_ms"],
                                                                     r["max_error_mm"], r["max_error_px"]))
    savings = []
    for humans, distance in sorted({(r["humans"], r["distance_m"]) for r in rows}):
        here = [r for r in rows if r["humans"] == humans and r["distance_m"] == distance]
        auto = next((r for r in here if r["label"] == "automatic"), None)
        gpu = next((r for r in here if r["vertices"] == "gpu"), None)
        fixed = next((r for r in here if r["level"] == "8" and r["lod"] != "automatic"), None)
        if auto is None or gpu is None or fixed is None:
            sys.exit("make_evaluation.py: scene_budget.csv lacks the automatic, GPU or level-8 row for %d at %g m"
                     % (humans, distance))
        savings.append("%d human%s at %g m: %.2f× the triangles and %.2f× the time of level 8, max %.2f px error "
                       "(level 8: %.2f px); with GPU vertices the update takes %.3f ms instead of %.3f ms"
                       % (humans, "s" if humans > 1 else "", distance, auto["triangles"] / fixed["triangles"],
                          auto["median_update_ms"] / fixed["median_update_ms"], auto["max_error_px"],
                          fixed["max_error_px"], gpu["median_update_ms"], auto["median_update_ms"]))
    alone = sorted({r["distance_m"] for r in rows if r["humans"] == 1})
    groups = sorted({(r["humans"], r["distance_m"]) for r in rows if r["humans"] > 1})
    scene = "alone at %s m from the camera and as rows of %s" % (
        words(["%g" % d for d in alone]), words(["%d humans 1 m apart seen from %g m" % g for g in groups]))
    return lines, savings, scene


def words(items):
    """'a', 'a and b', 'a, b and c'."""
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def relief_modes_section(results):
    rows = read_csv(os.path.join(results, "relief_modes.csv"))
    figure, axes = plt.subplots(figsize=(7.5, 5))
    colours = {"Displaced geometry": "tab:red", "Bump mapping": "tab:green", "Flat": "tab:grey"}
    for r in rows:
        x, y = float(r["display_ms_median"]), float(r["rms_difference_to_displaced_garments"])
        axes.plot(x, y, "o", color=colours[r["mode"]])
        axes.annotate("%s, %s m" % (r["mode"], r["distance_m"]), (x, y), textcoords="offset points", xytext=(5, 4),
                      fontsize=8)
    axes.set_xscale("log")
    axes.set_xlabel("display CPU per frame (ms, median)")
    axes.set_ylabel("RMS luminance difference to displaced geometry\non the garments (0-255)")
    axes.set_title("Relief: bump mapping vs displaced geometry, near and far")
    axes.grid(True, which="both", alpha=0.3)
    figure.tight_layout()
    figure.savefig(os.path.join(DOCS, "relief_modes.png"), dpi=110)
    plt.close(figure)
    return read_text(os.path.join(DOCS, "relief_modes.md"))


def skin_map_section(results):
    medians = benchmark_medians(os.path.join(results, "bench_relief.json"))
    points = {}
    for name, value in medians.items():
        if name.startswith("SkinMapLevels/"):
            _, resolution, levels = name.split("/")[:3]
            points.setdefault(int(levels), []).append((int(resolution), in_ms(value)))
    if not points:
        sys.exit("make_evaluation.py: bench_relief.json has no SkinMapLevels/<resolution>/<levels> runs")
    figure, axes = plt.subplots(figsize=(7.5, 5))
    lines = ["| resolution | levels | skin map (ms, median, one core) |", "|---|---|---|"]
    for levels in sorted(points):
        series = sorted(points[levels])
        axes.plot([p[0] ** 2 for p in series], [p[1] for p in series], "o-", label="%d level%s" % (levels, "s" * (levels > 1)))
        for resolution, ms in series:
            axes.annotate("%d², L%d" % (resolution, levels), (resolution ** 2, ms), textcoords="offset points",
                          xytext=(4, 3), fontsize=7)
            lines.append("| %d² | %d | %.1f |" % (resolution, levels, ms))
    brute = [(int(n.split("/")[1]), in_ms(v)) for n, v in medians.items() if n.startswith("SkinMapBruteForce/")]
    for resolution, ms in brute:
        axes.plot(resolution ** 2, ms, "kx")
        axes.annotate("brute force %d², L1" % resolution, (resolution ** 2, ms), textcoords="offset points",
                      xytext=(4, 3), fontsize=7)
        lines.append("| %d² | 1 (brute-force nearest seed, reference) | %.1f |" % (resolution, ms))
    axes.axhline(50.0, color="grey", ls="--", lw=0.8)
    axes.annotate("target 50 ms at 1024², 3 levels", (256 ** 2, 52), fontsize=8, color="grey")
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("pixels")
    axes.set_ylabel("time (ms, median)")
    axes.set_title("Voronoi skin map: resolution and levels vs time")
    axes.legend()
    axes.grid(True, which="both", alpha=0.3)
    figure.tight_layout()
    figure.savefig(os.path.join(DOCS, "skin_map_speed.png"), dpi=110)
    plt.close(figure)
    target = dict(points.get(3, [])).get(1024)
    if target is None:
        sys.exit("make_evaluation.py: bench_relief.json has no SkinMapLevels/1024/3 run")
    verdict = ("The target, 1024² with 3 levels in 50 ms on one core, is %s: %.1f ms in this run."
               % ("met" if target <= 50.0 else "not met", target))
    build = medians.get("SkinHierarchyBuild")
    if build is None:
        sys.exit("make_evaluation.py: bench_relief.json has no SkinHierarchyBuild run")
    verdict += (" Building the cell hierarchy for a parameter set (seeds, wobbled walls, each cell's sectors) "
                "takes %.1f ms once, so a new parameter set costs %.1f ms to its first 1024² map."
                % (in_ms(build), in_ms(build) + target))
    return lines, verdict


def smooth_fold_sentence(results):
    rows = read_csv(os.path.join(results, "smooth_fold_error.csv"))
    default = int(rows[0]["default_harmonics_per_cell"])
    at_default = [r for r in rows if int(r["harmonics_per_cell"]) == default]
    if not at_default:
        sys.exit("make_evaluation.py: smooth_fold_error.csv has no row at the default %d harmonics" % default)
    worst = max(float(r["rms_error"]) / float(r["h1"]) for r in at_default)
    return ("The displayed folds are the exact tile blurred through its own Fourier series; the default, %d "
            "harmonics per cell, keeps %s at alpha %s within %.1f %% RMS of h1 (the worst of them)." % (
                default, words(sorted({r["pattern"] for r in at_default})),
                words(sorted({r["alpha"] for r in at_default})), 100.0 * worst))


def rviz_scaling_verdict(results):
    """What the in-view rviz run (rviz_scaling.csv, several runs per point) says: DressedHuman
    against RobotModel, the vertex paths against each other beyond their spread (which one
    "Automatic" should pick here), and the goals of 10 humans at the nearest distance."""
    rows = read_csv(os.path.join(results, "rviz_scaling.csv"))
    by = {(r["display"], int(r["humans"]), float(r["distance_m"])): r for r in rows}
    not_drawn = ["%s x %d at %s m" % (r["display"], int(r["humans"]), r["distance_m"]) for r in rows
                 if int(r["drawn"]) < int(r["humans"])]
    if not_drawn:
        sys.exit("make_evaluation.py: rviz_scaling.csv has points that did not draw every human: " + ", ".join(not_drawn))
    names = ("DressedHuman (GPU vertices)", "DressedHuman (CPU vertices)", "RobotModel")
    automatic = rows[0]["automatic_choice"]
    default = names[0] if automatic == "GPU" else names[1]
    cost = lambda r: "%.2f ms (%.2f–%.2f)" % (float(r["per_human_ms"]), float(r["per_human_low"]),  # noqa: E731
                                            float(r["per_human_high"]))
    fps = lambda r: "%.1f" % float(r["fps"]) + ("" if float(r["fps_high"]) - float(r["fps_low"]) < 0.5  # noqa: E731
                                                else " (%.1f–%.1f)" % (float(r["fps_low"]), float(r["fps_high"])))
    points = sorted({(int(r["humans"]), float(r["distance_m"])) for r in rows},
                    key=lambda p: (p[1] != min(float(r["distance_m"]) for r in rows), p[1], p[0]))
    sentences, cheaper = [], {"GPU": [], "CPU": [], "neither": []}
    for count, distance in points:
        gpu, cpu, robot = (by[(name, count, distance)] for name in names)
        sentences.append(
            "%d human%s at %g m: DressedHuman %s fps, rviz CPU per human per frame %s with CPU vertices; %s fps, %s "
            "with GPU vertices; RobotModel %s fps, %s" % (
                count, "s" if count > 1 else "", distance, fps(cpu), cost(cpu), fps(gpu), cost(gpu), fps(robot),
                cost(robot)))
        # Beyond the spread: one path's costliest run below the other's cheapest.
        if float(gpu["per_human_high"]) < float(cpu["per_human_low"]):
            cheaper["GPU"].append("%d at %g m" % (count, distance))
        elif float(cpu["per_human_high"]) < float(gpu["per_human_low"]):
            cheaper["CPU"].append("%d at %g m" % (count, distance))
        else:
            cheaper["neither"].append("%d at %g m" % (count, distance))
    runs = int(rows[0]["repeats"])
    verdict = "Vertex paths over %d runs per point: " % runs + "; ".join(
        "%s cheaper beyond the spread at %s" % (path, words(where)) for path, where in cheaper.items()
        if where and path != "neither")
    if cheaper["neither"]:
        verdict += ("; " if len(verdict) > 40 else "") + "ranges overlapping at " + words(cheaper["neither"])
    other = "CPU" if automatic == "GPU" else "GPU"
    if len(cheaper[automatic]) > len(cheaper[other]):
        judged = "this run supports that: it was the cheaper one at more points"
    elif len(cheaper[automatic]) < len(cheaper[other]):
        judged = "this run does **not** support that: the %s was the cheaper one at more points" % other
    else:
        judged = "this run does not decide between the two paths"
    verdict += ". `Vertex Evaluation: Automatic` chose the %s on this renderer; %s" % (automatic, judged)
    sentences.append(verdict)
    near = points[0][1]
    if (default, 10, near) in by:
        human, robot = by[(default, 10, near)], by[(names[2], 10, near)]
        frame_rate, ratio, per_human = float(human["fps"]), float(human["fps"]) / float(robot["fps"]), float(
            human["per_human_ms"])
        sentences.append("Goals for 10 humans at %g m (issue 19), DressedHuman as configured by default here (%s "
                         "vertices, Automatic's choice): ≥ 29 fps: %.1f (%s); ≥ 1.5× RobotModel's fps: %.2f× (%s); "
                         "≤ 3 ms rviz CPU per human: %.2f ms (%s)" % (
                             near, automatic, frame_rate, "met" if frame_rate >= 29 else "not met", ratio,
                             "met" if ratio >= 1.5 else "not met", per_human, "met" if per_human <= 3 else "not met"))
    if any(float(r["per_human_ms"]) < 0 for r in rows):
        sentences.append("A negative CPU per human is noise: the empty scene, measured in its own run, cost more "
                         "than that point with its few humans; the host's load varies by more than one human costs")
    return "\n".join("- " + s + "." for s in sentences)


def run_spread_sentence(results):
    """How much the same point differed between runs, from rviz_scaling.csv's ranges."""
    rows = read_csv(os.path.join(results, "rviz_scaling.csv"))
    # Of rviz's whole CPU per frame: a few humans' own cost is smaller than the host's noise.
    spread = max((float(r["per_human_high"]) - float(r["per_human_low"])) * int(r["humans"]) /
                 float(r["cpu_ms_per_frame"]) for r in rows)
    return ("The machine is a virtual one on a shared host: in this run the same point's rviz CPU per frame "
            "differed by up to %.0f %% of its median between its %s runs (`bench/rviz_scaling.py`), so the ratios "
            "against peers measured in the same run are the figures to compare." % (100.0 * spread, rows[0]["repeats"]))


def node_cpu_verdict():
    """The ratio column of docs/node_cpu.md against the target, ≤ 0.5× robot_state_publisher."""
    verdicts = []
    for line in read_text(os.path.join(DOCS, "node_cpu.md")).splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 4 and cells[0].endswith("Hz") and re.match(r"^[\d.]+$", cells[3]):
            ratio = float(cells[3])
            verdicts.append("%s: %.2f× (%s)" % (cells[0], ratio, "met" if ratio <= 0.5 else "not met"))
    if not verdicts:
        sys.exit("make_evaluation.py: docs/node_cpu.md has no ratio column")
    return "Target ≤ 0.5× robot_state_publisher's CPU: " + "; ".join(verdicts) + "."


def rviz_scaling_scene(results):
    """'1, 10 and 30 humans ... 12 m away' as the run measured them."""
    rows = read_csv(os.path.join(results, "rviz_scaling.csv"))
    near = min(float(r["distance_m"]) for r in rows)
    counts = sorted({int(r["humans"]) for r in rows if float(r["distance_m"]) == near})
    far = sorted({(int(r["humans"]), float(r["distance_m"])) for r in rows if float(r["distance_m"]) != near})
    text = "%s humans walking in place, all in view %g m away" % (words([str(n) for n in counts]), near)
    if far:
        text += ", and %s" % words(["%d at %g m" % f for f in far])
    return text


def readme_speed_section(results, machine, skeleton_lines, rviz_verdict):
    """The README's "Speed" figures, from this run only."""
    skin_json = os.path.join(results, "bench_skin.json")
    skin = benchmark_medians(skin_json)
    default = skin.get("BM_SkinPoseAndTessellate/4")
    fine = skin.get("BM_SkinPoseAndTessellate/8")
    if default is None or fine is None:
        sys.exit("make_evaluation.py: bench_skin.json has no BM_SkinPoseAndTessellate/4 and /8 runs")
    return README_SPEED.format(
        machine=machine, skeleton_table="\n".join(skeleton_lines), skin_default=in_us(default), skin_fine=in_us(fine),
        skin_patches=int(benchmark_counter(skin_json, "BM_SkinPose", "patches")),
        rviz_scene=rviz_scaling_scene(results),
        node_cpu=read_text(os.path.join(DOCS, "node_cpu.md")), node_verdict=node_cpu_verdict(),
        rviz_scaling=read_text(os.path.join(DOCS, "rviz_scaling.md")), rviz_verdict=rviz_verdict,
        rviz_memory=read_text(os.path.join(DOCS, "rviz_memory.md")),
        crowd_scaling=read_text(os.path.join(DOCS, "crowd_scaling.md")),
        relief_switch=read_text(os.path.join(DOCS, "relief_switch.md")))


README_BEGIN = "<!-- Written by scripts/make_evaluation.py from one run of scripts/evaluate.sh: edit it there. -->"
README_END = "<!-- End of the section written by scripts/make_evaluation.py. -->"


def write_readme_section(text):
    path = os.path.join(ROOT, "README.md")
    with open(path) as f:
        readme = f.read()
    begin, end = readme.find(README_BEGIN), readme.find(README_END)
    if begin < 0 or end < begin:
        sys.exit("make_evaluation.py: README.md has no generated-section markers")
    with open(path, "w") as f:
        f.write(readme[:begin + len(README_BEGIN)] + "\n" + text.strip() + "\n" + readme[end:])


def main():
    global DOCS
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    results = sys.argv[1]
    record = run_record(results)
    DOCS = need(os.path.join(results, "docs"))
    machine = record["machine"]
    fourier_lines, fourier_sentence = fourier_section()
    skeleton_lines = skeleton_section(results)
    tessellation_lines = tessellation_section()
    budget_lines, savings, budget_scene = scene_budget_section(results)
    relief_table = relief_modes_section(results)
    skin_lines, skin_verdict = skin_map_section(results)
    stability = read_text(os.path.join(SOURCE_DOCS, "stability.md"))
    if stability.startswith("# "):
        stability = stability.split("\n", 1)[1].strip()
    stability = stability.replace("\n## ", "\n### ")  # its sections sit under this report's
    rviz_verdict = rviz_scaling_verdict(results)
    text = TEMPLATE.format(
        machine=machine, duration=record["duration"], spread=run_spread_sentence(results),
        fourier_table="\n".join(fourier_lines), fourier_sentence=fourier_sentence,
        skeleton_table="\n".join(skeleton_lines),
        node_cpu=read_text(os.path.join(DOCS, "node_cpu.md")),
        tessellation_table="\n".join(tessellation_lines),
        budget_table="\n".join(budget_lines), budget_savings="\n".join("- " + s for s in savings),
        budget_scene=budget_scene,
        relief_table=relief_table,
        skin_table="\n".join(skin_lines), skin_verdict=skin_verdict,
        smooth_folds=smooth_fold_sentence(results),
        rviz_scene=rviz_scaling_scene(results),
        rviz_verdict=rviz_verdict,
        rviz_scaling=read_text(os.path.join(DOCS, "rviz_scaling.md")),
        rviz_memory=read_text(os.path.join(DOCS, "rviz_memory.md")),
        crowd_scaling=read_text(os.path.join(DOCS, "crowd_scaling.md")),
        track_following=read_text(os.path.join(DOCS, "track_following.md")),
        relief_switch=read_text(os.path.join(DOCS, "relief_switch.md")),
        relief_flicker=read_text(os.path.join(DOCS, "relief_flicker.md")),
        skin_distance=read_text(os.path.join(DOCS, "skin_distance.md")),
        relief_distance=read_text(os.path.join(DOCS, "relief_distance.md")),
        stability=stability)
    readme = readme_speed_section(results, machine, skeleton_lines, rviz_verdict)
    with open(os.path.join(DOCS, "EVALUATION.md"), "w") as f:
        f.write(text)
    # Everything was read and written inside the run's folder: only now does docs/ change.
    publish(DOCS)
    write_readme_section(readme)
    print("published %s to docs/ and wrote the README's Speed section" % results)


TEMPLATE = """# Speed against accuracy

"Both speed and accuracy count: chart one against the other, test stability where methods fail,
and model no more than a scene needs." Everything below was written from one run of one command,
`scripts/evaluate.sh` ({duration} on the machine below), from the project's own tools and
benchmarks; medians of repeated runs throughout, with ratios against a peer (robot_state_publisher,
rviz's RobotModel, spencer's walking-man meshes, brute force, uniform tessellation) measured in
the same run.

Machine and run: {machine} {spread}

## Motion: Fourier order m

![Fourier order](fourier_order_speed_vs_accuracy.png)

`fit_motion data/motion/cmu_02_01_walk.bvh --sweep-csv ...` fits the CMU walk at every order and
measures the fit against the capture; `scripts/chart_fourier_order.py` draws it.

{fourier_table}

{fourier_sentence}

Skeleton update per tick (`bench_skeleton_update`, Google Benchmark, median of 5 repetitions):

{skeleton_table}

The node against its peer, robot_state_publisher, publishing the same URDF's TF at the same rate
(`bench/node_cpu.py`):

{node_cpu}

## Surfaces: tessellation, uniform vs adaptive

![Tessellation](tessellation_speed_vs_accuracy.png)

`scripts/chart_tessellation.py --tool tessellation_accuracy`: measured geometric error (closest
point on the patch, not the bound) against triangles and time. The real skin in a walk pose:

{tessellation_table}

## Scene budget: what the automatic level of detail saves

![Scene budget](scene_budget.png)

`scene_budget` (src/tools/scene_budget.cpp): the dressed human (jacket + skirt) over 60 walk poses
(one gait cycle, played twice, the second timed),
{budget_scene};
automatic level of detail (1 px screen-space error bound, rviz's default 0.8 rad field of view on
a 1000 px viewport; the display's default) against the fixed levels 4 (the core's default,
Skin::kDefaultLevel) and 8. Error columns are the
error bound the level of detail uses per patch (CalibratedErrorBound: never below a patch's error as drawn, each part's largest bound within 2× of its largest drawn error, test_calibrated_error_bound), in mm and projected to pixels at the patch's nearest point. The
"GPU vertices" rows are what rviz's thread pays when the vertex shader evaluates the patches
(the display's choice on a graphics card): posing the control points and choosing levels, plus a new mesh layout
when the levels change; their levels sit on a coarse ladder that only drops after 2 s, hence
somewhat more triangles for the same error bound.

{budget_table}

{budget_savings}

## Relief: bump mapping against displaced geometry

![Relief modes](relief_modes.png)

`bench/relief_modes.py`: one frozen human in rviz (Mesa llvmpipe), the same view in the three
relief modes of the display; the image difference is measured against displaced geometry, the
reference bump mapping approximates (relief strength 2 so that it is large enough to matter).
The chart uses the garment pixels: displaced geometry at its 24 x 24 cuts per patch resolves the
folds but not the skin's finer cells (about 12 x 12 per patch, 2 or 3 levels), which it filters
out (each vertex reads the relief's mip level for its spacing) rather than alias them into noise:
on the skin it is a reference only for the coarse cells, and the whole-figure column carries
what bump mapping adds finer than that.

{relief_table}

Images: `docs/relief_modes/`.

### What hiding an unseen relief changes

![Relief switch](relief_switch.png)

`bench/relief_switch.py`: one frozen human drawn with `Hide Unseen Relief` on and off from 2 to
32 m. Where a relief's features cover 3 pixels or fewer (faded to nothing) the display draws it with the plain material
(no normal-map fetch); the difference is what the relief still added there. Images and their
difference (×8): `docs/relief_switch/`.

{relief_switch}

## Skin relief map: levels and resolution against time

![Skin map speed](skin_map_speed.png)

`bench_relief` (Google Benchmark, median of 5 repetitions, one core), with the brute-force
nearest-seed renderer as the reference the tests compare against. The fast renderer rasterises
each cell sector by sector; it differs from the reference only in which cell owns a few pixels
along furrows — at most 0.1 % of pixels at 256², the tolerance
`SkinRelief.FastRenderMatchesReferenceWithinTolerance` asserts:

{skin_table}

{skin_verdict} The display renders its 512² map off rviz's thread, so rviz never waits for it.

## Wrinkles: Gaussian approximation against exact folds

![Gaussian approximation](relief/gaussian_rms_vs_terms.png)

`scripts/make_relief_figures.py`: RMS height error of the Gaussian sum against the exact
piecewise-planar fold, per number of Gaussians; each term costs one exp() per pixel.

## Wrinkles: smooth folds against exact folds, and where they show

![Smooth folds](relief/smooth_fold_rms_vs_harmonics.png)

{smooth_folds}

![Fold strength against the bend](relief/fold_strength_vs_flexion.png)

What the renderer shows behind the knee and inside the elbow over `walk.yaml`
(`wrinkle_placement_walk`, per-vertex strength as the vertex shader computes it).

![Close-ups](relief/fold_closeups.png)

`fold_closeups`: the walk's most and least bent pose; the exact folds moved into a level-64
mesh, the smooth folds tilting its normals (as the shader's bump mapping does per pixel), and
the single unoriented Y-Y tile drawn before issue 21.

### Shimmer under sub-pixel motion and over a walk

`bench/relief_flicker.py`: one human frozen at phase 0.5 of the shipped walk, drawn twice from
distances 0.2 % apart (the figure moves by a fraction of a pixel, as between two frames of a slow
walk); the mean change over the garments' and the skin's pixels, with the relief as drawn by
default (faded out from 6 to 3 pixels per feature, then not drawn), forced on (with the normal
maps' own mip levels: the normals of the filtered relief), forced on with the GPU's mip levels
instead (averaged encoded normals, for comparison), forced on without mipmaps, and flat (what the
motion alone changes). Then the same human at consecutive 30 fps frames of its walk: what each
condition changes beyond flat is the relief's own flicker.

{relief_flicker}

### The skin relief by distance

![Skin relief by distance](relief/skin_distance.png)

![Skin at 1 m](relief/skin_closeup.png)

`bench/skin_distance.py`: the same frozen human from 1 to 8 m, drawn with the default relief and
with `Relief: Flat`; what the relief adds over the skin's and the garments' pixels. The close-up
is the nearest distance, cropped to the skin: relief (left), flat (right).

{skin_distance}

### The relief at the distances users view from (issue 40)

![Relief at 0.3-5 m, flat, before and after](relief_distance.png)

`bench/relief_distance.py`: one human frozen in a bent pose (the walk's phase 0.5, replayed at speed
0), its body seen from 0.5, 1, 2.5 and 5 m and its hand and head from 0.3 m, and the same human
standing at rest (every joint at 0: no garment compressed, so no fold may show) from 2.5 m; per view the flat shot,
then the default relief of the build this run was given as "before" (if any) and of this commit.
The skin's cells are sized in metres per body region (README, the rviz display); the garments'
folds are the exact folds blurred by `Fold Softness` (twice as far along the folds as across them)
and kept as deep as the exact folds, laid along the folds' direction by fold coordinates
(`fold_coordinates.h`: one pattern that bends with the field, where twelve fixed orientations
cross-faded two patterns of unrelated phase and read as creases where the direction turns).

{relief_distance}

## The display against rviz's RobotModel

![rviz scaling](rviz_scaling.png)

`bench/rviz_scaling.py`: {rviz_scene} (rows of 10, 1 m apart; rows 3 m behind
one another, seen from higher up, beyond 10); DressedHuman displays (jacket + skirt, automatic
level of detail; vertices evaluated by the vertex shader and by the CPU) against the same number
of RobotModel displays of the URDF, in one run. Each point saves a screenshot as its measurement starts and as it ends
(`docs/rviz_scaling/`) and counts only if every human is drawn in both.

{rviz_scaling}

{rviz_verdict}

Memory per additional human: the table's resident memory grows with time as TF streams in, with
or without humans drawn, so `bench/rviz_memory.py` compares runs of the same length with the same
humans publishing that differ only in what rviz draws:

{rviz_memory}

## A crowd from one publisher against spencer's walking-man meshes

![crowd scaling](crowd_scaling.png)

`bench/crowd_scaling.py`: one `crowd_publisher` walks every human (on treadmills, in the rows
above) and publishes one `dressed_human/Crowd` message for all at 30 Hz; one DressedHuman display
draws them (`Humans: From Topic`). The peer, spencer's TrackedPersons display with its walking-man
meshes, gets one TrackedPersons message for all persons at the same rate and places. Both subjects'
per-human costs are counted against one baseline per crowd size: the median of every run of rviz
drawing only its grid at that size, each with one subject's publisher running. The subjects take
turns, a run of ours and then one of the peer's per repeat, so that a drift of the machine over a
crowd size's minutes falls on both.
Then rviz's resident memory over minutes with the shipped `crowd.launch count:=40`.

{crowd_scaling}

## People from elsewhere: walkers following recorded pedestrians

![track following](track_following.png)

`bench/track_following.py`: the shared Jülich recordings resampled at a tracker's rates, each
person a walker following its track (`src/tools/track_following.cpp` runs the core's TrackedCrowd
as `crowd_publisher ~people_topic` does), and the node's CPU following `trajectories.launch`.

{track_following}

"rviz CPU per human" is the whole rviz process (its thread, Ogre, and Mesa's software rasteriser
on both cores) minus the empty scene, divided by the humans; "the display's own update" is what
the DressedHuman display measures of its update() on rviz's thread (TF lookups, posing, level of
detail, uploads): most of a human's cost is the drawing, not the display.

## Stability where methods fail

{stability}
"""

README_SPEED = """Machine and run: {machine} Everything in this section is written by
`scripts/make_evaluation.py` from that one run of `scripts/evaluate.sh`; more in
[docs/EVALUATION.md](docs/EVALUATION.md).

One full skeleton update (Eq. 1 for 48 DOF and the root at order m, then forward kinematics to
all frames), `bench_skeleton_update`, median of 5 repetitions:

{skeleton_table}

Skin, `bench_skin`: pose + tessellate the whole skin ({skin_patches} patches) at the default level 4 in
{skin_default:.0f} µs, at level 8 in {skin_fine:.0f} µs (median, one core).

Node CPU against robot_state_publisher, same URDF, same rate (`bench/node_cpu.py`; each TF
stream has one subscriber; RSP is fed by a JointState stream at the same rate):

{node_cpu}

{node_verdict}

rviz with {rviz_scene} (a screenshot at the start and end of each
point proves every human drawn), DressedHuman displays (jacket + skirt, automatic
level of detail) against the same number of RobotModel displays of the same URDF
(`bench/rviz_scaling.py`):

![rviz scaling](docs/rviz_scaling.png)

{rviz_scaling}

{rviz_verdict}

Memory per additional human, with the same humans publishing TF in every run (`bench/rviz_memory.py`):

{rviz_memory}

A crowd from one publisher (one `dressed_human/Crowd` message for all at 30 Hz, one display "From
Topic") against spencer's walking-man meshes fed one TrackedPersons message at the same rate and
places, and rviz's memory over minutes with `crowd.launch count:=40` (`bench/crowd_scaling.py`):

![crowd scaling](docs/crowd_scaling.png)

{crowd_scaling}
"""

if __name__ == "__main__":
    main()
