#!/usr/bin/python3
"""The relief at the distances users view humans from (issue 40): one dressed human frozen in a
bent pose of the shipped walk (mode replay, speed 0, at phase 0.5: elbows and one knee bent), seen
from its body frame at 0.5, 1, 2.5 and 5 m and its hand and head from 0.3 m, and standing at
rest (the walk's joint angles all 0: nowhere is a garment compressed) from 2.5 m, each drawn with
the default relief and with 'Relief: Flat'. Optionally the same shots from a build made before
(--before-devel: its devel space, whose plugin rviz then loads), so before and after come from
one run of this script.

Per shot it measures, over the pixels that are skin (garment) in both the relief and the flat shot:
  * skin: mean |relief - flat| (largest of R, G, B; grey levels): what the skin relief adds;
  * cloth: the luminance change D = relief - flat over the garment's inner pixels (all 8
    neighbours garment too); where |D| >= 1 grey level ("relief pixels", their share of the garment
    pixels: coverage), mean |Laplacian of D| / mean |D|: how sharp the creases are (a crease is a
    jump in D, large against the Laplacian's 4-neighbour stencil; a soft fold changes D smoothly).
Writes a Markdown table, a JSON of the numbers and a figure: per distance the flat shot, the
relief before and the relief after, cropped to the human (or the hand or head).

Usage: bench/relief_distance.py [--before-devel /path/to/devel] [--figure docs/relief_distance.png]
       [--markdown docs/relief_distance.md] [--json FILE] [--images DIR]
Exits 1 when folds show on the standing human (more than STANDING_FOLD_SHARE of its garment pixels).
Needs the package built in build/ and xvfb-run.
"""
import argparse
import json
import os
import sys
import tempfile
import time

import numpy
from PIL import Image, ImageDraw

import rviz_scaling as rs
from relief_flicker import classes
from ros_processes import report, ros_environment, start, start_frozen_human, stop

BENT_PHASE = 0.5  # of walk.yaml's cycle: elbows at about 65 degrees, the swing knee bent
# (label, target frame, distance, pose): the body at the distances users view from, the hand and
# the head in a close view, all bent; the body standing at rest, where no fold may show.
VIEWS = [("body 0.5 m", "body_0", 0.5, "bent"), ("body 1 m", "body_0", 1.0, "bent"),
         ("body 2.5 m", "body_0", 2.5, "bent"), ("body 5 m", "body_0", 5.0, "bent"),
         ("hand 0.3 m", "l_wrist_0", 0.3, "bent"), ("head 0.3 m", "head_0", 0.3, "bent"),
         ("standing, body 2.5 m", "body_0", 2.5, "standing")]
LUMINANCE = numpy.array([0.299, 0.587, 0.114])
STANDING_FOLD_SHARE = 0.001  # of the standing human's garment pixels (see the end of main)
SECONDS = 5  # per shot, also the span over which rviz's CPU time per frame is measured


def standing_motion(directory):
    """The shipped walk with every joint's series at 0 (the skeleton's rest pose, in which the
    garments are made: nowhere compressed), the root's as they are; its path."""
    import yaml
    with open(os.path.join(rs.ROOT, "config", "motions", "walk.yaml")) as f:
        motion = yaml.safe_load(f)
    for joint in motion["joints"].values():
        for dof in joint:
            joint[dof] = {"a0": 0.0}
    motion["name"] = "standing at rest"
    path = os.path.join(directory, "standing.yaml")
    with open(path, "w") as f:
        yaml.safe_dump(motion, f)
    return path


def shoot(properties, target, distance, path, env, env_script=None):
    """The shot, and rviz's CPU time per frame while it drew it (ms)."""
    point = rs.harness("dressed_human/DressedHuman", 1, SECONDS, properties, path, env, distance, target_frame=target,
                       env_script=env_script)
    return numpy.asarray(Image.open(path).convert("RGB")).astype(numpy.float64), point["cpu_ms_per_frame"]


def inner(mask):
    """Pixels of `mask` whose 8 neighbours are in it too (off silhouettes and part borders)."""
    core = mask.copy()
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            core &= numpy.roll(numpy.roll(mask, dy, axis=0), dx, axis=1)
    core[0, :] = core[-1, :] = core[:, 0] = core[:, -1] = False
    return core


def crease_sharpness(change, garment):
    """Mean |Laplacian| of the luminance change over its mean |change|, on the garment pixels
    where it is 1 grey level or more (None below 50 such pixels), and those pixels."""
    laplacian = numpy.zeros_like(change)
    laplacian[1:-1, 1:-1] = (4.0 * change[1:-1, 1:-1] - change[:-2, 1:-1] - change[2:, 1:-1] - change[1:-1, :-2] -
                             change[1:-1, 2:])
    shown = garment & (numpy.abs(change) >= 1.0)
    sharpness = float(numpy.abs(laplacian[shown]).mean() / numpy.abs(change[shown]).mean()) if shown.sum() >= 50 else None
    return sharpness, shown


def screenshot_floor(flat, change, shown, garment, frequency):
    """The crease sharpness of a perfectly smooth fold as the two 8-bit screenshots show it: a
    sinusoid of the folds' own frequency (fold_frequency) and mean |change|, added to the flat shot's
    colours over its garment pixels and rounded to grey levels as rviz's screenshot rounds them.
    Rounding alone puts steps of one grey level into a smooth change of a few levels, and the
    Laplacian counts every step: at 25 px and a mean |change| of 5 levels such a fold measures
    about 0.26, at 10 levels about 0.15 (test/tools/test_crease_sharpness.py), far above
    (2 pi / period)^2 = 0.06."""
    y, x = numpy.mgrid[0:change.shape[0], 0:change.shape[1]].astype(float)
    amplitude = 0.5 * numpy.pi * numpy.abs(change[shown]).mean()  # a sinusoid's mean |value| is 2 / pi of its peak
    fold = amplitude * numpy.sin(2.0 * numpy.pi * (frequency[0] * y + frequency[1] * x))
    luminance = numpy.maximum(flat @ LUMINANCE, 1.0)
    smooth = numpy.clip(numpy.round(flat + (fold / luminance)[:, :, None] * flat), 0.0, 255.0)
    sharpness, _ = crease_sharpness(numpy.where(garment, (smooth - flat) @ LUMINANCE, 0.0), garment)
    return sharpness


def measure(relief, flat):
    cloth_a, skin_a = classes(relief)
    cloth_b, skin_b = classes(flat)
    skin, cloth = skin_a & skin_b, cloth_a & cloth_b
    difference = numpy.abs(relief - flat).max(axis=2)
    row = {"skin_pixels": int(skin.sum()), "garment_pixels": int(cloth.sum()),
           "skin_change": float(difference[skin].mean()) if skin.any() else None,
           "garment_change": float(difference[cloth].mean()) if cloth.any() else None}
    change = (relief - flat) @ LUMINANCE
    garment = inner(cloth)
    row["crease_sharpness"], shown = crease_sharpness(change, garment)
    row["fold_coverage"] = float(shown.sum() / garment.sum()) if garment.any() else None
    row["fold_period_px"] = row["screenshot_floor"] = None
    if shown.sum() >= 50:
        frequency = fold_frequency(change, shown)
        row["fold_period_px"] = 1.0 / float(numpy.hypot(*frequency))
        row["screenshot_floor"] = screenshot_floor(flat, change, shown, garment, frequency)
    return row, skin | cloth


def fold_frequency(change, shown):
    """The folds' dominant spatial frequency on screen (cycles per pixel, down and across): the
    strongest of the luminance change over the fold pixels' bounding box (periods from 3 to 60
    pixels). A perfectly smooth fold of period p measures (2 pi / p)^2 on the crease sharpness:
    the floor for folds of that size, however soft."""
    rows, columns = numpy.nonzero(shown)
    window = numpy.where(shown, change, 0.0)[rows.min():rows.max() + 1, columns.min():columns.max() + 1]
    power = numpy.abs(numpy.fft.fft2(window - window.mean())) ** 2
    fy = numpy.fft.fftfreq(window.shape[0])[:, None] + numpy.zeros((1, window.shape[1]))
    fx = numpy.fft.fftfreq(window.shape[1])[None, :] + numpy.zeros((window.shape[0], 1))
    frequency = numpy.hypot(fy, fx)
    power[(frequency < 1.0 / 60.0) | (frequency > 1.0 / 3.0)] = 0.0
    peak = numpy.argmax(power)
    return float(fy.flat[peak]), float(fx.flat[peak])


def crop(image, mask, size):
    rows, columns = numpy.nonzero(mask)
    if rows.size == 0:
        return Image.new("RGB", size, (48, 48, 48))
    top, bottom = max(rows.min() - 10, 0), min(rows.max() + 10, image.shape[0])
    left, right = max(columns.min() - 10, 0), min(columns.max() + 10, image.shape[1])
    piece = Image.fromarray(image[top:bottom, left:right].astype(numpy.uint8))
    piece.thumbnail(size, Image.LANCZOS)  # only ever shrinks
    canvas = Image.new("RGB", size, (48, 48, 48))
    canvas.paste(piece, ((size[0] - piece.width) // 2, (size[1] - piece.height) // 2))
    return canvas


def figure(shots, conditions, path):
    cell = (220, 300)
    labels = sorted({label for label, _ in shots}, key=[view[0] for view in VIEWS].index)
    rows = ["flat"] + conditions
    sheet = Image.new("RGB", (90 + cell[0] * len(labels), 24 + cell[1] * len(rows)), (255, 255, 255))
    draw = ImageDraw.Draw(sheet)
    for c, label in enumerate(labels):
        draw.text((90 + c * cell[0] + 6, 6), label, fill=(0, 0, 0))
        mask = shots[(label, "after")]["mask"]
        for r, condition in enumerate(rows):
            image = shots[(label, "after")]["flat"] if condition == "flat" else shots[(label, condition)]["relief"]
            sheet.paste(crop(image, mask, cell), (90 + c * cell[0], 24 + r * cell[1]))
    for r, condition in enumerate(rows):
        draw.text((6, 24 + r * cell[1] + cell[1] // 2), condition, fill=(0, 0, 0))
    sheet.save(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--before-devel", default="")
    parser.add_argument("--figure", default="")
    parser.add_argument("--markdown", default="")
    parser.add_argument("--json", default="")
    parser.add_argument("--images", default="")
    parser.add_argument("--views", nargs="+", default=[view[0] for view in VIEWS],
                        help="labels of VIEWS to shoot (default: all)")
    parser.add_argument("--set", action="append", default=[], metavar="PROPERTY=VALUE",
                        help="a property of the display for the 'after' shots (repeatable)")
    args = parser.parse_args()
    images = args.images or tempfile.mkdtemp()
    os.makedirs(images, exist_ok=True)
    builds = [("after", None)]
    if args.before_devel:
        builds.insert(0, ("before", os.path.join(args.before_devel, "env.sh")))
    env = ros_environment(11921)
    processes = [start(["roscore", "-p", "11921"], env)]
    shots, rows = {}, []
    motions = {"bent": None, "standing": standing_motion(images)}
    human, posed = None, None
    try:
        time.sleep(4)
        for label, target, distance, pose in [view for view in VIEWS if view[0] in args.views]:
            if pose != posed:
                if human is not None:
                    stop(human)
                    processes.remove(human)
                human = start_frozen_human(rs.ROOT, env, "/relief_distance", BENT_PHASE * 2.0 * numpy.pi, motions[pose])
                processes.append(human)
                posed = pose
            for build, env_script in builds:
                chosen = [] if build == "before" else sum((["--set", value] for value in args.set), [])
                stem = os.path.join(images, "%s_%s" % (label.replace(" ", "_"), build))
                relief, relief_ms = shoot(chosen, target, distance, stem + "_relief.png", env, env_script)
                flat, flat_ms = shoot(chosen + ["--set", "Relief=Flat"], target, distance, stem + "_flat.png", env,
                                      env_script)
                row, mask = measure(relief, flat)
                row.update(relief_cpu_ms=relief_ms, flat_cpu_ms=flat_ms)
                if not mask.any():
                    raise RuntimeError("no skin or garment pixels in %s (%s)" % (label, stem))
                row.update(view=label, build=build)
                rows.append(row)
                shots[(label, build)] = {"relief": relief, "flat": flat, "mask": mask}
                print(row, file=sys.stderr)
    finally:
        for process in reversed(processes):
            stop(process)
    if args.figure:
        figure(shots, [build for build, _ in builds], args.figure)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)

    def number(value, form):
        return "-" if value is None else form % value

    lines = ["| view | build | skin pixels | skin: relief - flat | garment pixels | garments: relief - flat | "
             "fold pixels (share) | crease sharpness (8-bit floor) | fold period (its floor) | "
             "rviz CPU ms/frame, relief (flat) |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for row in rows:
        period = row["fold_period_px"]
        floor = "-" if period is None else "%.1f px (%.2f)" % (period, (2.0 * numpy.pi / period) ** 2)
        lines.append("| %s | %s | %d | %s | %d | %s | %s | %s | %s | %.1f (%.1f) |" % (
            row["view"], row["build"], row["skin_pixels"], number(row["skin_change"], "%.2f"), row["garment_pixels"],
            number(row["garment_change"], "%.2f"), number(row["fold_coverage"] and 100 * row["fold_coverage"], "%.1f %%"),
            number(row["crease_sharpness"], "%.2f") + ("" if row["screenshot_floor"] is None else
                                                       " (%.2f)" % row["screenshot_floor"]),
            floor, row["relief_cpu_ms"], row["flat_cpu_ms"]))
    lines.append("")
    lines.append("One human frozen at phase %g of walk.yaml (mode replay, speed 0), an orbit view of the named frame "
                 "in a 1000 x 700 panel, Mesa llvmpipe, default properties. 'relief - flat': mean of the largest "
                 "|R, G, B| difference between the default relief and 'Relief: Flat' over the pixels that are skin "
                 "(garment) in both (grey levels). Fold pixels: inner garment pixels whose luminance the relief "
                 "changes by 1 grey level or more, and their share of the inner garment pixels. Crease sharpness: "
                 "mean |Laplacian| of that luminance change over its mean |change| on the fold pixels (soft folds "
                 "low, creases high); in brackets what a perfectly smooth fold of the folds' own period, direction and mean |change| measures once both 8-bit screenshots round it to grey levels (steps of one level are what the Laplacian sees in a smooth change of a few levels): the floor the screenshots put under it. Fold period: the strongest spatial frequency of that change on screen; in brackets "
                 "(2 pi / period)^2, what a perfectly smooth fold of that period measures as crease sharpness, the "
                 "floor for folds of that size however soft. rviz CPU ms/frame: rviz's process CPU time per drawn frame over the %d s of each "
                 "shot, with the relief and with 'Relief: Flat'. `bench/relief_distance.py`%s." %
                 (BENT_PHASE, SECONDS, ", 'before' from the build given by --before-devel" if args.before_devel else ""))
    report("\n".join(lines), args.markdown)
    # Where no garment is compressed no fold may show. Two renders of one frozen frame round alike,
    # so the standing human measures exactly 0 % (and forcing every vertex's wrinkle strength to 1
    # in the shader measured 84 %): 0.1 % leaves room for a few stray pixels, not for a fold.
    folds_at_rest = [row for row in rows if row["view"].startswith("standing") and row["build"] == "after" and
                     (row["fold_coverage"] or 0.0) > STANDING_FOLD_SHARE]
    for row in folds_at_rest:
        print("relief_distance: folds on the standing human, where nothing is compressed: %.1f %% of the garment "
              "pixels (%s)" % (100.0 * row["fold_coverage"], row["view"]), file=sys.stderr)
    return 1 if folds_at_rest else 0


if __name__ == "__main__":
    sys.exit(main())
