#!/usr/bin/python3
"""Chart of the Fourier order m against accuracy and cost, from the CSV that
`fit_motion INPUT --sweep-csv FILE` writes (one row per m: RMS residual in degrees, joint-position
errors in cm, nanoseconds per MotionEvaluator::evaluate call).

Usage: chart_fourier_order.py SWEEP.csv [OUTPUT.png]   (default: docs/fourier_order_speed_vs_accuracy.png)

Example (from the package directory):
  build/fit_motion data/motion/cmu_02_01_walk.bvh -o /tmp/walk.yaml --sweep-csv /tmp/sweep.csv
  scripts/chart_fourier_order.py /tmp/sweep.csv
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(sys.argv) >= 2 else 2
    here = os.path.dirname(os.path.abspath(__file__))
    output = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "docs", "fourier_order_speed_vs_accuracy.png")
    with open(sys.argv[1]) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.stderr.write("%s: no rows\n" % sys.argv[1])
        return 1
    column = lambda name: [float(r[name]) for r in rows]
    order = [int(r["order"]) for r in rows]

    fig, accuracy = plt.subplots(figsize=(8.5, 5.0))
    accuracy.plot(order, column("mean_rms_deg"), "o-", color="tab:blue", label="RMS residual, mean over DOFs (deg)")
    accuracy.plot(order, column("joint_error_samples_mean_cm"), "s-", color="tab:green",
                  label="joint position vs unsmoothed retarget (cm)")
    accuracy.plot(order, [v - column("unsmoothed_error_capture_mean_cm")[i]
                          for i, v in enumerate(column("joint_error_capture_mean_cm"))], "^--", color="tab:olive",
                  label="joint position vs capture FK, minus the %.1f cm\nbone-proportion floor (cm)"
                  % column("unsmoothed_error_capture_mean_cm")[0])
    accuracy.set_xlabel("Fourier order m (harmonics per DOF)")
    accuracy.set_ylabel("error (deg / cm)")
    accuracy.set_ylim(bottom=0)
    accuracy.set_xticks(order)
    accuracy.grid(True, alpha=0.3)

    cost = accuracy.twinx()
    cost.plot(order, column("evaluate_ns"), "d:", color="tab:red", label="MotionEvaluator::evaluate (ns/update)")
    cost.plot(order, column("evaluate_fk_ns"), "x:", color="tab:purple", label="evaluate + forward kinematics (ns/update)")
    cost.set_ylabel("cost per update (ns)")
    cost.set_ylim(bottom=0)

    lines = accuracy.get_legend_handles_labels()
    more = cost.get_legend_handles_labels()
    accuracy.legend(lines[0] + more[0], lines[1] + more[1], loc="upper right", fontsize=8)
    accuracy.set_title("CMU 02_01 walk: accuracy vs evaluation cost of the Fourier order")
    fig.tight_layout()
    fig.savefig(output, dpi=120)
    print("wrote %s" % output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
