#!/usr/bin/env python3
"""Writes config/motions/hand_made_walk.yaml: a hand-made walk from textbook gait keyframes (degrees over the
gait cycle, left heel strike at 0 %), turned into Eq. 1 coefficients by a discrete Fourier
transform of the piecewise-linear keyframe curve. Standard library only.

Sign conventions of the skeleton (README, "Skeleton"): every DOF turns the bone about its own
frame's y (flexion axis, pointing left), x, z (along the bone). For the legs and arms (z down,
x backward) +y swings the distal end backward: hip extension, knee flexion, shoulder extension;
for the foot (z forward-down) +y is plantarflexion.
"""
import math
import os

ORDER = 4
SAMPLES = 200
PERIOD = 1.1          # s per gait cycle
FORWARD_SPEED = 1.0   # m/s

# (percent of cycle, degrees)
HIP_FLEXION = [(0, 30), (15, 25), (30, 10), (50, -10), (60, -5), (75, 20), (87, 32), (100, 30)]
KNEE_FLEXION = [(0, 3), (15, 18), (30, 8), (40, 5), (50, 10), (60, 38), (72, 62), (85, 35), (95, 5), (100, 3)]
ANKLE_DORSIFLEXION = [(0, 0), (8, -6), (30, 8), (45, 10), (55, 0), (62, -18), (75, -2), (90, 2), (100, 0)]


def curve(keys, shift=0.0, scale=1.0, offset=0.0):
    """Samples the periodic piecewise-linear curve, shifted by `shift` of a cycle, in radians."""
    out = []
    for k in range(SAMPLES):
        p = ((k / SAMPLES + shift) % 1.0) * 100.0
        for (p0, v0), (p1, v1) in zip(keys, keys[1:]):
            if p0 <= p <= p1:
                out.append(math.radians(offset + scale * (v0 + (v1 - v0) * (p - p0) / (p1 - p0))))
                break
    return out


def fourier(samples, order=ORDER):
    n = len(samples)
    a0 = 2.0 * sum(samples) / n
    a = [2.0 * sum(s * math.cos(k * 2 * math.pi * i / n) for i, s in enumerate(samples)) / n for k in range(1, order + 1)]
    b = [2.0 * sum(s * math.sin(k * 2 * math.pi * i / n) for i, s in enumerate(samples)) / n for k in range(1, order + 1)]
    return a0, a, b


def fmt(v):
    return "%.6g" % (0.0 if abs(v) < 1e-9 else v)


def series(samples=None, a0=0.0, a=(), b=()):
    if samples is not None:
        a0, a, b = fourier(samples)
    text = "{a0: " + fmt(a0)
    if a:
        text += ", a: [%s], b: [%s]" % (", ".join(fmt(v) for v in a), ", ".join(fmt(v) for v in b))
    return text + "}"


def cosine(amplitude, harmonic=1):
    return [amplitude * math.cos(harmonic * 2 * math.pi * k / SAMPLES) for k in range(SAMPLES)]


def sine(amplitude, harmonic=1):
    return [amplitude * math.sin(harmonic * 2 * math.pi * k / SAMPLES) for k in range(SAMPLES)]


def main():
    joints = {name: {"y": series(), "x": series(), "z": series()} for name in (
        "waist", "torso", "neck", "head", "l_shoulder", "l_elbow", "l_wrist", "r_shoulder", "r_elbow",
        "r_wrist", "l_hip", "l_knee", "l_ankle", "r_hip", "r_knee", "r_ankle")}
    for side, shift in (("l", 0.0), ("r", 0.5)):
        joints[side + "_hip"]["y"] = series(curve(HIP_FLEXION, shift, scale=-1.0))
        joints[side + "_knee"]["y"] = series(curve(KNEE_FLEXION, shift))
        joints[side + "_ankle"]["y"] = series(curve(ANKLE_DORSIFLEXION, shift, scale=-1.0))
        # Arms swing against the legs: the left arm is back at left heel strike.
        swing = 1.0 if side == "l" else -1.0
        joints[side + "_shoulder"]["y"] = series(cosine(math.radians(18) * swing))
        joints[side + "_shoulder"]["x"] = series(a0=2 * math.radians(-5) * swing)
        joints[side + "_elbow"]["y"] = series([-math.radians(20) + v for v in cosine(math.radians(10) * swing)])
    joints["torso"]["z"] = series(cosine(math.radians(5)))       # thorax counter-rotates the pelvis
    joints["waist"]["y"] = series(a0=2 * math.radians(4))        # slight forward lean

    lines = ["# Hand-made walk from textbook gait keyframes (scripts/make_hand_walk.py).",
             "# Eq. 1 per DOF, radians; root translation in metres.",
             "name: hand_made_walk", "period: %g" % PERIOD, "joints:"]
    for name, dofs in joints.items():
        lines.append("  %s:" % name)
        for dof in ("y", "x", "z"):
            lines.append("    %s: %s" % (dof, dofs[dof]))
    lines += ["root:", "  forward_speed: %g" % FORWARD_SPEED, "  translation:",
              "    x: %s" % series(),
              "    y: %s" % series(sine(0.02)),
              "    z: %s" % series([0.93 + v for v in cosine(-0.02, 2)]),
              "  rotation:",
              "    roll: %s" % series(sine(math.radians(3), 2)),
              "    pitch: %s" % series(),
              "    yaw: %s" % series(cosine(math.radians(-4)))]
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "config", "motions", "hand_made_walk.yaml")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
