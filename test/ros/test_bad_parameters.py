#!/usr/bin/python3
"""Every bad parameter stops skeleton_publisher with a non-zero exit and a message naming it."""
import os
import subprocess
import unittest

import roslib.packages
import rosparam
import rospkg
import rostest
from node_runs import run_node

PACKAGE = rospkg.RosPack().get_path("dressed_human")
BAD_MOTION = os.path.join(PACKAGE, "test", "data", "bad_motions", "coefficient_nan.yaml")


class BadParametersTest(unittest.TestCase):
    def assertRejected(self, expected, *arguments):
        # A node name per case: private parameters given on the command line stay on the
        # parameter server, and must not leak into the next case.
        node_name = "publisher_" + self.id().split(".")[-1]
        expected = expected.replace("{node}", node_name)
        code, output = run_node("skeleton_publisher", "__name:=" + node_name, *arguments)
        self.assertNotEqual(code, 0, "skeleton_publisher accepted %s:\n%s" % (arguments, output))
        self.assertIn("FATAL", output)
        self.assertIn(expected, output)

    def assertSurvives(self, expected, *arguments, waypoints=None):
        """A bad walking parameter is an error naming it; the node walks on with the default.
        Lists cannot be given on a C++ node's command line: `waypoints` goes to the server."""
        node_name = "publisher_" + self.id().split(".")[-1]
        if waypoints is not None:
            rosparam.set_param_raw("/%s/waypoints" % node_name, waypoints)
        expected = expected.replace("{node}", node_name)
        executable = roslib.packages.find_node("dressed_human", "skeleton_publisher")[0]
        process = subprocess.Popen([executable, "__name:=" + node_name] + list(arguments), stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT, universal_newlines=True)
        try:
            output, _ = process.communicate(timeout=4)
            self.fail("skeleton_publisher stopped (code %s) on %s:\n%s" % (process.returncode, arguments, output))
        except subprocess.TimeoutExpired:
            process.terminate()
            output, _ = process.communicate(timeout=10)
        self.assertIn("ERROR", output)
        self.assertIn(expected, output)
        self.assertIn("walking a route", output)

    def test_waypoints_not_pairs(self):
        self.assertSurvives("parameter /{node}/waypoints must be a list of [x, y] pairs in metres, e.g. [[0, 0], [4, 0], "
                            "[4, 3]]; element 1 is a list of 3", waypoints=[[0, 0], [1, 2, 3]])

    def test_waypoints_nan(self):
        self.assertSurvives("parameter /{node}/waypoints: waypoint 1 is [nan, 1]", waypoints=[[0, 0], [float("nan"), 1]])

    def test_waypoints_one_place_looped(self):
        self.assertSurvives("is a closed route with fewer than two distinct places", waypoints=[[2, 2]])

    def test_speed_running(self):
        self.assertSurvives("parameter /{node}/speed must be in [0, 3] m/s, got 5", "_speed:=5")

    def test_mode_unknown(self):
        self.assertRejected("parameter /{node}/mode must be 'walk' or 'replay', got 'run'", "_mode:=run")

    def test_route_end_unknown(self):
        self.assertRejected("parameter /{node}/route_end must be 'loop' or 'stand', got 'stop'", "_route_end:=stop")

    def test_body_file_missing(self):
        self.assertRejected("parameter /{node}/body_file (the body whose feet walk): /nonexistent/body.yaml: cannot "
                            "open the body description", "_body_file:=/nonexistent/body.yaml")

    def test_gait_file_missing(self):
        self.assertRejected("/nonexistent/gaits.yaml: cannot open gait table", "_gait_file:=/nonexistent/gaits.yaml")

    def test_rate_out_of_range(self):
        self.assertRejected("parameter /{node}/rate must be in (0, 10000] Hz", "_rate:=-5")

    def test_rate_wrong_type(self):
        self.assertRejected("parameter /{node}/rate must be a number, got a string", "_rate:=fast")

    def test_speed_factor_negative(self):
        self.assertRejected("parameter /{node}/speed_factor must be in [0, 10]", "_speed_factor:=-1")

    def test_speed_factor_absurd(self):
        self.assertRejected("parameter /{node}/speed_factor must be in [0, 10] (times the motion's speed), got 1e+12",
                            "_speed_factor:=1e12")

    def test_origin_beyond_a_map(self):
        self.assertRejected("parameter /{node}/origin_x must be in [-100000, 100000] m, got 1e+308", "_origin_x:=1e308")

    def test_yaw_in_degrees(self):
        self.assertRejected("parameter /{node}/origin_yaw must be in [-6.28319, 6.28319] rad, got 90", "_origin_yaw:=90")

    def test_loop_wrong_type(self):
        self.assertRejected("parameter /{node}/loop must be true or false, got a string", "_loop:=maybe")

    def test_body_id_characters(self):
        self.assertRejected("parameter /{node}/body_id must be letters and digits only", "_body_id:=a-b")

    def test_body_id_against_suffixed_urdf(self):
        self.assertRejected("parameter /other_id/{node}/body_id is '2' but robot_description's frames "
                            "carry the suffix '_3'", "__ns:=/other_id", "_body_id:=2")

    def test_missing_motion_file(self):
        self.assertRejected("/nonexistent/walk.yaml: cannot open the motion file", "_motion_file:=/nonexistent/walk.yaml")

    def test_invalid_motion_file(self):
        self.assertRejected("coefficient_nan.yaml:4:25: joints.waist.y.a[2]: expected a finite number",
                            "_motion_file:=" + BAD_MOTION)

    def test_fitted_motion_on_another_body(self):
        fitted = os.path.join(roslib.packages.get_pkg_dir("dressed_human"), "config", "motions", "cmu_02_01_fitted.yaml")
        self.assertRejected("cmu_02_01_fitted.yaml was fitted to a body whose waist is [a, b, c] = [",
                            "_motion_file:=" + fitted)

    def test_missing_robot_description(self):
        self.assertRejected("parameter /nowhere/robot_description is not set", "__ns:=/nowhere")

    def test_invalid_robot_description(self):
        self.assertRejected("the URDF root link must be 'body' or 'body_<id>', found 'pelvis'", "__ns:=/bad_urdf")

    def test_good_parameters_run(self):
        executable = roslib.packages.find_node("dressed_human", "skeleton_publisher")[0]
        process = subprocess.Popen([executable, "__ns:=/other_id", "_body_id:=3", "_rate:=1000"],
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
        try:
            with self.assertRaises(subprocess.TimeoutExpired):
                process.wait(timeout=3)  # still running: it accepted its parameters
        finally:
            process.terminate()
            process.wait(timeout=10)


if __name__ == "__main__":
    rostest.rosrun("dressed_human", "bad_parameters", BadParametersTest)
