#!/usr/bin/env python3
"""Writes urdf/human.urdf: the one skeleton definition of dressed_human.

The figure is described here in the body frame at rest (x forward, y left, z up, origin at the
pelvis centre, standing upright), bone by bone as a segment from its proximal joint to its distal
end. Every bone frame sits at its proximal joint with z along the bone; its x/y axes follow one
rule (y as close to body-left as possible, else x forward) so that flexion/extension is always the
rotation about y. The URDF origins are derived from these segments, so the numbers in one place
stay consistent. Standard library only: runs with any python3.

Usage: generate_human_urdf.py [output-path]   (default: urdf/human.urdf next to this script)
"""
import math
import os
import sys

# name (frame, REP-155 style), parent frame, articulated?, proximal joint, distal end, radius,
# anatomical name. Proximal/distal points in metres in the body frame at rest (pelvis centre 0.96 m
# above the floor, stature 1.75 m).
BONES = [
    ("waist",       "body",        True,  (0.0, 0.0, 0.05),   (0.0, 0.0, 0.25),    0.125, "lower spine (abdomen)"),
    ("torso",       "waist",       True,  (0.0, 0.0, 0.25),   (0.0, 0.0, 0.51),    0.140, "upper spine (chest)"),
    ("neck",        "torso",       True,  (0.0, 0.0, 0.51),   (0.0, 0.0, 0.60),    0.050, "neck"),
    ("head",        "neck",        True,  (0.0, 0.0, 0.60),   (0.0, 0.0, 0.79),    0.095, "head"),
    ("l_clavicle",  "torso",       False, (0.0, 0.02, 0.47),  (0.0, 0.19, 0.47),   0.040, "left clavicle"),
    ("l_shoulder",  "l_clavicle",  True,  (0.0, 0.19, 0.47),  (0.0, 0.19, 0.18),   0.050, "left upper arm"),
    ("l_elbow",     "l_shoulder",  True,  (0.0, 0.19, 0.18),  (0.0, 0.19, -0.07),  0.040, "left forearm"),
    ("l_wrist",     "l_elbow",     True,  (0.0, 0.19, -0.07), (0.0, 0.19, -0.25),  0.035, "left hand"),
    ("r_clavicle",  "torso",       False, (0.0, -0.02, 0.47), (0.0, -0.19, 0.47),  0.040, "right clavicle"),
    ("r_shoulder",  "r_clavicle",  True,  (0.0, -0.19, 0.47), (0.0, -0.19, 0.18),  0.050, "right upper arm"),
    ("r_elbow",     "r_shoulder",  True,  (0.0, -0.19, 0.18), (0.0, -0.19, -0.07), 0.040, "right forearm"),
    ("r_wrist",     "r_elbow",     True,  (0.0, -0.19, -0.07), (0.0, -0.19, -0.25), 0.035, "right hand"),
    ("l_pelvis",    "body",        False, (0.0, 0.0, 0.0),    (0.0, 0.09, -0.06),  0.080, "left hip bone"),
    ("l_hip",       "l_pelvis",    True,  (0.0, 0.09, -0.06), (0.0, 0.09, -0.48),  0.075, "left thigh"),
    ("l_knee",      "l_hip",       True,  (0.0, 0.09, -0.48), (0.0, 0.09, -0.89),  0.055, "left shank"),
    ("l_ankle",     "l_knee",      True,  (0.0, 0.09, -0.89), (0.15, 0.09, -0.95), 0.040, "left foot"),
    ("r_pelvis",    "body",        False, (0.0, 0.0, 0.0),    (0.0, -0.09, -0.06), 0.080, "right hip bone"),
    ("r_hip",       "r_pelvis",    True,  (0.0, -0.09, -0.06), (0.0, -0.09, -0.48), 0.075, "right thigh"),
    ("r_knee",      "r_hip",       True,  (0.0, -0.09, -0.48), (0.0, -0.09, -0.89), 0.055, "right shank"),
    ("r_ankle",     "r_knee",      True,  (0.0, -0.09, -0.89), (0.15, -0.09, -0.95), 0.040, "right foot"),
]

# Chain order of the three revolute joints of every articulated joint: flexion first (largest
# angles in a walk), twist about the bone last, so the middle rotation (ab/adduction) stays small
# and far from gimbal lock in gait.
DOF_AXES = [("ry", (0, 1, 0)), ("rx", (1, 0, 0)), ("rz", (0, 0, 1))]
JOINT_LIMIT = math.pi


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def norm(a):
    return math.sqrt(sum(x * x for x in a))


def unit(a):
    n = norm(a)
    return tuple(x / n for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def bone_axes(proximal, distal):
    """Columns x, y, z of the bone frame at rest, in body coordinates."""
    z = unit(sub(distal, proximal))
    left = (0.0, 1.0, 0.0)
    if abs(dot(z, left)) < 0.9:
        y = unit(sub(left, tuple(dot(z, left) * c for c in z)))
        x = cross(y, z)
    else:
        forward = (1.0, 0.0, 0.0)
        x = unit(sub(forward, tuple(dot(z, forward) * c for c in z)))
        y = cross(z, x)
    return x, y, z


def matrix_from_columns(x, y, z):
    return [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]]


def transpose(m):
    return [[m[j][i] for j in range(3)] for i in range(3)]


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def matvec(m, v):
    return tuple(sum(m[i][k] * v[k] for k in range(3)) for i in range(3))


def rpy_from_matrix(m):
    """URDF convention: R = Rz(yaw) Ry(pitch) Rx(roll)."""
    pitch = math.atan2(-m[2][0], math.hypot(m[0][0], m[1][0]))
    if abs(math.cos(pitch)) > 1e-9:
        roll = math.atan2(m[2][1], m[2][2])
        yaw = math.atan2(m[1][0], m[0][0])
    else:  # gimbal: put everything into yaw
        roll = 0.0
        yaw = math.atan2(-m[0][1], m[1][1])
    return roll, pitch, yaw


def fmt(values):
    return " ".join(repr(0.0 if abs(v) < 1e-15 else round(float(v), 12)) for v in values)


def capsule_visual(length, radius, colour):
    return (
        '    <visual>\n'
        '      <origin xyz="0 0 %s" rpy="0 0 0"/>\n'
        '      <geometry><cylinder radius="%s" length="%s"/></geometry>\n'
        '      <material name="%s"/>\n'
        '    </visual>\n'
        '    <visual>\n'
        '      <origin xyz="0 0 %s" rpy="0 0 0"/>\n'
        '      <geometry><sphere radius="%s"/></geometry>\n'
        '      <material name="%s"/>\n'
        '    </visual>\n'
    ) % (fmt([length / 2]), fmt([radius]), fmt([length]), colour, fmt([length]), fmt([radius]), colour)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out_path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "urdf", "human.urdf")

    frames = {"body": ((0.0, 0.0, 0.0), matrix_from_columns((1, 0, 0), (0, 1, 0), (0, 0, 1)))}
    for name, _, _, proximal, distal, _, _ in BONES:
        frames[name] = (proximal, matrix_from_columns(*bone_axes(proximal, distal)))

    out = ['<?xml version="1.0"?>\n',
           '<!-- Generated by scripts/generate_human_urdf.py: edit that script, not this file. -->\n',
           '<!-- 20 bones, 16 articulated joints of 3 revolute DOF each (chain ry, rx, rz through\n',
           '     dummy links), 4 fixed joints (clavicles, hip bones). Every bone frame: origin at the\n',
           '     proximal joint, z along the bone; the bone cylinder spans [0, length] on z. -->\n',
           '<robot name="human">\n',
           '  <material name="skin"><color rgba="0.87 0.72 0.62 1"/></material>\n',
           '  <material name="spine"><color rgba="0.55 0.62 0.75 1"/></material>\n',
           '  <link name="body">\n',
           '    <visual>\n',
           '      <origin xyz="0 0 0" rpy="0 0 0"/>\n',
           '      <geometry><sphere radius="0.11"/></geometry>\n',
           '      <material name="spine"/>\n',
           '    </visual>\n',
           '  </link>\n']
    for name, parent, articulated, proximal, distal, radius, anatomical in BONES:
        parent_origin, parent_rotation = frames[parent]
        origin, rotation = frames[name]
        xyz = matvec(transpose(parent_rotation), sub(origin, parent_origin))
        rpy = rpy_from_matrix(matmul(transpose(parent_rotation), rotation))
        length = norm(sub(distal, proximal))
        colour = "spine" if parent in ("body", "waist", "torso") and name not in ("l_pelvis", "r_pelvis") else "skin"
        out.append('\n  <!-- %s -->\n' % anatomical)
        if articulated:
            previous = parent
            for index, (suffix, axis) in enumerate(DOF_AXES):
                child = name if index == len(DOF_AXES) - 1 else "%s_%s_link" % (name, suffix)
                joint_xyz, joint_rpy = (xyz, rpy) if index == 0 else ((0, 0, 0), (0, 0, 0))
                out.append(
                    '  <joint name="%s_%s" type="revolute">\n'
                    '    <parent link="%s"/>\n    <child link="%s"/>\n'
                    '    <origin xyz="%s" rpy="%s"/>\n    <axis xyz="%s"/>\n'
                    '    <limit lower="%s" upper="%s" effort="100" velocity="20"/>\n'
                    '  </joint>\n' % (name, suffix, previous, child, fmt(joint_xyz), fmt(joint_rpy),
                                      fmt(axis), fmt([-JOINT_LIMIT]), fmt([JOINT_LIMIT])))
                if child != name:
                    out.append('  <link name="%s"/>\n' % child)
                previous = child
        else:
            out.append(
                '  <joint name="%s_fixed" type="fixed">\n'
                '    <parent link="%s"/>\n    <child link="%s"/>\n'
                '    <origin xyz="%s" rpy="%s"/>\n'
                '  </joint>\n' % (name, parent, name, fmt(xyz), fmt(rpy)))
        out.append('  <link name="%s">\n%s  </link>\n' % (name, capsule_visual(length, radius, colour)))
    out.append('</robot>\n')
    with open(out_path, "w") as f:
        f.write("".join(out))


if __name__ == "__main__":
    main()
