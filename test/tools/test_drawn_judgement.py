#!/usr/bin/env python3
"""The benchmarks' "drawn" judgement (bench/rviz_scaling.py drawn(), which bench/crowd_scaling.py
uses too) on the committed screenshots of bench/rviz_scaling.py's points (docs/rviz_scaling/):
every human at its place is drawn, and in the one-row points an empty place one past the end of
the row, beside its last human, is not (a missing human must fail its point; with 60 figure
pixels in 0.9 m boxes such empty places counted as drawn). Points of several rows are not judged
this way: seen from 0.7 rad above, a row's boxes overlap the next row's figures on screen (an
empty place beside a row of 30 holds more than 3 % of figure pixels), which still lets a
missing human there pass.

Usage: test_drawn_judgement.py <repository root>
"""
import os
import re
import sys
import unittest

ROOT = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else "."
sys.argv[1:] = sys.argv[2:]
sys.path.insert(0, os.path.join(ROOT, "bench"))
import rviz_scaling as rs  # noqa: E402

SHOTS = os.path.join(ROOT, "docs", "rviz_scaling")
POINT = re.compile(r"(dressedhuman_cpu_vertices|dressedhuman_gpu_vertices|robotmodel)_(\d+)_(\d+)m(_start)?\.png$")


class DrawnJudgement(unittest.TestCase):
    def test_every_human_is_drawn_and_no_empty_place_beside_one_row(self):
        points = [(name, POINT.match(name)) for name in sorted(os.listdir(SHOTS))]
        points = [(name, match) for name, match in points if match]
        self.assertGreaterEqual(len(points), 20, "the screenshots of bench/rviz_scaling.py are missing from " + SHOTS)
        for name, match in points:
            count, distance = int(match.group(2)), float(match.group(3))
            orbit = rs.view(count, distance)
            places = rs.positions(count)
            path = os.path.join(SHOTS, name)
            self.assertEqual(rs.drawn(path, places, orbit), count, name + ": a human at its place not judged drawn")
            if count > rs.ROW_LENGTH:
                continue
            empty = [(0.0, max(y for _, y in places) + 1.0), (0.0, min(y for _, y in places) - 1.0)]
            self.assertEqual(rs.drawn(path, empty, orbit), 0, name + ": an empty place beside the row judged drawn")


if __name__ == "__main__":
    unittest.main()
