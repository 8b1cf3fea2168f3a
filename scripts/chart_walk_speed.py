#!/usr/bin/python3
"""docs/walk_speed.png and docs/walk_speed.md from the walk_speed_table tool (issue 20): our stride
and cadence against speed beside the normative trend, and the worst stance slide per step with
planted feet against the old constant-speed playback. Figures are written, never typed.
Usage: scripts/chart_walk_speed.py <walk_speed_table binary> [source dir]"""
import csv
import os
import subprocess
import sys
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def rows(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def main():
    tool = sys.argv[1]
    source = sys.argv[2] if len(sys.argv) > 2 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([tool, source, out], check=True)
        trend, slide = rows(os.path.join(out, "walk_speed_trend.csv")), rows(os.path.join(out, "walk_slide.csv"))
    docs = os.environ.get("DRESSED_HUMAN_DOCS", os.path.join(source, "docs"))  # evaluate.sh: its run's folder
    figure, (stride_axis, cadence_axis, slide_axis) = plt.subplots(1, 3, figsize=(15, 4.2))
    speeds = [r["speed_m_s"] for r in trend]
    stride_axis.plot(speeds, [r["normative_stride_m"] for r in trend], "o--", color="grey", label="normative (Schwartz 2008, scaled)")
    stride_axis.plot(speeds, [r["our_stride_m"] for r in trend], "o-", label="ours, planted feet")
    stride_axis.set(xlabel="speed (m/s)", ylabel="stride length (m)", title="Stride against speed")
    cadence_axis.plot(speeds, [r["normative_cadence_steps_min"] for r in trend], "o--", color="grey", label="normative")
    cadence_axis.plot(speeds, [r["our_cadence_steps_min"] for r in trend], "o-", label="ours")
    cadence_axis.set(xlabel="speed (m/s)", ylabel="cadence (steps/min)", title="Cadence against speed")
    slide_speeds = [r["speed_m_s"] for r in slide]
    slide_axis.plot(slide_speeds, [r["playback_worst_slide_mm"] for r in slide], "s-", color="tab:red",
                    label="before: walk sped up, root at constant speed (set down onto its lowest frame)")
    slide_axis.plot(slide_speeds, [r["planted_worst_slide_mm"] for r in slide], "o-", color="tab:green", label="planted feet")
    slide_axis.axhline(5.0, color="black", linewidth=0.8, linestyle=":", label="goal 5 mm")
    slide_axis.set_yscale("symlog", linthresh=1.0)
    slide_axis.set_ylim(bottom=0.0)
    slide_axis.set(xlabel="speed (m/s)", ylabel="worst stance slide per step (mm)", title="Foot slide, straight walking")
    for axis in (stride_axis, cadence_axis, slide_axis):
        axis.grid(alpha=0.3)
        axis.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(os.path.join(docs, "walk_speed.png"), dpi=90)
    with open(os.path.join(docs, "walk_speed.md"), "w") as f:
        f.write("<!-- Written by scripts/chart_walk_speed.py from the walk_speed_table tool; do not edit. -->\n")
        f.write("| speed (m/s) | our stride (m) | normative stride (m) | our cadence (steps/min) | normative cadence (steps/min) |\n|---|---|---|---|---|\n")
        for r in trend:
            f.write("| %.2f | %.3f | %.3f | %.1f | %.1f |\n" % (r["speed_m_s"], r["our_stride_m"], r["normative_stride_m"],
                                                          r["our_cadence_steps_min"], r["normative_cadence_steps_min"]))
        f.write("\n| speed (m/s) | travel (m/s) | worst stance slide, planted (mm) | lowest sole point, planted (mm) | "
                "stance (% of the cycle): left / right | foot flat (% of stance) | stances begun on the heel (%) | "
                "worst slide, old playback (mm) | lowest sole point, old playback (mm) |\n"
                "|---|---|---|---|---|---|---|---|---|\n")
        for r in slide:
            f.write("| %.1f | %.3f | %.2f | %.2f | %.1f / %.1f | %.1f | %.0f | %.1f | %.1f |\n" % (
                r["speed_m_s"], r["planted_travel_m_s"], r["planted_worst_slide_mm"], r["planted_lowest_sole_mm"],
                r["stance_left_percent"], r["stance_right_percent"], r["flat_percent_of_stance"],
                r["heel_first_percent"], r["playback_worst_slide_mm"], r["playback_lowest_sole_mm"]))
        f.write("\nStance: a foot's lowest sole point within 1 cm of the floor; foot flat: its heel and toe both "
                "within 1 cm (FootContactMeter, foot_contact.h); foot flat and heel first over both feet; 10 s of "
                "straight walking. The old playback is set down so that its lowest sole point over those 10 s "
                "touches the floor (its fitted root height need not put the drawn sole there).\n")
    print("wrote docs/walk_speed.png and docs/walk_speed.md")


if __name__ == "__main__":
    main()
