#!/usr/bin/env python3
"""Prints a URDF with `_<id>` appended to every link and joint name, so several humans coexist in
one TF tree (REP-155 frame naming). Standard library only.

Usage: suffix_urdf.py <input.urdf> <id>
  e.g. <param name="robot_description" command="$(find dressed_human)/scripts/suffix_urdf.py
                                                 $(find dressed_human)/urdf/human.urdf 2"/>
"""
import re
import sys
import xml.etree.ElementTree as ElementTree


def main():
    if len(sys.argv) != 3:
        sys.stderr.write("usage: suffix_urdf.py <input.urdf> <id>\n")
        return 2
    path, body_id = sys.argv[1], sys.argv[2]
    if not re.fullmatch(r"[A-Za-z0-9]+", body_id):
        sys.stderr.write("suffix_urdf.py: id '%s' must be letters and digits only\n" % body_id)
        return 2
    try:
        tree = ElementTree.parse(path)
    except (OSError, ElementTree.ParseError) as error:
        sys.stderr.write("suffix_urdf.py: cannot read URDF '%s': %s\n" % (path, error))
        return 1
    suffix = "_" + body_id
    robot = tree.getroot()
    for element in robot.iter():
        if element.tag in ("link", "joint") and element.get("name") is not None and element in list(robot):
            element.set("name", element.get("name") + suffix)
        if element.tag in ("parent", "child") and element.get("link") is not None:
            element.set("link", element.get("link") + suffix)
    robot.set("name", robot.get("name", "human") + suffix)
    sys.stdout.write(ElementTree.tostring(robot, encoding="unicode"))
    sys.stdout.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
