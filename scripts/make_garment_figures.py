#!/usr/bin/python3
"""docs/garments_fig9.png: like the seed's Fig. 9(a), the skirt made continuously longer
(mini -> knee -> long, Eq. 8' across thigh and shank) and pants, each under the jacket; top row
standing, bottom row in a walk pose (the long skirt follows the bending knee).

Run from the repository root after building: scripts/make_garment_figures.py [BUILD_DIR]
(default build_garment). Renders with the core's CPU rasterizer (src/tools/render_mesh.cpp),
over the real posed skin (skin.h, tessellated as in src/tools/render_skin.cpp).
"""
import os
import subprocess
import sys
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build_garment")
RENDER = os.path.join(BUILD, "render_mesh")
G = os.path.join(ROOT, "config", "garments")

PANELS = [
    ("mini skirt, c = 0.2", ["jacket.yaml", "skirt.yaml"], "0.2"),
    ("knee length, c = c_k", ["jacket.yaml", "skirt.yaml"], "knee"),
    ("long skirt, c = 1", ["jacket.yaml", "skirt.yaml"], "1.0"),
    ("pants", ["jacket.yaml", "pants.yaml"], None),
]
POSES = [("standing", ["--rest"]), ("walking, t = 0.25 s", ["--time", "0.25"])]


def render(files, length, pose_args, out):
    cmd = [RENDER, "--source-dir", ROOT, "--size", "360x720", "--view", "three_quarter", "--out", out]
    for f in files:
        cmd += ["--garment", os.path.join(G, f)]
    if length is not None:
        cmd += ["--length", length]
    cmd += pose_args
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def main():
    fig, axes = plt.subplots(len(POSES), len(PANELS), figsize=(2.6 * len(PANELS), 5.4 * len(POSES)))
    with tempfile.TemporaryDirectory() as tmp:
        for r, (pose_name, pose_args) in enumerate(POSES):
            for c, (title, files, length) in enumerate(PANELS):
                out = os.path.join(tmp, "p%d%d.png" % (r, c))
                render(files, length, pose_args, out)
                ax = axes[r][c]
                ax.imshow(mpimg.imread(out)[40:700, 20:340])
                ax.set_axis_off()
                ax.set_title("%s\n(%s)" % (title, pose_name), fontsize=9)
    fig.suptitle("Garments as C1 bicubic Bezier patch sets following the skeleton (cf. seed Fig. 9(a))", fontsize=10)
    fig.tight_layout()
    out = os.path.join(os.environ.get("DRESSED_HUMAN_DOCS", os.path.join(ROOT, "docs")), "garments_fig9.png")  # evaluate.sh: its run's folder
    fig.savefig(out, dpi=90)
    print("wrote", out)


if __name__ == "__main__":
    main()
