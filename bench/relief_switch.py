#!/usr/bin/python3
"""What 'Hide Unseen Relief' changes on screen: one dressed human, its walk frozen (speed_factor
0), seen from 2 to 32 m, drawn once with the property on (a relief whose features cover under 2
pixels is drawn with the plain material) and once off (the relief everywhere). Reports, per
distance, the mean and the 99th percentile of the absolute difference over the figure's pixels
(grey levels, 0-255), charts them against distance, and keeps the screenshot pairs and their
difference images: where the switch has happened, the difference is what the relief added there.

Usage: bench/relief_switch.py [--distances 2 3 4 6 8 12 16 24 32] [--chart docs/relief_switch.png]
       [--images docs/relief_switch] [--markdown docs/relief_switch.md]
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


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--distances", type=float, nargs="+", default=[2, 3, 4, 6, 8, 12, 16, 24, 32])
    parser.add_argument("--chart", default="")
    parser.add_argument("--images", default="")
    parser.add_argument("--markdown", default="")
    args = parser.parse_args()
    images = args.images or tempfile.mkdtemp()
    os.makedirs(images, exist_ok=True)
    env = ros_environment(11913)
    processes = [start(["roscore", "-p", "11913"], env)]
    rows = []
    try:
        time.sleep(4)
        processes.append(start_frozen_human(rs.ROOT, env, "/relief_switch"))
        for distance in args.distances:
            shots = {}
            for hide in ("true", "false"):
                path = os.path.join(images, "%gm_hide_%s.png" % (distance, hide))
                # Aimed at the human's body frame: the distance is to the human wherever the node put it.
                rs.harness("dressed_human/DressedHuman", 1, 3, ["--set", "Hide Unseen Relief=" + hide], path, env,
                           distance, target_frame="body_0")
                shots[hide] = numpy.asarray(Image.open(path).convert("RGB")).astype(numpy.float64)
            mask = figure_mask(shots["false"]) | figure_mask(shots["true"])
            difference = numpy.abs(shots["true"] - shots["false"]).max(axis=2)
            values = difference[mask]
            rows.append((distance, int(mask.sum()), float(values.mean()) if values.size else 0.0,
                         float(numpy.percentile(values, 99)) if values.size else 0.0))
            Image.fromarray(numpy.clip(difference * 8, 0, 255).astype(numpy.uint8)).save(
                os.path.join(images, "%gm_difference_x8.png" % distance))
            print(distance, rows[-1], file=sys.stderr)
    finally:
        for process in reversed(processes):
            stop(process)
    lines = ["| distance | figure pixels | mean difference | 99th percentile |", "|---|---|---|---|"]
    lines += ["| %g m | %d | %.2f | %.0f |" % row for row in rows]
    lines.append("")
    lines.append("Absolute difference (largest of R, G, B; grey levels 0-255) over the figure's pixels between "
                 "'Hide Unseen Relief' on and off, one human with its walk frozen, an orbit view of its body frame in a 1000 x "
                 "700 panel; `bench/relief_switch.py`.")
    if args.chart:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        figure, ax = plt.subplots(figsize=(7, 4))
        ax.plot([r[0] for r in rows], [r[2] for r in rows], "o-", label="mean over the figure")
        ax.plot([r[0] for r in rows], [r[3] for r in rows], "s--", label="99th percentile")
        ax.set_xscale("log")
        ax.set_xticks([r[0] for r in rows])
        ax.set_xticklabels(["%g" % r[0] for r in rows])
        ax.set_xlabel("camera distance (m)")
        ax.set_ylabel("|on - off| (grey levels)")
        ax.set_title("What 'Hide Unseen Relief' changes on screen (bench/relief_switch.py)")
        ax.grid(True, alpha=0.3)
        ax.legend()
        figure.tight_layout()
        figure.savefig(args.chart, dpi=100)
    report("\n".join(lines), args.markdown)


if __name__ == "__main__":
    main()
