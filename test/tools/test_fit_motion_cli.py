#!/usr/bin/env python3
"""fit_motion refuses absurd options and unwritable outputs at once, naming what is wrong (issue 23).

Usage: test_fit_motion_cli.py <fit_motion binary> <repository root>
"""
import os
import subprocess
import sys
import tempfile
import unittest

FIT_MOTION = sys.argv[1] if len(sys.argv) > 1 else "build/devel/lib/dressed_human/fit_motion"
ROOT = sys.argv[2] if len(sys.argv) > 2 else "."
CAPTURE = os.path.join(ROOT, "data", "motion", "cmu_02_01_walk.bvh")
URDF = os.path.join(ROOT, "urdf", "human.urdf")


def run(*arguments):
    result = subprocess.run([FIT_MOTION, CAPTURE, "--urdf", URDF, *arguments], capture_output=True, text=True,
                            timeout=120)
    return result.returncode, result.stderr


class ShippedMotionsSayHowToFitThemAgain(unittest.TestCase):
    """Each shipped motion written by fit_motion records its command in its header. fit_motion
    fits the person's body unless told --body default, and the node refuses a fitted-body motion
    on the plain URDF: a command that would make the other kind of file does not reproduce it."""

    def test_the_recorded_command_makes_a_motion_of_the_same_kind(self):
        folder = os.path.join(ROOT, "config", "motions")
        checked = 0
        for name in sorted(os.listdir(folder)):
            with open(os.path.join(folder, name)) as f:
                text = f.read()
            lines = text.splitlines()
            if len(lines) < 2 or not lines[0].startswith("# Fitted to motion capture by:"):
                continue
            command = lines[1].lstrip("# ").split()
            self.assertEqual(command[0], "fit_motion", name)
            default_body = any(a == "--body" and b == "default" for a, b in zip(command, command[1:]))
            fitted_body = "\nbody_shape:" in text
            self.assertNotEqual(default_body, fitted_body,
                                "%s: %s, but its command %s --body default" % (
                                    name, "has a fitted body_shape" if fitted_body else "has no body_shape",
                                    "passes" if default_body else "lacks"))
            checked += 1
        self.assertGreaterEqual(checked, 2)


class FitMotionRefusesAbsurdInput(unittest.TestCase):
    def assertRefused(self, expected_message, *arguments):
        code, stderr = run(*arguments)
        self.assertNotEqual(code, 0, stderr)
        self.assertIn(expected_message, stderr)
        # Refused before fitting: the fit's report (its accuracy against the capture) never came.
        self.assertNotIn("joint positions, fitted series vs", stderr)

    def test_sweep_orders_are_capped(self):
        self.assertRefused("--sweep-max is at most 64", "--sweep-max", "100000", "--sweep-csv", "/tmp/sweep.csv")
        self.assertRefused("--max-order is at most 64", "--max-order", "1000")
        self.assertRefused("--timing-calls is at most 10000000", "--timing-calls", "1e12")

    def test_period_in_the_range_of_a_gait(self):
        self.assertRefused("--period expects a number >= 0.1", "--period", "1e-300")
        self.assertRefused("--period expects a number in [0.1, 60] s", "--period", "1e9")

    def test_output_checked_before_the_fit(self):
        with tempfile.TemporaryDirectory() as directory:
            self.assertRefused("cannot write the motion file: no such directory '%s/missing'" % directory,
                               "-o", os.path.join(directory, "missing", "walk.yaml"))
            self.assertRefused("%s: cannot write the motion file: is a directory" % directory, "-o", directory)
            self.assertRefused("cannot write the sweep CSV: no such directory", "--sweep-csv",
                               os.path.join(directory, "missing", "sweep.csv"))
            if os.geteuid() != 0:  # root writes anywhere
                os.chmod(directory, 0o500)
                self.assertRefused("is not writable", "-o", os.path.join(directory, "walk.yaml"))

    def test_units_and_body_options_are_checked(self):
        self.assertRefused("unknown length unit 'parsec': expected one of m, cm, mm, in, cmu", "--units", "parsec")
        self.assertRefused("--body must be 'fitted' or 'default', got 'tall'", "--body", "tall")
        # Our feet are aimed for the drawn body: a body that cannot be read stops the fit, naming it.
        code, stderr = run("--body-description", "/nonexistent/body.yaml", "-q")
        self.assertEqual(code, 1, stderr)
        self.assertIn("/nonexistent/body.yaml: cannot open the body description", stderr)
        gait = os.path.join(ROOT, "data", "motion", "tutorial_normal_gait_cycle.mot")
        for arguments, message in ((["--units", "cm"], "--units applies to BVH input only"),
                                   (["--osim", "x.osim", "--format", "bvh"], "--osim applies to OpenSim motion input only")):
            result = subprocess.run([FIT_MOTION, gait, "--urdf", URDF, *arguments], capture_output=True, text=True,
                                    timeout=120)
            self.assertEqual(result.returncode, 2, result.stderr)
            self.assertIn(message, result.stderr)
        # The right skeleton in a wrong unit: no human has those proportions.
        code, stderr = run("--units", "m", "-q")
        self.assertNotEqual(code, 0, stderr)
        self.assertIn("outside [0.2, 5]: a wrong unit (--units) or joint map?", stderr)

    def test_the_body_is_fitted_unless_asked_not_to(self):
        with tempfile.TemporaryDirectory() as directory:
            fitted = os.path.join(directory, "fitted.yaml")
            code, stderr = run("-o", fitted, "--max-order", "2")
            self.assertEqual(code, 0, stderr)
            self.assertIn("units: cmu, the rest pose is", stderr)  # detected: CMU's ASF units
            # Issue 39's floor: our rigid skeleton on every captured frame, against the capture.
            self.assertIn("our skeleton on the unsmoothed retarget vs the capture's FK: mean", stderr)
            with open(fitted) as f:
                text = f.read()
            self.assertIn("\nbody_shape:", text)
            self.assertIn("# Joint positions vs the capture's own FK (metres", text)
            default = os.path.join(directory, "default.yaml")
            code, stderr = run("-o", default, "--max-order", "2", "--body", "default", "--units", "cmu")
            self.assertEqual(code, 0, stderr)
            with open(default) as f:
                self.assertNotIn("body_shape", f.read())

    def test_an_opensim_motion_gets_the_body_of_its_model(self):
        gait = os.path.join(ROOT, "data", "motion", "tutorial_normal_gait_cycle.mot")
        model = os.path.join(ROOT, "config", "opensim", "gait2392_joints.osim")
        with tempfile.TemporaryDirectory() as directory:
            fitted = os.path.join(directory, "gait.yaml")
            result = subprocess.run([FIT_MOTION, gait, "--urdf", URDF, "--osim", model, "--period", "1", "-o", fitted],
                                    capture_output=True, text=True, timeout=120)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertIn("Joint positions vs the capture's own FK (metres", result.stderr)
            with open(fitted) as f:
                self.assertIn("\nbody_shape:", f.read())
            # A map of joint coordinates reads angles without a model: it cannot give a fitted body.
            coordinates = os.path.join(directory, "coordinates.yaml")
            joints = ["waist", "torso", "neck", "head", "l_shoulder", "l_elbow", "l_wrist", "r_shoulder", "r_elbow",
                      "r_wrist", "l_hip", "l_knee", "l_ankle", "r_hip", "r_knee", "r_ankle"]
            with open(coordinates, "w") as f:
                f.write("kind: coordinates\nroot: {translation: [pelvis_tx, pelvis_ty, pelvis_tz], "
                        "rotation: [[pelvis_tilt, 0, 0, 1]]}\njoints: {%s}\n" % ", ".join(
                            j + (": [[knee_angle_l, 0, 0, 1]]" if j == "l_knee" else ": []") for j in joints))
            for body, code in ((["--body", "fitted"], 1), ([], 0)):
                result = subprocess.run([FIT_MOTION, gait, "--urdf", URDF, "--map", coordinates, "--period", "1", "-q",
                                         "-o", fitted, *body], capture_output=True, text=True, timeout=120)
                self.assertEqual(result.returncode, code, result.stderr)
                if code:
                    self.assertIn(coordinates + ": a map of kind 'coordinates' reads joint angles only", result.stderr)
            # A model that is not there, or not a model, is named.
            for bad, message in ((os.path.join(directory, "none.osim"), "cannot open the OpenSim model file"),
                                 (gait, "not valid XML")):
                result = subprocess.run([FIT_MOTION, gait, "--urdf", URDF, "--osim", bad, "--period", "1", "-q"],
                                        capture_output=True, text=True, timeout=120)
                self.assertEqual(result.returncode, 1, result.stderr)
                self.assertIn(bad + ": " + message, result.stderr)

    def test_a_good_output_is_written(self):
        with tempfile.TemporaryDirectory() as directory:
            output = os.path.join(directory, "walk.yaml")
            code, stderr = run("-o", output, "--max-order", "2", "-q")
            self.assertEqual(code, 0, stderr)
            self.assertTrue(os.path.getsize(output) > 0)

    def test_verbose_names_where_the_fit_is_poorest(self):
        code, stderr = run("--max-order", "2", "--verbose")
        self.assertEqual(code, 0, stderr)
        worst = [line for line in stderr.splitlines() if line.strip().startswith("worst against the capture: ")]
        self.assertEqual(len(worst), 1, stderr)
        # A joint of ours, the frame and time, the error, and the joint's angles there.
        self.assertRegex(worst[0], r"worst against the capture: [lr]?_?[a-z]+ at frame \d+ \([\d.]+ s\), [\d.]+ cm; "
                                   r"its y, x, z there: sampled( -?[\d.]+){3} deg, fitted( -?[\d.]+){3} deg")


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]])
