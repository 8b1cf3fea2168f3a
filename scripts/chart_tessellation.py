#!/usr/bin/python3
"""Speed-vs-accuracy chart of uniform vs adaptive Bezier tessellation.

Surfaces: two synthetic test sets (capsule, body) and the real skin (config/bodies/default.yaml)
posed in the walk.

Runs the C++ tool `tessellation_accuracy` (or reads its CSV), writes the CSV next to the chart and
plots max geometric error (mm) against triangle count and against per-frame tessellation time.
Also prints, for every adaptive point, how many times more triangles uniform tessellation needs
for the same error (log-log interpolation along the uniform curve).

    /usr/bin/python3 scripts/chart_tessellation.py --tool build_skin/tessellation_accuracy
    /usr/bin/python3 scripts/chart_tessellation.py --csv docs/tessellation_accuracy.csv
"""
import argparse
import csv
import io
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def load(args):
    if args.csv:
        with open(args.csv) as f:
            text = f.read()
    else:
        text = subprocess.run([args.tool, ROOT], check=True, capture_output=True, text=True).stdout
        docs = os.environ.get("DRESSED_HUMAN_DOCS", os.path.join(ROOT, "docs"))  # evaluate.sh: its run's folder
        with open(os.path.join(docs, "tessellation_accuracy.csv"), "w") as f:
            f.write(text)
    rows = list(csv.DictReader(io.StringIO(text)))
    if not rows:
        sys.exit("no data rows in the CSV")
    for r in rows:
        for key in ("parameter", "triangles", "vertices", "max_error_mm", "max_parametric_error_mm",
                    "tessellate_us", "layout_build_us"):
            r[key] = float(r[key])
    return rows


def series(rows, surface, method):
    picked = sorted((r for r in rows if r["surface"] == surface and r["method"] == method),
                    key=lambda r: r["triangles"])
    return (np.array([r["triangles"] for r in picked]), np.array([r["max_error_mm"] for r in picked]),
            np.array([r["tessellate_us"] for r in picked]))


def uniform_triangles_at(error, uniform_triangles, uniform_errors):
    """Triangles uniform tessellation needs for `error`, interpolated in log-log; None outside."""
    order = np.argsort(uniform_errors)
    e, t = np.log(uniform_errors[order]), np.log(uniform_triangles[order])
    if not (e[0] <= np.log(error) <= e[-1]):
        return None
    return float(np.exp(np.interp(np.log(error), e, t)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tool", default=os.path.join(ROOT, "build_skin", "tessellation_accuracy"))
    parser.add_argument("--csv", help="read this CSV instead of running the tool")
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "tessellation_speed_vs_accuracy.png"))
    args = parser.parse_args()
    rows = load(args)

    surfaces = list(dict.fromkeys(r["surface"] for r in rows))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    figure, (by_triangles, by_time) = plt.subplots(1, 2, figsize=(13, 5.5))
    summary = []
    for index, surface in enumerate(surfaces):
        colour = colours[index % len(colours)]
        ut, ue, us = series(rows, surface, "uniform")
        at, ae, as_ = series(rows, surface, "adaptive")
        by_triangles.loglog(ut, ue, "o-", color=colour, label=f"{surface}: uniform n x n")
        by_triangles.loglog(at, ae, "s--", color=colour, label=f"{surface}: adaptive (error bound)")
        by_time.loglog(us, ue, "o-", color=colour, label=f"{surface}: uniform")
        by_time.loglog(as_, ae, "s--", color=colour, label=f"{surface}: adaptive")
        ratios = []
        for triangles, error in zip(at, ae):
            needed = uniform_triangles_at(error, ut, ue)
            if needed is not None:
                ratios.append((error, needed / triangles))
        for error, ratio in ratios:
            print(f"{surface}: error {error:8.4f} mm  uniform needs {ratio:4.2f}x the triangles of adaptive")
        if ratios:
            values = np.array([r for _, r in ratios])
            summary.append(f"{surface}: uniform/adaptive triangles at equal error "
                           f"{values.min():.1f}-{values.max():.1f}x (median {np.median(values):.1f}x)")
    for axes in (by_triangles, by_time):
        axes.set_ylabel("max geometric error (mm)")
        axes.grid(True, which="both", alpha=0.3)
        axes.legend(fontsize=8)
    by_triangles.set_xlabel("triangles")
    by_time.set_xlabel("tessellation time per frame (us, layout reused, 1 core)")
    by_triangles.set_title("error vs triangles")
    by_time.set_title("error vs time")
    figure.suptitle("Bicubic Bezier tessellation, uniform vs adaptive\n" + "\n".join(summary), fontsize=10)
    figure.text(0.01, 0.01,
                "Why the ratio differs: adaptive saves where patches differ (body: torso, arm and finger "
                "patches span 20x in size). On the capsule every patch needs nearly the same level (~1.7x). "
                "On the real skin (188 patches, walk pose) most triangles lie on the large\ntrunk and thigh "
                "quarter-cylinders, which all need about the same level, so adaptive saves only ~1.6x there: "
                "the >= 3x goal is met on the body test set, not on the skin. The error bound behind the "
                "adaptive levels is 1.0-2x the\nmeasured error. Times: best of 5 rounds on a shared 2-core "
                "machine under load from other builds; expect noise.",
                fontsize=8, va="bottom")
    figure.tight_layout(rect=(0, 0.08, 1, 1))
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    figure.savefig(args.out, dpi=110)
    print("\n".join(summary))
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
