#!/usr/bin/python3
"""Figures of docs/stability.md (issue #8: stability where methods fail).

Runs the C++ tool `stability_cases` (src/tools/stability_cases.cpp) into a temporary directory,
or reads its CSVs from --csv-dir, and writes docs/stability/*.png:

  buckling_domain.png   h1 (and w, h2) of a Y pattern across alpha_min under each policy
  fk_gimbal.png         bone end through x = +-90 degrees; a rotation path through gimbal lock
                        split into y, x, z: the split jumps, the reconstruction error does not
  fk_wrap.png           bone end across the +-pi seam; FK error against 2 pi k added turns
  skirt_map.png         A_i, A_j (corrected and printed) around c_k, and the skirt's hem height
  period.png            autocorrelation of periodic vs non-periodic input, with the verdict
  corner_normals.png    normal angle to the degenerate corner's normal vs distance t
  relief_degenerate.png Voronoi relief with co-circular, nearly coincident, collinear seeds

    /usr/bin/python3 scripts/make_stability_figures.py --tool build_stability/stability_cases
    /usr/bin/python3 scripts/make_stability_figures.py --csv-dir /tmp/stability_csv
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))



def finish(fig, axes, out, name):
    """Grid on every axes, tight layout, PNG into `out`."""
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=110)
    plt.close(fig)

def read(directory, name):
    with open(os.path.join(directory, name)) as handle:
        rows = list(csv.reader(handle))
    return rows[0], rows[1:]


def numeric(rows, columns):
    return np.array([[float(row[c]) for c in columns] for row in rows])


def buckling(directory, out):
    _, rows = read(directory, "buckling_domain.csv")
    data = numeric(rows, range(7))
    alpha_min = data[0, 1]
    names = ["clampToDomainEdge", "fallBackToIPattern", "throwError"]
    styles = [("tab:blue", "-", 3.0), ("tab:orange", "--", 2.0), ("tab:green", ":", 2.5)]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for p, name in enumerate(names):
        d = data[data[:, 2] == p]
        color, style, width = styles[p]
        axes[0].plot(d[:, 0], d[:, 3], style, color=color, lw=width, label=name)
        axes[1].plot(d[:, 0], d[:, 5], style, color=color, lw=width, label=name)
    for ax in axes:
        ax.axvline(alpha_min, color="grey", lw=1)
        ax.axvspan(0, alpha_min, color="grey", alpha=0.12)
        ax.set_xlabel("alpha (1 = uncompressed)")
        ax.grid(alpha=0.3)
    axes[0].text(alpha_min / 2, 0.05, "beyond the domain\nh1 > L_x", ha="center", fontsize=9)
    axes[0].set_ylabel("h1 (ridge rise), L_y = 1")
    axes[0].set_title("Y pattern, L_x = 0.5, L_y = 1: h1 across alpha_min = %.3f" % alpha_min)
    axes[0].legend(loc="upper right", fontsize=9)
    axes[1].set_ylabel("h2 (split point sink)")
    axes[1].set_title("h2 reaches 0 at the edge (P5 under P7)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "buckling_domain.png"), dpi=110)
    plt.close(fig)


def gimbal(directory, out):
    _, rows = read(directory, "fk_gimbal.csv")
    data = numeric(rows, range(10))
    sweep = data[data[:, 0] == 0]
    path = data[data[:, 0] == 1]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    deg = np.degrees(sweep[:, 2])
    for k, name in zip(range(3, 6), "xyz"):
        axes[0].plot(deg, sweep[:, k], label="end " + name)
    for x in (-90, 90):
        axes[0].axvline(x, color="grey", lw=1, ls="--")
    axes[0].set_xlabel("x DOF of l_shoulder (deg), y = 0.4, z = -0.7 rad")
    axes[0].set_ylabel("bone end (m, body frame)")
    axes[0].set_title("FK through gimbal poses: smooth")
    axes[0].legend(fontsize=9)
    xdeg = np.degrees(path[:, 2])
    for k, name in zip(range(6, 9), ["y", "x", "z"]):
        axes[1].plot(xdeg, np.degrees(path[:, k]), label="split " + name)
    axes[1].axvline(90, color="grey", lw=1, ls="--")
    axes[1].set_xlabel("true x of the rotation (deg)")
    axes[1].set_ylabel("decomposeYxz angles (deg)")
    axes[1].set_title("Euler split through 90 deg: angles jump")
    axes[1].legend(fontsize=9)
    axes[2].semilogy(xdeg, np.maximum(path[:, 9], 1e-17))
    axes[2].axvline(90, color="grey", lw=1, ls="--")
    axes[2].set_xlabel("true x of the rotation (deg)")
    axes[2].set_ylabel("|Ry Rx Rz(split) - R|")
    axes[2].set_title("...but they compose back to R")
    finish(fig, axes, out, "fk_gimbal.png")


def wrap(directory, out):
    _, rows = read(directory, "fk_wrap.csv")
    data = numeric(rows, range(6))
    seam = data[data[:, 0] == 0]
    turns = data[data[:, 0] == 1]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    index = np.arange(len(seam))
    ax2 = axes[0].twinx()
    ax2.plot(index, np.degrees(seam[:, 1]), color="grey", lw=1, label="stored angle (deg)")
    ax2.set_ylabel("stored knee y angle (deg), wraps at +-180", color="grey")
    axes[0].plot(index, seam[:, 2], label="end x")
    axes[0].plot(index, seam[:, 4], label="end z")
    axes[0].set_xlabel("sample (true angle 180 - 29 ... 180 + 29 deg)")
    axes[0].set_ylabel("l_knee bone end (m)")
    axes[0].set_title("FK across the +-pi seam: no jump")
    axes[0].legend(loc="upper left", fontsize=9)
    eps = np.finfo(float).eps
    axes[1].loglog(turns[:, 1], np.maximum(turns[:, 5], 1e-18), "o-", label="max bone position error")
    axes[1].loglog(turns[:, 1], 2 * np.pi * turns[:, 1] * eps, "--", color="grey", label="eps |angle| (rounding of the angle)")
    axes[1].set_xlabel("2 pi k added to every angle, k")
    axes[1].set_ylabel("error (m)")
    axes[1].set_title("Large multiples of 2 pi: error = rounding of the angle")
    axes[1].legend(fontsize=9)
    for ax in axes:
        ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fk_wrap.png"), dpi=110)
    plt.close(fig)


def skirt(directory, out):
    _, rows = read(directory, "skirt_map.csv")
    data = numeric(rows, range(6))
    ck = data[0, 1]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    axes[0].plot(data[:, 0], data[:, 2], lw=2.5, label="A_i")
    axes[0].plot(data[:, 0], data[:, 3], lw=2.5, label="A_j (corrected)")
    printed = np.where(data[:, 0] >= ck, data[:, 4], np.nan)
    axes[0].plot(data[:, 0], printed, "--", color="tab:red", label="A_j as printed (jumps at c_k)")
    axes[0].axvline(ck, color="grey", lw=1)
    axes[0].text(ck, -0.18, "c_k = %.3f" % ck, ha="center", fontsize=9)
    axes[0].set_xlabel("normalized skirt length c")
    axes[0].set_ylabel("weight")
    axes[0].set_ylim(-0.25, 1.1)
    axes[0].set_title("Skirt length map (default body)")
    axes[0].legend(fontsize=9, loc="upper left")
    axes[1].plot(data[:, 0], data[:, 5], lw=2)
    axes[1].axvline(ck, color="grey", lw=1)
    axes[1].set_xlabel("normalized skirt length c")
    axes[1].set_ylabel("lowest skirt control point z (m), standing")
    axes[1].set_title("Hem height: monotone, continuous at c_k")
    finish(fig, axes, out, "skirt_map.png")


def period(directory, out):
    _, rows = read(directory, "period.csv")
    fig, ax = plt.subplots(figsize=(9, 4.6))
    signals = {}
    for row in rows:
        signals.setdefault(int(float(row[0])), []).append(row)
    for k, rs in sorted(signals.items()):
        lag = np.array([float(r[1]) for r in rs])
        r = np.array([float(r[2]) for r in rs])
        found = float(rs[0][3])
        verdict = rs[0][5] if np.isnan(found) else "period %.3f s" % found
        ax.plot(lag, r, lw=2 if k == 0 else 1.3, label="%s: %s" % (rs[0][4], verdict))
    ax.axhline(0.6, color="grey", ls="--", lw=1)
    ax.text(2.95, 0.62, "min_correlation 0.6", ha="right", fontsize=9, color="grey")
    ax.axvline(0.3, color="grey", ls=":", lw=1)
    ax.set_xlabel("lag (s)")
    ax.set_ylabel("pooled normalised autocorrelation r")
    ax.set_title("Gait period detection: periodic vs non-periodic input (6 s records)")
    ax.legend(fontsize=9, loc="lower left")
    finish(fig, [ax], out, "period.png")


def corner(directory, out):
    _, rows = read(directory, "corner_normals.csv")
    data = numeric(rows, range(3))
    names = ["coincident corner points P00 = P10", "parallel corner tangents",
             "collapsed edge v = 0 (pole)", "two collapsed edges at the corner"]
    fig, ax = plt.subplots(figsize=(8, 4.6))
    for c, name in enumerate(names):
        d = data[data[:, 0] == c]
        ax.loglog(d[:, 1], np.maximum(d[:, 2], 1e-17), lw=2, label=name)
    t = np.logspace(-14, 0, 20)
    ax.loglog(t, t, ":", color="grey", label="slope 1")
    ax.set_xlabel("distance t from the corner along the diagonal (u = v = t)")
    ax.set_ylabel("angle between n(t, t) and the corner normal (rad)")
    ax.set_title("Normals converge to the limit normal at degenerate corners")
    ax.legend(fontsize=9)
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "corner_normals.png"), dpi=110)
    plt.close(fig)


def relief(directory, out):
    cases = [("cocircular", "no jitter: co-circular seeds"), ("max_jitter", "jitter 0.5: near-coincident seeds"),
             ("collinear", "stretch 10 at 90 deg, no jitter:\ncollinear seed rows"),
             ("one_column", "cell_size 1: one column per tile")]
    fig, axes = plt.subplots(1, 4, figsize=(16, 4.4))
    for ax, (name, title) in zip(axes, cases):
        with open(os.path.join(directory, "relief_%s.csv" % name)) as handle:
            heights = np.array([[float(v) for v in line.split(",")] for line in list(handle)[1:]])
        tiled = np.tile(heights, (2, 2))  # 2 x 2 tiles: seams would show as lines through the middle
        ax.imshow(tiled, cmap="gray", origin="lower", extent=(0, 2, 0, 2))
        ax.set_title(title, fontsize=10)
        ax.set_xticks([0, 1, 2])
        ax.set_yticks([0, 1, 2])
    fig.suptitle("Voronoi skin relief with degenerate seed sets (height maps, 2 x 2 tiles, reference path)")
    fig.tight_layout()
    fig.subplots_adjust(top=0.82, bottom=0.08)
    fig.savefig(os.path.join(out, "relief_degenerate.png"), dpi=100)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tool", help="path of the stability_cases executable")
    parser.add_argument("--csv-dir", help="read the CSVs from here instead of running the tool")
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "stability"))
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    with tempfile.TemporaryDirectory() as scratch:
        directory = args.csv_dir
        if directory is None:
            if args.tool is None:
                sys.exit("give --tool or --csv-dir")
            subprocess.run([args.tool, ROOT, scratch], check=True)
            directory = scratch
        for draw in (buckling, gimbal, wrap, skirt, period, corner, relief):
            draw(directory, args.out)
    print("wrote figures to", args.out)


if __name__ == "__main__":
    main()
