#!/usr/bin/python3
"""What fitting the captured person's proportions buys: joint-position error against the capture's
own forward kinematics, in cm, against the Fourier order, on the fitted body and on our default
1.75 m body, with the angle residual in degrees; the feet in stance. Runs fit_motion's order sweep
on the CMU walk, on another CMU subject's walk that nothing here was fitted on (07_01) and on
OpenSim's tutorial gait cycle (on the gait2392 model) and writes the chart and the Markdown tables
from those runs. With BANDAI_MIRROR (a bare clone of BandaiNamcoResearchInc/
Bandai-Namco-Research-Motiondataset, whose CC BY-NC-ND captures this repository does not carry),
also every dataset-1 walk's first take: another lab's rig, fitted at fit_motion's default order.
With LAFAN_MIRROR (a bare clone of karstm/motion-matching, whose history carried two LAFAN1 walks,
CC BY-NC-ND), also those: the straightest stretch of each, fitted at the default order. With
MIXAMO_MIRROR (a bare clone of jerech33/haze), also its Mixamo-rigged walk cycle.

Usage: [BANDAI_MIRROR=DIR] [LAFAN_MIRROR=DIR] [MIXAMO_MIRROR=DIR] chart_body_fit.py FIT_MOTION [CAPTURE]
  writes docs/body_fit_accuracy.png, docs/body_fit_accuracy.md, docs/body_fit_sweep_cmu_02_01.csv,
  docs/body_fit_sweep_cmu_07_01.csv and docs/body_fit_sweep_opensim_gait2392.csv
"""
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
DOCS = os.environ.get("DRESSED_HUMAN_DOCS", os.path.join(ROOT, "docs"))  # evaluate.sh: its run's folder


def sweep(tool, capture, name, extra):
    """fit_motion's order sweep of one capture: its CSV rows and its verbose report."""
    path = os.path.join(DOCS, "body_fit_sweep_%s.csv" % name)
    with tempfile.TemporaryDirectory() as directory:
        report = subprocess.run([tool, capture, "--urdf", os.path.join(ROOT, "urdf", "human.urdf"), "-o",
                                 os.path.join(directory, "walk.yaml"), "--sweep-csv", path, "--sweep-max", "10",
                                 "--timing-calls", "1000", "-v"] + extra,
                                capture_output=True, text=True, check=True, cwd=ROOT).stderr
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows or rows[0]["body_fitted"] != "1":
        sys.stderr.write("%s: no fitted-body rows (a capture without a skeleton?)\n" % path)
        sys.exit(1)
    return rows, report, path


def table(rows):
    lines = ["| order m | angle RMS mean / worst (deg) | joints, fitted body: mean / max (cm) | "
             "joints, default body: mean / max (cm) | sole in stance off one floor, fitted: mean / max (cm) |",
             "|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f |" % (
            r["order"], float(r["mean_rms_deg"]), float(r["max_rms_deg"]), float(r["joint_error_capture_mean_cm"]),
            float(r["joint_error_capture_max_cm"]), float(r["default_body_capture_mean_cm"]),
            float(r["default_body_capture_max_cm"]), float(r["stance_foot_mean_cm"]), float(r["stance_foot_max_cm"])))
    return lines


def reportLines(report):
    summary = [line.strip() for line in report.splitlines()
               if line.strip().startswith(("Body fitted", "Our sole in stance"))]
    per_joint = [line.strip() for line in report.splitlines() if re.match(r"^ {4}[a-z_]+ +mean ", line)]
    return summary, per_joint


BANDAI_WALKS = "dataset/Bandai-Namco-Research-Motiondataset-1/data/"
# LAFAN1 (Ubisoft La Forge) walks as karstm/motion-matching carried them in its history: the
# original take of walk4_subject1, and walk1_subject1 as cropped there (its header says 5700
# frames, the file holds 5707: the reader takes the header's).
LAFAN_WALKS = [("fcce6935ab4d144a966096a1766735c638057ac3", "data/mocap/lafan1/walk4_subject1.bvh", "walk4_subject1"),
               ("84903d96666f34f16a71d603b7a21acf35a7c839", "data/mocap/lafan1_basic/walk1_subject1 copy.bvh",
                "walk1_subject1 (cropped)")]
LAFAN_WINDOW_S = 5.0     # a straight stretch: at least three gait cycles
LAFAN_MIN_SPEED = 0.5    # m/s throughout it (the takes are in cm)


def bvh_motion(bvh_text):
    """A BVH file's lines up to its frame time, the frame time (s) and its frames' lines (as many as
    its header declares: a file may hold more)."""
    lines = bvh_text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.strip().startswith("Frame Time"))
    declared = next(int(line.split(":")[1]) for line in lines if line.strip().startswith("Frames:"))
    frames = [line.rstrip() for line in lines[start + 1:] if line.strip()][:declared]
    return [line.rstrip() for line in lines[:start + 1]], float(lines[start].split(":")[1]), frames


def bvh_with_frames(header, frames):
    """A BVH file from `header` (bvh_motion's) and these frames' lines."""
    return "\n".join([("Frames: %d" % len(frames)) if line.strip().startswith("Frames:") else line
                      for line in header] + frames) + "\n"


def straightest_stretch(bvh_text):
    """The frames [first, end) of the LAFAN take's straightest LAFAN_WINDOW_S seconds walked at
    LAFAN_MIN_SPEED or faster throughout (speed and heading of the root over one second). LAFAN
    walks wander, turn and stop; fit_motion fits a periodic walk. Returns (first, end, the
    heading's range over it in degrees, the mean speed)."""
    _, frame_time, lines = bvh_motion(bvh_text)
    frames = [[float(v) for v in line.split()[:3]] for line in lines]
    second = max(1, round(1.0 / frame_time))
    window = round(LAFAN_WINDOW_S / frame_time)
    velocity = []
    for f in range(len(frames) - second):
        dx = (frames[f + second][0] - frames[f][0]) / 100.0
        dz = (frames[f + second][2] - frames[f][2]) / 100.0
        velocity.append((math.hypot(dx, dz) / (second * frame_time), math.atan2(dz, dx)))
    best = None
    for first in range(0, len(velocity) - window):
        stretch = velocity[first:first + window]
        if min(v[0] for v in stretch) < LAFAN_MIN_SPEED:
            continue
        headings, turned = [stretch[0][1]], 0.0
        for v in stretch[1:]:
            turned += math.remainder(v[1] - headings[-1], 2.0 * math.pi)
            headings.append(headings[0] + turned)
        spread = max(headings) - min(headings)
        if best is None or spread < best[2]:
            best = (first, first + window + second, spread, sum(v[0] for v in stretch) / window)
    return None if best is None else (best[0], best[1], math.degrees(best[2]), best[3])


def cut_bvh(bvh_text, first, end):
    """The take with frames [first, end) only."""
    header, _, frames = bvh_motion(bvh_text)
    return bvh_with_frames(header, frames[first:end])


MIRROR_HEADER = ["| walk | period, speed | joints: mean / max (cm) | worst joint (mean / max, cm) | "
                 "the capture's cycle-to-cycle variation: mean / max (cm) | "
                 "our skeleton on the unsmoothed retarget: mean / max (cm) | rest | "
                 "mean angles beyond 90 deg from rest |", "|---|---|---|---|---|---|---|---|"]


def fitted_row(tool, directory, name, label, bvh_bytes, options=()):
    """One Markdown row: `bvh_bytes` fitted by fit_motion -v at its default tolerances."""
    path = os.path.join(directory, name)
    with open(path, "wb") as f:
        f.write(bvh_bytes)
    run = subprocess.run([tool, path, "--urdf", os.path.join(ROOT, "urdf", "human.urdf"), "-o",
                          os.path.join(directory, "walk.yaml"), "-v"] + list(options), capture_output=True, text=True,
                         cwd=ROOT)
    if run.returncode != 0:
        reason = run.stderr.strip().splitlines()[-1].replace("fit_motion: %s: " % path, "")
        return "| %s | not fitted: %s | | | | | | |" % (label, reason)
    report = run.stderr
    number = lambda pattern: re.search(pattern, report)  # noqa: E731
    period = number(r"period ([0-9.]+) s")
    speed = number(r"forward speed (-?[0-9.]+) m/s")
    joints = number(r"root-relative\): mean ([0-9.]+) cm, max ([0-9.]+) cm")
    floor = number(r"unsmoothed retarget vs the capture's FK: mean ([0-9.]+) cm, max ([0-9.]+) cm")
    variation = number(r"cycle-to-cycle variation .*?: mean ([0-9.]+) cm, max ([0-9.]+) cm")
    per_joint = re.findall(r"^ {4}([a-z_]+) +mean ([0-9.]+) cm, max ([0-9.]+) cm", report, re.M)
    worst = max(per_joint, key=lambda j: float(j[2]))
    rest = number(r"frame (\d+) is taken as the rest pose")
    suspects = re.findall(r"suspect: (\S+) has a mean of (-?[0-9.]+) deg", report)
    varies = "%s / %s" % (variation.group(1), variation.group(2)) if variation else "one cycle only"
    return "| %s | %s s, %s m/s | %s / %s | %s %s / %s | %s | %s / %s | %s | %s |" % (
        label, period.group(1), speed.group(1), joints.group(1), joints.group(2), worst[0], worst[1], worst[2],
        varies, floor.group(1), floor.group(2),
        "frame %s" % rest.group(1) if rest else "zero pose",
        ", ".join("%s %s" % (dof, mean) for dof, mean in suspects) or "none")


def git_blob(mirror, commit, path):
    return subprocess.run(["git", "--git-dir", mirror, "show", "%s:%s" % (commit, path)], capture_output=True,
                          check=True).stdout


def bandai_rows(tool, mirror):
    """One Markdown row per dataset-1 walk (first take of each style) fitted from BANDAI_MIRROR."""
    listing = subprocess.run(["git", "--git-dir", mirror, "ls-tree", "--name-only", "HEAD", BANDAI_WALKS],
                             capture_output=True, text=True, check=True).stdout.split()
    walks = sorted(p for p in listing if re.search(r"dataset-1_walk_[a-z-]+_001\.bvh$", p))
    if not walks:
        sys.stderr.write("%s: no dataset-1 walks under %s\n" % (mirror, BANDAI_WALKS))
        sys.exit(1)
    commit = subprocess.run(["git", "--git-dir", mirror, "rev-parse", "HEAD"], capture_output=True, text=True,
                            check=True).stdout.strip()
    rows = list(MIRROR_HEADER)
    with tempfile.TemporaryDirectory() as directory:
        for walk in walks:
            style = re.search(r"walk_([a-z-]+)_001", walk).group(1)
            rows.append(fitted_row(tool, directory, os.path.basename(walk), style, git_blob(mirror, "HEAD", walk)))
    return rows, commit


def lafan_rows(tool, mirror):
    """One Markdown row per LAFAN1 walk: its straightest stretch, fitted from LAFAN_MIRROR."""
    rows = list(MIRROR_HEADER)
    with tempfile.TemporaryDirectory() as directory:
        for commit, path, label in LAFAN_WALKS:
            text = git_blob(mirror, commit, path).decode()
            stretch = straightest_stretch(text)
            if stretch is None:
                rows.append("| %s | no %.0f s stretch at %.1f m/s or faster | | | | | | |" % (
                    label, LAFAN_WINDOW_S, LAFAN_MIN_SPEED))
                continue
            first, end, spread, speed = stretch
            cut = "%s, frames %d-%d (heading within %.0f deg)" % (label, first, end - 1, spread)
            rows.append(fitted_row(tool, directory, "lafan.bvh", cut, cut_bvh(text, first, end).encode()))
    return rows


# A Mixamo-rigged walk ("mixamorig:" joint names): one in-place cycle of 40 frames that loops.
MIXAMO_WALK = ("0417d922cfe2049481d8b60fb319a880f0c9a276", "bvh/walk.bvh", "jerech33/haze walk.bvh")


def closed_loop(bvh_text):
    """A looping cycle of N frames as N + 1 frames ending where it began, its period (N frames: one
    whole cycle, which fit_motion needs the record to span) and N."""
    header, frame_time, frames = bvh_motion(bvh_text)
    return bvh_with_frames(header, frames + frames[:1]), len(frames) * frame_time, len(frames)


def mixamo_rows(tool, mirror):
    """The Mixamo walk's rows, its one cycle closed and fitted from MIXAMO_MIRROR with --period,
    and its frame count."""
    commit, path, label = MIXAMO_WALK
    text, period, frames = closed_loop(git_blob(mirror, commit, path).decode())
    with tempfile.TemporaryDirectory() as directory:
        row = fitted_row(tool, directory, "mixamo.bvh", label, text.encode(), ["--period", "%.6f" % period])
    return list(MIRROR_HEADER) + [row], frames


def bandai_section(tool, mirror):
    rows, commit = bandai_rows(tool, mirror)
    return ["## Bandai-Namco dataset-1 walks (BVH): another lab's rig, not fitted on", "",
            "BandaiNamcoResearchInc/Bandai-Namco-Research-Motiondataset @%s, every walk style's first take "
            "(CC BY-NC-ND 4.0, read from a clone, not carried here). Their pelvis hangs below a root joint "
            "and their zero pose is folded: fit_motion takes their most upright frame as the rest pose. "
            "Fitted at fit_motion's default tolerances, over every whole cycle of each take. The takes start "
            "and end at a standstill and their cycles differ: \"the capture's cycle-to-cycle variation\" is "
            "each joint against the mean of the take's cycles at the same phase, how close any periodic motion "
            "could follow it on average (fit_motion -v)." % commit[:7], ""] + rows


def lafan_section(tool, mirror):
    return ["## LAFAN1 walks (BVH): Ubisoft La Forge's rig and actor, not fitted on", "",
            "LAFAN1 (Harvey et al. 2020, CC BY-NC-ND 4.0, read from a clone of karstm/motion-matching, whose "
            "history carried two of its walks; not carried here): walk4_subject1 @%s and walk1_subject1 as "
            "cropped @%s. Their zero pose lies along the bones' x axes: fit_motion takes their most upright "
            "frame as the rest pose. The takes wander, turn and stop, so each is cut to its straightest "
            "%.0f s walked at %.1f m/s or faster throughout (chart_body_fit.py's straightest_stretch), "
            "then fitted at fit_motion's default tolerances over that stretch's whole cycles." % (
                LAFAN_WALKS[0][0][:7], LAFAN_WALKS[1][0][:7], LAFAN_WINDOW_S, LAFAN_MIN_SPEED), ""] + lafan_rows(
                    tool, mirror)


def mixamo_section(tool, mirror):
    rows, frames = mixamo_rows(tool, mirror)
    return ["## A Mixamo walk (BVH): Adobe Mixamo's rig, not fitted on", "",
            "jerech33/haze @%s `%s` (a game engine's sample; the repository states no licence and Mixamo's "
            "animations are Adobe's: read from a clone, not carried here): one in-place walk cycle of %d "
            "frames that loops, closed with its first frame and fitted as one cycle (`--period`), so it has "
            "no cycle-to-cycle variation to show; its feet slide back under a still root, so its stance feet "
            "say little." % (MIXAMO_WALK[0][:7], MIXAMO_WALK[1], frames), ""] + rows


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(sys.argv) >= 2 else 2
    tool = os.path.abspath(sys.argv[1])
    capture = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "data", "motion", "cmu_02_01_walk.bvh")
    rows, report, sweep_path = sweep(tool, capture, "cmu_02_01", [])
    other = os.path.join(ROOT, "data", "motion", "cmu_07_01_walk.bvh")
    other_rows, other_report, other_path = sweep(tool, other, "cmu_07_01", [])
    gait = os.path.join(ROOT, "data", "motion", "tutorial_normal_gait_cycle.mot")
    model = os.path.join("config", "opensim", "gait2392_joints.osim")  # relative: the report names it
    osim_rows, osim_report, osim_path = sweep(tool, gait, "opensim_gait2392", ["--osim", model, "--period", "1"])
    column = lambda name: [float(r[name]) for r in rows]
    osim_column = lambda name: [float(r[name]) for r in osim_rows]
    order = [int(r["order"]) for r in rows]

    fig, (cm, degrees) = plt.subplots(1, 2, figsize=(13, 4.8))
    cm.plot(order, column("default_body_capture_mean_cm"), "o--", color="tab:gray", label="CMU, our default body: mean")
    cm.plot(order, column("default_body_capture_max_cm"), "v:", color="tab:gray", label="CMU, our default body: max")
    cm.plot(order, column("joint_error_capture_mean_cm"), "o-", color="tab:blue", label="CMU, fitted body: mean")
    cm.plot(order, column("joint_error_capture_max_cm"), "v-", color="tab:blue", label="CMU, fitted body: max")
    cm.plot(order, column("stance_foot_max_cm"), "s-", color="tab:green", label="CMU, fitted body: lowest foot\npoint in stance, max")
    other_order = [int(r["order"]) for r in other_rows]
    cm.plot(other_order, [float(r["joint_error_capture_mean_cm"]) for r in other_rows], "o-", color="tab:purple",
            label="CMU 07_01 (not fitted on),\nfitted body: mean")
    cm.plot(other_order, [float(r["joint_error_capture_max_cm"]) for r in other_rows], "v-", color="tab:purple",
            label="... max")
    osim_order = [int(r["order"]) for r in osim_rows]
    cm.plot(osim_order, osim_column("joint_error_capture_mean_cm"), "o-.", color="tab:orange",
            label="OpenSim gait2392 cycle,\nfitted body: mean")
    cm.plot(osim_order, osim_column("joint_error_capture_max_cm"), "v-.", color="tab:orange", label="... max")
    cm.axhline(1.0, color="tab:green", lw=0.8, ls=":", label="goal: feet 1 cm")
    cm.axhline(2.0, color="tab:red", lw=0.8, ls="--", label="goal: mean 2 cm, max 5 cm")
    cm.axhline(5.0, color="tab:red", lw=0.8, ls="--")
    cm.set_yscale("log")
    cm.set_yticks([0.2, 0.5, 1, 2, 5, 10, 20, 50])
    cm.set_yticklabels(["0.2", "0.5", "1", "2", "5", "10", "20", "50"])
    cm.set_xlabel("Fourier order m")
    cm.set_ylabel("joint position vs the capture's FK (cm)")
    cm.set_xticks(order)
    cm.grid(True, which="both", alpha=0.3)
    cm.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    cm.set_title("every mapped joint and frame, root-relative")
    degrees.plot(order, column("mean_rms_deg"), "o-", color="tab:purple", label="mean over DOFs")
    degrees.plot(order, column("max_rms_deg"), "v-", color="tab:purple", alpha=0.6, label="worst DOF")
    degrees.set_xlabel("Fourier order m")
    degrees.set_ylabel("angle RMS residual (deg)")
    degrees.set_ylim(bottom=0)
    degrees.set_xticks(order)
    degrees.grid(True, alpha=0.3)
    degrees.legend(fontsize=8)
    degrees.set_title("CMU joint angles (the same on either body)")
    fig.suptitle("Captures fitted by fit_motion: the person's proportions vs our default body")
    fig.tight_layout()
    chart = os.path.join(DOCS, "body_fit_accuracy.png")
    fig.savefig(chart, dpi=110)

    summary, per_joint = reportLines(report)
    osim_summary, osim_per_joint = reportLines(osim_report)
    other_summary, other_per_joint = reportLines(other_report)
    unsmoothed = [line.strip() for line in other_report.splitlines()
                  if line.strip().startswith(("our skeleton on the unsmoothed", "joint positions, fitted series",
                                              "worst against"))]
    lines = ["<!-- Written by scripts/chart_body_fit.py from one fit_motion run per capture; do not edit. -->",
             "# Fitted body proportions: accuracy against the capture", "",
             "![accuracy](body_fit_accuracy.png)", "", "## CMU 02_01 walk (BVH)", ""] + summary + [""] + table(rows)
    lines += ["", "Per joint at the order fit_motion chose by tolerance (fitted body):", "", "```"] + per_joint + ["```", ""]
    lines += ["## CMU 07_01 walk (BVH): another subject, not fitted on", "",
              "The same rig as 02_01; nothing in the code or its tolerances was set on this capture.", ""]
    lines += other_summary + [""] + table(other_rows)
    lines += ["", "Per joint at the order fit_motion chose by tolerance (fitted body):", "", "```"] + other_per_joint
    lines += unsmoothed + ["```", ""]
    lines += ["## OpenSim tutorial gait cycle on gait2392 (`.mot` and `config/opensim/gait2392_joints.osim`)", "",
              "One cycle (`--period 1`); the reference is the model's own forward kinematics, knee translation included.",
              ""] + osim_summary + [""] + table(osim_rows)
    lines += ["", "Per joint at the order fit_motion chose by tolerance (fitted body):", "", "```"] + osim_per_joint + ["```", ""]
    for variable, section in (("BANDAI_MIRROR", bandai_section), ("LAFAN_MIRROR", lafan_section),
                              ("MIXAMO_MIRROR", mixamo_section)):
        if os.environ.get(variable, ""):
            lines += section(tool, os.environ[variable]) + [""]
    with open(os.path.join(DOCS, "body_fit_accuracy.md"), "w") as f:
        f.write("\n".join(lines))
    print("wrote %s, %s, %s, %s, %s" % (chart, os.path.join(DOCS, "body_fit_accuracy.md"), sweep_path, other_path,
                                        osim_path))
    return 0


if __name__ == "__main__":
    sys.exit(main())
