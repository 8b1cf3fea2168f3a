#!/usr/bin/python3
"""Bump mapping against displaced geometry (and flat shading), near and far: the image each mode
draws compared with displaced geometry's (the reference bump mapping approximates), against
what each mode costs the display per frame. One frozen walking human (jacket + skirt) in rviz,
bench/rviz_display_scaling.cpp as the rviz side; each point the median of --repeats runs.

Usage: bench/relief_modes.py [--seconds 5] [--repeats 3] [--distances 2 8] [--csv out.csv]
       [--images docs/relief_modes] [--markdown docs/relief_modes.md]
Needs the package built in build/ and xvfb-run.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

import numpy
from PIL import Image

from ros_processes import report, ros_environment, start, start_frozen_human, stop

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEVEL = os.path.join(ROOT, "build", "devel")
MODES = ["Displaced geometry", "Bump mapping", "Flat"]
BACKGROUND = numpy.array([48, 48, 48])  # rviz's default background


def harness(mode, distance, seconds, screenshot, env):
    command = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24", os.path.join(DEVEL, "env.sh"),
               os.path.join(DEVEL, "lib", "dressed_human", "rviz_display_scaling"), "dressed_human/DressedHuman",
               "1", str(seconds), "--set", "Relief=" + mode, "--set", "Skin Relief Strength=2",
               "--distance", str(distance), "--focal", "0;0;0", "--view", "Target Frame=body_0", "--view", "Pitch=0.15",
               "--screenshot", screenshot]
    output = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, timeout=seconds + 120).stdout
    match = re.search(r"fps=([\d.]+) cpu_percent=([\d.]+) cpu_ms_per_frame=([\d.]+) display_ms=([-\d.]+)", output)
    if not match or not os.path.exists(screenshot):
        raise RuntimeError("harness failed for %s at %g m:\n%s" % (mode, distance, output[-2000:]))
    if float(match.group(4)) < 0:
        raise RuntimeError("the display reported no 'Update' time for %s at %g m (fewer than 30 frames?); "
                           "use more --seconds" % (mode, distance))
    return float(match.group(4)), float(match.group(1))


def luminance(path):
    """Luminance, the human's pixels, and the garments' (blue jacket, red skirt) among them."""
    image = numpy.asarray(Image.open(path).convert("RGB")).astype(numpy.float64)
    r, g, b = image[:, :, 0], image[:, :, 1], image[:, :, 2]
    figure = numpy.abs(image - BACKGROUND).sum(axis=2) > 40
    garments = figure & ((b > 1.2 * r) | ((r > 1.5 * g) & (r > 1.2 * b)))
    return image @ numpy.array([0.299, 0.587, 0.114]), figure, garments


def difference(path, reference):
    """RMS luminance difference (0-255) where either image shows the human, and where either
    shows a garment: the skin's cells are finer than displaced geometry's mesh resolves, the
    wrinkles are not."""
    a, figure_a, garments_a = luminance(path)
    b, figure_b, garments_b = luminance(reference)
    squared = (a - b) ** 2
    figure, garments = figure_a | figure_b, garments_a | garments_b
    return float(numpy.sqrt(squared[figure].mean())), float(numpy.sqrt(squared[garments].mean())), int(figure.sum())


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seconds", type=float, default=10.0)  # displaced geometry draws about 5 fps: 30 frames and more
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--distances", type=float, nargs="+", default=[3.0, 10.0])
    parser.add_argument("--csv", default="")
    parser.add_argument("--images", default="")
    parser.add_argument("--markdown", default="")
    args = parser.parse_args()

    images = args.images or tempfile.mkdtemp()
    os.makedirs(images, exist_ok=True)
    env = ros_environment(11913)
    processes = [start(["roscore", "-p", "11913"], env)]
    results = {}
    try:
        time.sleep(4)
        processes.append(start_frozen_human(ROOT, env, "/relief_modes"))
        for distance in args.distances:
            for mode in MODES:
                costs = []
                for repeat in range(args.repeats):
                    path = os.path.join(images, "%s_%gm.png" % (mode.split()[0].lower(), distance))
                    costs.append(harness(mode, distance, args.seconds, path, env)[0])
                    # The camera follows the frozen human: a point that did not draw it, when its
                    # measurement started or ended, measured nothing.
                    for shot in (path[:-4] + "_start.png", path):
                        if luminance(shot)[1].sum() < 1000:
                            raise RuntimeError("%s at %g m: the human is not drawn in %s" % (mode, distance, shot))
                    print(mode, distance, costs[-1], file=sys.stderr)
                results[(mode, distance)] = (statistics.median(costs), costs)
    finally:
        for process in reversed(processes):
            stop(process)

    rows = ["mode,distance_m,display_ms_median,display_ms_runs,rms_difference_to_displaced,"
            "rms_difference_to_displaced_garments,figure_pixels"]
    lines = ["| distance | relief mode | display CPU per frame (median) | vs bump mapping | "
             "RMS luminance difference to displaced geometry: whole figure | garments only |",
             "|---|---|---|---|---|---|"]
    for distance in args.distances:
        reference = os.path.join(images, "displaced_%gm.png" % distance)
        bump_cost = results[("Bump mapping", distance)][0]
        for mode in MODES:
            path = os.path.join(images, "%s_%gm.png" % (mode.split()[0].lower(), distance))
            rms, rms_garments, pixels = difference(path, reference)
            cost, runs = results[(mode, distance)]
            rows.append("%s,%g,%.4f,%s,%.3f,%.3f,%d" % (mode, distance, cost, " ".join("%.4f" % c for c in runs), rms,
                                                       rms_garments, pixels))
            lines.append("| %g m | %s | %.3f ms | %.1f x | %.2f | %.2f |" % (distance, mode, cost, cost / bump_cost, rms,
                                                                          rms_garments))
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("\n".join(rows) + "\n")
    lines.append("")
    lines.append("%d runs of %g s per point (median), one frozen human, Mesa llvmpipe on %d cores; "
                 "`bench/relief_modes.py`." % (args.repeats, args.seconds, os.cpu_count()))
    report("\n".join(lines), args.markdown)


if __name__ == "__main__":
    main()
