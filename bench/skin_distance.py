#!/usr/bin/python3
"""How the skin relief reads with distance (issue 21, part 5): one dressed human frozen at phase
0.5 of the shipped walk, seen from its body frame at 1 to 8 m, drawn with the default relief and
with 'Relief: Flat'. Per distance: the mean absolute difference between the two over the pixels
that are skin in both (grey levels; what the relief adds to the skin), and the same over the
garments. Charts both against distance, and puts the two shots of the nearest distance side by
side, cropped to its skin, in a figure.

Usage: bench/skin_distance.py [--distances 1 1.5 2 3 4 6 8] [--chart docs/relief/skin_distance.png]
       [--closeup docs/relief/skin_closeup.png] [--markdown docs/skin_distance.md] [--images DIR]
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
from relief_flicker import FROZEN_PHASE, classes
from ros_processes import report, ros_environment, start, start_frozen_human, stop


def shoot(properties, distance, path, env):
    rs.harness("dressed_human/DressedHuman", 1, 3, properties, path, env, distance, target_frame="body_0")
    return numpy.asarray(Image.open(path).convert("RGB")).astype(numpy.float64)


def closeup(relief, flat, skin, path):
    """The two shots side by side, cropped to a margin around the skin pixels."""
    rows, columns = numpy.nonzero(skin)
    top, bottom = max(rows.min() - 20, 0), min(rows.max() + 20, skin.shape[0])
    left, right = max(columns.min() - 20, 0), min(columns.max() + 20, skin.shape[1])
    crops = [Image.fromarray(shot[top:bottom, left:right].astype(numpy.uint8)) for shot in (relief, flat)]
    width, height = crops[0].size
    joined = Image.new("RGB", (2 * width + 10, height), (255, 255, 255))
    joined.paste(crops[0], (0, 0))
    joined.paste(crops[1], (width + 10, 0))
    joined.save(path)


def chart(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axis = plt.subplots(figsize=(6.5, 4))
    distances = [row[0] for row in rows]
    axis.plot(distances, [row[2] for row in rows], "o-", label="skin")
    axis.plot(distances, [row[4] for row in rows], "s-", label="garments")
    axis.set_xlabel("camera distance to the body frame (m)")
    axis.set_ylabel("mean |relief - flat| (grey levels)")
    axis.set_title("What the relief adds to the picture, by distance")
    axis.set_ylim(bottom=0)
    axis.grid(alpha=0.3)
    axis.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=100)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--distances", type=float, nargs="+", default=[1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0])
    parser.add_argument("--chart", default="")
    parser.add_argument("--closeup", default="")
    parser.add_argument("--markdown", default="")
    parser.add_argument("--images", default="")
    args = parser.parse_args()
    images = args.images or tempfile.mkdtemp()
    os.makedirs(images, exist_ok=True)
    env = ros_environment(11919)
    processes = [start(["roscore", "-p", "11919"], env)]
    rows = []
    try:
        time.sleep(4)
        processes.append(start_frozen_human(rs.ROOT, env, "/skin_distance", FROZEN_PHASE * 2.0 * numpy.pi))
        for distance in args.distances:
            relief = shoot([], distance, os.path.join(images, "%gm_relief.png" % distance), env)
            flat = shoot(["--set", "Relief=Flat"], distance, os.path.join(images, "%gm_flat.png" % distance), env)
            cloth_a, skin_a = classes(relief)
            cloth_b, skin_b = classes(flat)
            skin, cloth = skin_a & skin_b, cloth_a & cloth_b
            if not skin.any() or not cloth.any():
                raise RuntimeError("no skin or no garment pixels at %g m (see %s)" % (distance, images))
            difference = numpy.abs(relief - flat).max(axis=2)
            rows.append((distance, int(skin.sum()), float(difference[skin].mean()), int(cloth.sum()),
                         float(difference[cloth].mean())))
            print(rows[-1], file=sys.stderr)
            if args.closeup and distance == args.distances[0]:
                closeup(relief, flat, skin, args.closeup)
    finally:
        for process in reversed(processes):
            stop(process)
    if args.chart:
        chart(rows, args.chart)
    lines = ["| distance | skin pixels | skin: relief - flat | garment pixels | garments: relief - flat |",
             "|---|---|---|---|---|"]
    lines += ["| %g m | %d | %.2f | %d | %.2f |" % row for row in rows]
    lines.append("")
    lines.append("Mean absolute difference (largest of R, G, B; grey levels 0-255) between the default relief and "
                 "'Relief: Flat', over the pixels that are skin (or garment) in both; one human frozen at phase %g "
                 "of walk.yaml, an orbit view of its body frame in a 1000 x 700 panel, Mesa llvmpipe; "
                 "`bench/skin_distance.py`." % FROZEN_PHASE)
    report("\n".join(lines), args.markdown)


if __name__ == "__main__":
    main()
