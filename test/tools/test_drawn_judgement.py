#!/usr/bin/env python3
"""The benchmarks' "drawn" judgement (bench/rviz_scaling.py drawn_places(), which
bench/crowd_scaling.py and bench/rviz_memory.py use too) on the committed screenshots of
bench/rviz_scaling.py's and bench/crowd_scaling.py's points (docs/rviz_scaling/,
docs/crowd_scaling/): every human at its place is drawn, and an empty place one past each end of
every row, judged with the humans, is not: that is a missing human with a neighbour beside it.
With 60 figure pixels in 0.9 m boxes such places counted as drawn beside one row; with boxes alone
(no nearest-place rule), beside the rows of the 30-human point; with 100 humans in rows of 10 seen
from 30 m, beside the far rows, whose heads and the next row's feet share the screen.

The peer's screenshots are judged for every person drawn, not for empty places: its display's
default labels (track and detection ids, track state, velocity arrows) are drawn beside each
figure, and they are part of what the peer's users get (its README: default properties).

Usage: test_drawn_judgement.py <repository root>
"""
import os
import re
import sys
import unittest

ROOT = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else "."
sys.argv[1:] = sys.argv[2:]
sys.path.insert(0, os.path.join(ROOT, "bench"))
import crowd_scaling as cs  # noqa: E402
import rviz_scaling as rs  # noqa: E402

SHOTS = os.path.join(ROOT, "docs", "rviz_scaling")
POINT = re.compile(r"(dressedhuman_cpu_vertices|dressedhuman_gpu_vertices|robotmodel)_(\d+)_(\d+)m(_start)?\.png$")
CROWD_SHOTS = os.path.join(ROOT, "docs", "crowd_scaling")
CROWD_POINT = re.compile(r"(dressedhuman_from_one_crowd_message|spencer_walking_man_mesh_peer)_(\d+)_(\d+)m(_start)?\.png$")


def rows_of(places):
    rows = {}
    for x, y in places:
        rows.setdefault(round(x, 6), []).append(y)
    return rows


class DrawnJudgement(unittest.TestCase):
    def judge(self, shots, point, view, positions, labelled=()):
        """Every point's screenshots under `shots` named by `point` (count and distance in groups
        2 and 3; group 1 the subject), its view and places from view(count, distance) and
        positions(count). Subjects in `labelled` draw labels beside their figures: no empty places."""
        points = [(name, point.match(name)) for name in sorted(os.listdir(shots))]
        points = [(name, match) for name, match in points if match]
        self.assertGreaterEqual(len(points), 20, "the benchmark's screenshots are missing from " + shots)
        multi_row = 0
        for name, match in points:
            count, distance = int(match.group(2)), float(match.group(3))
            orbit = view(count, distance)
            places = positions(count)
            path = os.path.join(shots, name)
            rows = rows_of(places)
            multi_row += len(rows) > 1
            empty = [(x, y) for x, ys in rows.items() for y in (min(ys) - 1.0, max(ys) + 1.0)]
            judged = rs.drawn_places(path, places + empty, orbit)
            self.assertEqual(judged[:count], [True] * count, name + ": a human at its place not judged drawn")
            if match.group(1) not in labelled:
                self.assertEqual(judged[count:], [False] * len(empty), name + ": an empty place beside a row judged drawn")
        self.assertGreater(multi_row, 0, "no point of several rows among the screenshots in " + shots)

    def test_rviz_scaling_every_human_drawn_and_no_empty_place(self):
        self.judge(SHOTS, POINT, rs.view, rs.positions)

    def test_crowd_scaling_every_human_drawn_and_no_empty_place(self):
        self.judge(CROWD_SHOTS, CROWD_POINT, cs.view, cs.positions, labelled=("spencer_walking_man_mesh_peer",))


if __name__ == "__main__":
    unittest.main()
