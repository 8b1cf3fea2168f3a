#!/usr/bin/python3
"""Runs this package's human_urdf tool, for launch files' `<param command=...>`.

rosrun skips executables under the package's own build/ folder, where this repository's devel
space lives; roslib's node lookup (the one roslaunch uses for type=) finds them.
"""
import os
import sys

import roslib.packages

found = roslib.packages.find_node("dressed_human", "human_urdf")
if not found:
    sys.exit("human_urdf.py: the human_urdf tool of dressed_human is not built (or its devel space is not sourced)")
os.execv(found[0], [found[0]] + sys.argv[1:])
