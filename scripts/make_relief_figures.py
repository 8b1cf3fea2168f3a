#!/usr/bin/python3
"""Regenerate docs/relief/: run the relief_images tool, then assemble the figure panels.

Usage: scripts/make_relief_figures.py [build_dir]   (default: build_relief next to this repo's root)
The tool writes raw PNGs/CSVs into <build_dir>/relief_raw/; this script composes into docs/relief/
  fig6_buckling_solution.png      h1, w, h2, h1+h2 and the bend vs alpha (seed Fig. 6, Lx = Ly = 1)
  fig8_wrinkles_vs_compression.png  X / Y-Y / I wrinkles for alpha 1 .. 0.6: exact, 8 Gaussians, smooth
  wrinkle_growth.png              one map, compression growing row by row
  gaussian_rms_vs_terms.png       RMS error of the Gaussian approximation vs number of Gaussians
  smooth_fold_rms_vs_harmonics.png  RMS error of the smooth folds (the exact tile blurred) against
                                  harmonics per cell and against the time to make a map
  fig11_slope.png ... fig17_direction.png, fig18_skin.png   skin parameter sweeps (paper 004)
  skin_tiling_2x2.png             the shaded skin tile repeated 2 x 2 (seams would show here)
  skin_mip_levels.png             normal map mip chain
  wrinkle_placement_walk.png      wrinkle placement over a walk (wrinkle_placement_walk tool): alpha
                                  behind the knee / inside the elbow / at the waist, pattern, h1
  fold_strength_vs_flexion.png    the fold strength the renderer shows behind the knee and inside
                                  the elbow against their bend over a walk cycle (same tool)
  fold_closeups.png               folds inside the elbow and behind the knee, bent and straight:
                                  exact folds as displaced geometry, the bump-mapped smooth folds
                                  drawn now, and what was drawn before issue 21 (fold_closeups tool)
Only the placement figures: scripts/make_relief_figures.py <build_dir> wrinkle_placement
Only the close-ups:         scripts/make_relief_figures.py <build_dir> fold_closeups
"""
import csv
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build_relief")
OUT = os.path.join(os.environ.get("DRESSED_HUMAN_DOCS", os.path.join(ROOT, "docs")), "relief")  # evaluate.sh: its run's folder
# Raw tool output (uncompressed PNGs, ~13 MB) stays in the build tree; only panels go to docs/.
RAW = os.path.join(BUILD, "relief_raw")


def grid(names, titles, path, columns, suptitle, cell=2.6):
    rows = (len(names) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(cell * columns, cell * rows + 0.5), squeeze=False)
    for axis in axes.flat:
        axis.axis("off")
    for axis, name, title in zip(axes.flat, names, titles):
        image = mpimg.imread(os.path.join(RAW, name + ".png"))
        axis.imshow(image, cmap="gray", vmin=0, vmax=1, interpolation="nearest")
        axis.set_title(title, fontsize=9)
    fig.suptitle(suptitle, fontsize=11)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, path), dpi=110)
    plt.close(fig)


def read_csv(name):
    with open(os.path.join(RAW, name)) as handle:
        return list(csv.DictReader(handle))


def main():
    os.makedirs(RAW, exist_ok=True)
    tool = os.path.join(BUILD, "relief_images")
    if not os.path.exists(tool):
        sys.exit(f"{tool} not found: build first (cmake --build {BUILD} --target relief_images)")
    subprocess.run([tool, RAW], check=True)

    rows = read_csv("buckling_solution.csv")
    alpha = np.array([float(r["alpha"]) for r in rows])
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for key, label in [("h1", "h1"), ("w", "w"), ("h2", "h2"), ("thickness", "h1 + h2")]:
        left.plot(alpha, [float(r[key]) for r in rows], label=label)
    left.set_xlabel("alpha (1 = uncompressed)")
    left.set_title("Eq. 9-10 solved, L_x = L_y = 1")
    left.invert_xaxis()
    left.legend()
    right.plot(alpha, [float(r["bend_angle_deg"]) for r in rows])
    right.set_xlabel("alpha")
    right.set_ylabel("bend 2 atan(w/h2) [deg]")
    right.invert_xaxis()
    right.set_title("bend between chained Y/X base planes")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "fig6_buckling_solution.png"), dpi=110)
    plt.close(fig)

    alphas = ["100", "095", "090", "080", "070", "060"]
    names, titles = [], []
    for chain, label in [("X", "X-X"), ("X_gauss8", "X-X, 8 Gaussians"), ("X_smooth", "X-X, smooth"), ("YY", "Y-Y"),
                         ("YY_gauss8", "Y-Y, 8 Gaussians"), ("YY_smooth", "Y-Y, smooth"), ("I", "I"), ("I_smooth", "I, smooth")]:
        for a in alphas:
            names.append(f"wrinkle_{chain}_alpha{a}")
            titles.append(f"{label}  alpha={int(a) / 100:.2f}")
    grid(names, titles, "fig8_wrinkles_vs_compression.png", len(alphas),
         "Buckling wrinkles growing with compression (Lambert, Eq. 12)", cell=2.2)
    grid(["wrinkle_growth_exact", "wrinkle_growth_gauss8", "wrinkle_growth_smooth"],
         ["exact folds", "8 Gaussians",
          "smooth (%s harmonics per cell)" % read_csv("smooth_fold_error.csv")[0]["default_harmonics_per_cell"]], "wrinkle_growth.png", 3,
         "alpha per row: 1.0, 0.97, 0.92, 0.85, 0.75, 0.6 (top to bottom)", cell=4.0)

    errors = read_csv("gaussian_error.csv")
    fig, axis = plt.subplots(figsize=(6.5, 4.5))
    for pattern in ["I", "Y", "X"]:
        for a, style in [("0.8", "--"), ("0.6", "-")]:
            picked = [r for r in errors if r["pattern"] == pattern and r["alpha"] == a]
            axis.plot([int(r["terms"]) for r in picked], [float(r["rms_error"]) / float(r["max_height"]) for r in picked],
                      style, marker="o", label=f"{pattern}, alpha={a}")
    axis.set_xscale("log", base=2)
    axis.set_yscale("log")
    axis.set_xlabel("number of Gaussians K")
    axis.set_ylabel("RMS error / h1")
    axis.set_title("Gaussian approximation vs exact fold surface")
    axis.grid(True, which="both", alpha=0.3)
    axis.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "gaussian_rms_vs_terms.png"), dpi=110)
    plt.close(fig)
    smooth_fold_figure()

    sweeps = [
        ("fig11_slope.png", "Cross-section slope (paper 004 Fig. 11)",
         ["skin_slope_0.8", "skin_slope_3", "skin_slope_12", "skin_slope_late"],
         ["edge slope 0.8", "edge slope 3", "edge slope 12", "late rise, sharp crest"]),
        ("fig13_roundness.png", "Roundness (Figs. 12-13)",
         ["skin_roundness_000", "skin_roundness_040", "skin_roundness_100"], ["roundness 0", "0.4", "1"]),
        ("fig14_jitter.png", "Seed jitter on the triangular lattice (Fig. 14)",
         ["skin_jitter_000", "skin_jitter_020", "skin_jitter_045"], ["jitter 0", "0.2", "0.45"]),
        ("fig15_wobble.png", "Midpoint-displacement wobble (Fig. 15)",
         ["skin_wobble_000", "skin_wobble_012", "skin_wobble_025"], ["wobble 0", "0.12", "0.25"]),
        ("fig16_levels.png", "Hierarchy levels (Fig. 16)",
         ["skin_levels_1", "skin_levels_2", "skin_levels_3"], ["1 level", "2 levels", "3 levels"]),
        ("fig17_direction.png", "Directionality, stretch 2.5 (Fig. 17)",
         ["skin_direction_none", "skin_direction_horizontal", "skin_direction_vertical"], ["none", "horizontal", "vertical"]),
        ("fig18_skin.png", "Combined skin (Fig. 18: a none, b vertical, c horizontal, f level 1 only)",
         ["skin_fig18_a", "skin_fig18_b", "skin_fig18_c", "skin_fig18_f"], ["(a)", "(b)", "(c)", "(f)"]),
    ]
    for path, title, names, labels in sweeps:
        grid(names, labels, path, len(names), title, cell=3.2)

    tile = mpimg.imread(os.path.join(RAW, "skin_shaded_mip0.png"))
    fig, axis = plt.subplots(figsize=(8, 8))
    axis.imshow(np.tile(tile, (2, 2)), cmap="gray", vmin=0, vmax=1, interpolation="nearest")
    axis.axis("off")
    axis.set_title("512x512 skin tile repeated 2x2: no seams")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "skin_tiling_2x2.png"), dpi=110)
    plt.close(fig)

    mips = sorted(n[:-4] for n in os.listdir(RAW) if n.startswith("skin_normal_mip"))
    grid(mips, [m.replace("skin_normal_", "") for m in mips], "skin_mip_levels.png", len(mips),
         "Tangent-space normal map mip chain (gradient box filter)", cell=2.4)
    wrinkle_placement_figure()
    fold_closeups_figure()
    print("figures in", OUT)


def smooth_fold_figure():
    """RMS error of the smooth folds over h1 against harmonics per cell and against ms per map."""
    errors = read_csv("smooth_fold_error.csv")
    fig, (by_harmonics, by_time) = plt.subplots(1, 2, figsize=(11, 4.5))
    for pattern in ["I", "Y", "X"]:
        for a, style in [("0.8", "--"), ("0.6", "-")]:
            picked = [r for r in errors if r["pattern"] == pattern and r["alpha"] == a]
            error = [float(r["rms_error"]) / float(r["h1"]) for r in picked]
            by_harmonics.plot([int(r["harmonics_per_cell"]) for r in picked], error, style, marker="o",
                              label=f"{pattern}, alpha={a}")
            by_time.plot([float(r["ms_per_map"]) for r in picked], error, style, marker="o", label=f"{pattern}, alpha={a}")
    for axis in (by_harmonics, by_time):
        axis.axhline(0.05, color="tab:red", lw=0.8, ls="--", label="goal: 5 % of h1")
        axis.set_yscale("log")
        axis.set_ylabel("RMS height error / h1")
        axis.grid(True, which="both", alpha=0.3)
    default = int(errors[0]["default_harmonics_per_cell"])
    by_harmonics.axvline(default, color="gray", lw=0.8, ls=":", label="default: %d" % default)
    by_harmonics.set_xlabel("harmonics kept per cell (across and along); blur 0.59 / that, in cells")
    by_harmonics.legend(fontsize=7)
    by_time.set_xlabel("ms to make a 256 x 256 map (exact tile + low pass), this machine")
    fig.suptitle("Smooth folds: the exact I / Y / X tile blurred through its own Fourier series (Gaussian, to 1/1000)")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "smooth_fold_rms_vs_harmonics.png"), dpi=110)
    plt.close(fig)


def wrinkle_placement_figure():
    """alpha per region over one walk cycle, the chosen pattern and amplitude h1, and the pose
    wrinkle tile behind the left knee at the least / middle / most compressed pose."""
    os.makedirs(RAW, exist_ok=True)
    tool = os.path.join(BUILD, "wrinkle_placement_walk")
    if not os.path.exists(tool):
        sys.exit(f"{tool} not found: build first (cmake --build {BUILD} --target wrinkle_placement_walk)")
    subprocess.run([tool, ROOT, RAW, "120"], check=True)
    fold_strength_figure()
    rows = read_csv("wrinkle_walk.csv")
    tiles = read_csv("wrinkle_walk_tiles.csv")
    phase = np.array([float(r["phase"]) for r in rows])
    fig = plt.figure(figsize=(12, 8.2))
    top = fig.add_axes([0.07, 0.56, 0.58, 0.38])
    middle = fig.add_axes([0.07, 0.09, 0.58, 0.38], sharex=top)
    bend_axis = top.twinx()
    series = [("pants_l_knee_back", "behind left knee (pants)", "C0"),
              ("pants_r_knee_back", "behind right knee (pants)", "C9"),
              ("jacket_l_elbow_inside", "inside left elbow (jacket)", "C3"),
              ("jacket_waist", "waist (jacket)", "C2"),
              ("pants_waist", "waist (pants)", "C8")]
    for key, label, colour in series:
        alpha = np.array([float(r[key + "_alpha"]) for r in rows])
        top.plot(phase, alpha, color=colour, label=label)
        h1 = np.array([float(r[key + "_h1_mm"]) for r in rows])
        chain = rows[int(np.argmin(alpha))][key + "_chain"]
        middle.plot(phase, h1, color=colour, label=f"{label}: {chain}")
    threshold = float(read_csv("wrinkle_walk_options.csv")[0]["alpha_threshold"])
    top.axhline(threshold, color="grey", linestyle=":", label=f"threshold {threshold:g} (no wrinkles above)")
    bend_axis.plot(phase, [float(r["l_knee_bend_deg"]) for r in rows], "--", color="C0", alpha=0.5)
    bend_axis.plot(phase, [float(r["l_elbow_bend_deg"]) for r in rows], "--", color="C3", alpha=0.5)
    bend_axis.set_ylabel("bend [deg] (dashed: left knee, left elbow)")
    top.set_ylabel("alpha (region's 10th percentile)")
    top.set_title("Compression on the posed garments, walk.yaml (knee, elbow: span length along the joint axis;\n"
                  "waist: smallest principal stretch vs rest)", fontsize=10)
    top.legend(fontsize=7, loc="lower left")
    top.grid(True, alpha=0.3)
    middle.set_xlabel("phase of the walk cycle")
    middle.set_ylabel("wrinkle amplitude h1 [mm]")
    middle.set_title(f"Amplitude h1(alpha / {threshold:g}) of the region's pattern (legend: chain at the lowest alpha)")
    middle.legend(fontsize=7, loc="upper left")
    middle.grid(True, alpha=0.3)
    for index, tile in enumerate(tiles):
        axis = fig.add_axes([0.72, 0.69 - 0.315 * index, 0.24, 0.24])
        axis.imshow(mpimg.imread(os.path.join(RAW, f"wrinkle_walk_tile_{tile['name']}.png")), cmap="gray", vmin=0, vmax=1)
        axis.set_xticks([])
        axis.set_yticks([])
        axis.set_xlabel("u (down the leg) ->", fontsize=7)
        axis.set_ylabel("v (around)", fontsize=7)
        axis.set_title(f"pose map behind left knee, phase {int(tile['pose']) / len(rows):.2f}\n"
                       f"alpha {float(tile['alpha']):.3f}, {tile['chain']}, max height {float(tile['max_height_mm']):.1f} mm",
                       fontsize=8)
        top.axvline(int(tile["pose"]) / len(rows), color="k", alpha=0.25)
    fig.savefig(os.path.join(OUT, "wrinkle_placement_walk.png"), dpi=110)
    plt.close(fig)
    print("wrote", os.path.join(OUT, "wrinkle_placement_walk.png"))


def fold_strength_figure():
    """The shown fold strength (fraction of the fold tile's height drawn) behind the left knee and
    inside the left elbow against the joint's bend, over one walk cycle, and its largest change
    between two frames at rviz's 30 fps."""
    rows = read_csv("wrinkle_walk_strength.csv")
    time = np.array([float(r["time_s"]) for r in rows])
    period = time[1] * len(rows)
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.6))
    joints = [("pants_l_knee_back", "l_knee_bend_deg", "behind the left knee (pants)", "C0"),
              ("jacket_l_elbow_inside", "l_elbow_bend_deg", "inside the left elbow (jacket)", "C3")]
    for axis, (region, bend_key, label, colour) in zip(axes[:2], joints):
        bend = np.array([float(r[bend_key]) for r in rows] + [float(rows[0][bend_key])])
        mean = np.array([float(r[region + "_mean"]) for r in rows] + [float(rows[0][region + "_mean"])])
        largest = np.array([float(r[region + "_max"]) for r in rows] + [float(rows[0][region + "_max"])])
        per_frame = np.max(np.abs(np.diff(mean))) * (1.0 / 30.0) / (period / len(rows))
        axis.plot(bend, mean, "-", color=colour, label="mean over the region")
        axis.plot(bend, largest, "--", color=colour, alpha=0.6, label="largest in the region")
        axis.scatter(bend[:-1], mean[:-1], c=time, cmap="viridis", s=10, zorder=3)
        axis.set_xlabel("bend [deg] (angle between the two bones)")
        axis.set_ylabel("fold strength shown (0 smooth, 1 full fold)")
        axis.set_ylim(-0.03, 1.05)
        axis.set_title(f"{label}\nlargest change between frames at 30 fps: {per_frame:.3f}", fontsize=10)
        axis.grid(True, alpha=0.3)
        axis.legend(fontsize=8, loc="lower right")
    phase = np.array([float(r["phase"]) for r in rows])
    over_time = axes[2]
    bends = over_time.twinx()
    for region, bend_key, label, colour in joints:
        over_time.plot(phase, [float(r[region + "_mean"]) for r in rows], color=colour, label=label)
        bends.plot(phase, [float(r[bend_key]) for r in rows], "--", color=colour, alpha=0.5)
    over_time.set_xlabel("phase of the walk cycle (dots in the other panels: time, dark to light)")
    over_time.set_ylabel("fold strength shown (mean)")
    bends.set_ylabel("bend [deg] (dashed)")
    over_time.legend(fontsize=8, loc="upper left")
    over_time.grid(True, alpha=0.3)
    options = read_csv("wrinkle_walk_options.csv")[0]
    fig.suptitle("Folds grow with the bend and fade as the joint straightens: walk.yaml, per-vertex strength as "
                 f"relief_surface.vert computes it (threshold alpha {float(options['alpha_threshold']):g}, "
                 f"saturation {float(options['saturation_alpha']):g})")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "fold_strength_vs_flexion.png"), dpi=110)
    plt.close(fig)
    print("wrote", os.path.join(OUT, "fold_strength_vs_flexion.png"))


def fold_closeups_figure():
    """Rows: elbow bent / straight, knee bent / straight (the walk's most and least bent poses);
    columns: exact folds displaced, the smooth folds as bump mapping, before issue 21."""
    os.makedirs(RAW, exist_ok=True)
    tool = os.path.join(BUILD, "fold_closeups")
    if not os.path.exists(tool):
        sys.exit(f"{tool} not found: build first (cmake --build {BUILD} --target fold_closeups)")
    subprocess.run([tool, ROOT, RAW], check=True)
    rows = read_csv("closeups.csv")
    columns = [("exact", "exact folds, displaced geometry"), ("bump", "smooth folds, bump mapped (now)"),
               ("before", "before issue 21: one Y-Y tile, not oriented")]
    fig, axes = plt.subplots(len(rows), len(columns), figsize=(3.0 * len(columns), 3.0 * len(rows) + 0.6), squeeze=False)
    for r, row in enumerate(rows):
        place = "inside the left elbow (jacket)" if row["joint"] == "elbow" else "behind the left knee (pants)"
        for c, (method, title) in enumerate(columns):
            axis = axes[r][c]
            axis.imshow(mpimg.imread(os.path.join(RAW, f"closeup_{row['joint']}_{row['state']}_{method}.png")))
            axis.set_xticks([])
            axis.set_yticks([])
            if r == 0:
                axis.set_title(title, fontsize=9)
            if c == 0:
                axis.set_ylabel(f"{place}\n{row['state']}, bend {float(row['bend_deg']):.0f} deg", fontsize=8)
    fig.suptitle("Garment folds over the walk cycle's most and least bent pose (core rasterizer, level 64 mesh;\n"
                 "bump mapping here tilts per-vertex normals, the display's shader does it per pixel)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "fold_closeups.png"), dpi=100)
    plt.close(fig)
    print("wrote", os.path.join(OUT, "fold_closeups.png"))


if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    if len(sys.argv) > 2 and sys.argv[2] == "wrinkle_placement":
        wrinkle_placement_figure()
    elif len(sys.argv) > 2 and sys.argv[2] == "fold_closeups":
        fold_closeups_figure()
    else:
        main()
