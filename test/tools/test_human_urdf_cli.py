#!/usr/bin/env python3
"""human_urdf --stature scales the whole body (crowd_member.launch's heights) and refuses absurd
factors, or a stature together with a fitted motion's body, naming what is wrong.

Usage: test_human_urdf_cli.py <human_urdf binary> <repository root>
"""
import subprocess
import sys
import unittest
import xml.etree.ElementTree as ElementTree

HUMAN_URDF = sys.argv[1] if len(sys.argv) > 1 else "build/devel/lib/dressed_human/human_urdf"
ROOT = sys.argv[2] if len(sys.argv) > 2 else "."
URDF = ROOT + "/urdf/human.urdf"


def run(*arguments):
    result = subprocess.run([HUMAN_URDF, URDF, *arguments], capture_output=True, text=True, timeout=60)
    return result.returncode, result.stdout, result.stderr


def knee_offset(urdf_text):
    joint = ElementTree.fromstring(urdf_text).find("joint[@name='l_knee_ry']")
    return float(joint.find("origin").get("xyz").split()[2])


class HumanUrdfStature(unittest.TestCase):
    def test_stature_scales_the_knee_offset_and_is_recorded(self):
        _, plain, _ = run()
        code, taller, stderr = run("--stature", "1.1")
        self.assertEqual(code, 0, stderr)
        self.assertAlmostEqual(knee_offset(taller), 1.1 * knee_offset(plain), places=6)
        self.assertIn("<dressed_human_body_shape>", taller)

    def test_absurd_statures_are_refused(self):
        for value in ("2", "0", "tall", "nan"):
            code, _, stderr = run("--stature", value)
            self.assertEqual(code, 2, value)
            self.assertIn("--stature must be a number in [0.8, 1.2], got '%s'" % value, stderr)

    def test_stature_and_a_fitted_body_are_one_too_many(self):
        code, _, stderr = run("--stature", "1.05", "--motion", ROOT + "/config/motions/cmu_02_01_fitted.yaml")
        self.assertEqual(code, 2)
        self.assertIn("--motion and --stature both shape the body: give one", stderr)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
