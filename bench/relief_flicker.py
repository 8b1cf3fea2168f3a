#!/usr/bin/python3
"""Shimmer of the relief under sub-pixel motion (issue 21, part 4): one dressed human frozen at
phase 0.5 of the shipped walk (replayed, not standing), drawn twice from distances 0.2 % apart (the figure
moves by a fraction of a pixel, as between two frames of a slow walk). A well filtered relief
changes little between the two; an aliased one sparkles. Reports, per distance and condition,
the mean absolute difference between the two shots over the garments' pixels and over the skin's
(grey levels), with the relief as drawn by default ('Hide Unseen Relief' on: faded out and then
not drawn from 3 px per feature down), with it forced on (the maps' own mip levels, the
normals of the filtered relief), forced on with the GPU's mip levels instead (averaged encoded
normals, DRESSED_HUMAN_RELIEF_MIPMAPS=gpu), forced on without mipmaps (=0), and 'Relief: Flat'
(no relief: what the motion alone changes).

Then the walking figure: the same human shot at consecutive frames of its walk (phases one 30 fps
frame apart, the camera following its body frame) at --walking-distance, in the same conditions.
Its limbs move by pixels between frames, so every condition changes a lot; the relief's flicker
is what a condition changes beyond 'Relief: Flat' over the same pixels.

Usage: bench/relief_flicker.py [--distances 2 4 10] [--walking-distance 10] [--walking-frames 4]
       [--markdown docs/relief_flicker.md] [--images DIR]
Needs the package built in build/ and xvfb-run.
"""
import argparse
import os
import sys
import tempfile
import time

import numpy
from PIL import Image

import rviz_scaling as rs
from ros_processes import report, ros_environment, start, start_frozen_human, stop

sys.path.insert(0, os.path.join(rs.ROOT, "test", "ros"))
from on_screen import figure_mask  # noqa: E402

# (label, harness properties, extra environment)
CONDITIONS = [("default (faded, hidden when unseen)", [], {}),
              ("relief forced on", ["--set", "Hide Unseen Relief=false"], {}),
              ("relief forced on, the GPU's mipmaps", ["--set", "Hide Unseen Relief=false"], {"DRESSED_HUMAN_RELIEF_MIPMAPS": "gpu"}),
              ("relief forced on, no mipmaps", ["--set", "Hide Unseen Relief=false"], {"DRESSED_HUMAN_RELIEF_MIPMAPS": "0"}),
              ("no relief (Relief: Flat)", ["--set", "Relief=Flat"], {})]
SHIFT = 1.002  # the second shot's distance factor: about a third of a pixel at the figure's edge at 10 m
FROZEN_PHASE = 0.5  # of walk.yaml's cycle
WALK_PERIOD_S = 1.1065  # walk.yaml's period
FRAME_S = 1.0 / 30.0  # rviz's frame cap


def classes(image):
    """Garment and skin pixels of a shot, by colour (jacket blue, skirt red, skin tone)."""
    r, g, b = (image[:, :, k] for k in range(3))
    figure = figure_mask(image)
    jacket = figure & (b > r + 30)
    skirt = figure & (r - g > 90)
    skin = figure & (r > 80) & (r - b > 25) & (r - b < 110) & (r - g > 5) & (r - g < 60)
    return jacket | skirt, skin


def shoot(condition, distance, path, env):
    label, properties, extra_env = condition
    shot_env = dict(env, **extra_env)
    # Aimed at the human's body frame: the distance is to the human wherever the node put it.
    rs.harness("dressed_human/DressedHuman", 1, 3, properties, path, shot_env, distance, target_frame="body_0")
    return numpy.asarray(Image.open(path).convert("RGB")).astype(numpy.float64)


def changes(first, second):
    """Mean change over the garment pixels and over the skin pixels of both shots."""
    cloth_a, skin_a = classes(first)
    cloth_b, skin_b = classes(second)
    difference = numpy.abs(first - second).max(axis=2)
    cloth, skin = cloth_a & cloth_b, skin_a & skin_b
    return (int(cloth.sum()), float(difference[cloth].mean()) if cloth.any() else 0.0,
            int(skin.sum()), float(difference[skin].mean()) if skin.any() else 0.0)


def walking_rows(distance, frames, images, env):
    """Per condition: mean garment and skin change between consecutive walk frames, and the
    same beyond 'Relief: Flat' (the last condition)."""
    shots = {}
    for frame in range(frames):
        phase = FROZEN_PHASE + frame * FRAME_S / WALK_PERIOD_S
        human = start_frozen_human(rs.ROOT, env, "/relief_flicker", phase * 2.0 * numpy.pi)
        try:
            for index, condition in enumerate(CONDITIONS):
                path = os.path.join(images, "walking_%gm_condition%d_frame%d.png" % (distance, index, frame))
                shots[(index, frame)] = shoot(condition, distance, path, env)
        finally:
            stop(human)
    measured = {}
    for index in range(len(CONDITIONS)):
        pairs = [changes(shots[(index, frame)], shots[(index, frame + 1)]) for frame in range(frames - 1)]
        measured[index] = [sum(pair[k] for pair in pairs) / len(pairs) for k in range(4)]
    flat = measured[len(CONDITIONS) - 1]
    rows = []
    for index, condition in enumerate(CONDITIONS):
        cloth_pixels, cloth, skin_pixels, skin = measured[index]
        rows.append((distance, condition[0], cloth_pixels, cloth, cloth - flat[1], skin_pixels, skin, skin - flat[3]))
        print(rows[-1], file=sys.stderr)
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--distances", type=float, nargs="+", default=[2.0, 4.0, 10.0])
    parser.add_argument("--walking-distance", type=float, default=10.0)
    parser.add_argument("--walking-frames", type=int, default=4)
    parser.add_argument("--markdown", default="")
    parser.add_argument("--images", default="")
    args = parser.parse_args()
    images = args.images or tempfile.mkdtemp()
    os.makedirs(images, exist_ok=True)
    env = ros_environment(11917)
    processes = [start(["roscore", "-p", "11917"], env)]
    rows = []
    try:
        time.sleep(4)
        human = start_frozen_human(rs.ROOT, env, "/relief_flicker", FROZEN_PHASE * 2.0 * numpy.pi)
        try:
            for distance in args.distances:
                for index, condition in enumerate(CONDITIONS):
                    stem = os.path.join(images, "%gm_condition%d" % (distance, index))
                    near = shoot(condition, distance, stem + "_a.png", env)
                    far = shoot(condition, distance * SHIFT, stem + "_b.png", env)
                    rows.append((distance, condition[0]) + changes(near, far))
                    print(rows[-1], file=sys.stderr)
        finally:
            stop(human)
        walking = walking_rows(args.walking_distance, args.walking_frames, images, env) if args.walking_frames >= 2 else []
    finally:
        for process in reversed(processes):
            stop(process)
    lines = ["| distance | relief | garment pixels | garment change | skin pixels | skin change |", "|---|---|---|---|---|---|"]
    lines += ["| %g m | %s | %d | %.2f | %d | %.2f |" % row for row in rows]
    lines.append("")
    lines.append("Mean absolute difference (largest of R, G, B; grey levels 0-255) between two shots of one human "
                 "frozen at phase %g of walk.yaml, from camera distances %.1f %% apart, over the pixels that are "
                 "garment (or skin) in both; an orbit view of its body frame in a 1000 x 700 panel, Mesa llvmpipe; "
                 "`bench/relief_flicker.py`." % (FROZEN_PHASE, (SHIFT - 1.0) * 100.0))
    if walking:
        lines += ["", "Walking figure, %d consecutive frames:" % args.walking_frames, "",
                  "| distance | relief | garment pixels | garment change | beyond flat | skin pixels | skin change | beyond flat |",
                  "|---|---|---|---|---|---|---|---|"]
        lines += ["| %g m | %s | %d | %.2f | %.2f | %d | %.2f | %.2f |" % row for row in walking]
        lines.append("")
        lines.append("The same human shot at %d phases of its walk one 30 fps frame (%.3f of the cycle) apart, "
                     "from phase %g, the camera following its body frame; mean change between consecutive frames "
                     "over the pixels that are garment (or skin) in both, and that change less the same measure "
                     "with 'Relief: Flat' (the relief's own flicker)." % (args.walking_frames, FRAME_S / WALK_PERIOD_S,
                                                                       FROZEN_PHASE))
    report("\n".join(lines), args.markdown)


if __name__ == "__main__":
    main()
