"""Shared by the rostests: the expected TF layout read from the URDF, and message comparison."""
import math
import xml.etree.ElementTree as ElementTree


def urdf_edges(urdf_text):
    """(moving, fixed): sets of (parent, child) link pairs of the URDF's joints."""
    robot = ElementTree.fromstring(urdf_text)
    moving, fixed = set(), set()
    for joint in robot.findall("joint"):
        edge = (joint.find("parent").get("link"), joint.find("child").get("link"))
        (fixed if joint.get("type") == "fixed" else moving).add(edge)
    return moving, fixed


def transform_difference(a, b):
    """Largest difference between two geometry_msgs/Transform: metres and quaternion components
    (a quaternion and its negative are the same rotation)."""
    ta, tb = a.translation, b.translation
    translation = max(abs(ta.x - tb.x), abs(ta.y - tb.y), abs(ta.z - tb.z))
    qa = (a.rotation.x, a.rotation.y, a.rotation.z, a.rotation.w)
    qb = (b.rotation.x, b.rotation.y, b.rotation.z, b.rotation.w)
    same = max(abs(x - y) for x, y in zip(qa, qb))
    flipped = max(abs(x + y) for x, y in zip(qa, qb))
    return max(translation, min(same, flipped))


def median(values):
    ordered = sorted(values)
    middle = len(ordered) // 2
    return ordered[middle] if len(ordered) % 2 else 0.5 * (ordered[middle - 1] + ordered[middle])


def is_unit(q):
    return abs(math.sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w) - 1.0) < 1e-9
