#!/usr/bin/python3
"""A glitching TF never takes rviz down: when the human's frames land at absurd places (1e308 m,
where float overflows; infinity; 1e6 m, beyond what rviz can draw a human at) the DressedHuman
display hides the human and names the frame, rviz keeps running, and the human comes back as soon
as its TF is sane again."""
import os
import tempfile
import threading
import time
import unittest

import rospy
import rostest
import tf2_ros
from geometry_msgs.msg import TransformStamped

from screenshots import Rviz, figure_mask, grab, wait_for_figure


class GlitchingOrigin:
    """Broadcasts world -> glitching_origin at 30 Hz, at a translation the test sets."""

    def __init__(self):
        self.x = 0.0
        self.broadcaster = tf2_ros.TransformBroadcaster()
        self.running = True
        self.thread = threading.Thread(target=self.run, daemon=True)
        self.thread.start()

    def run(self):
        rate = rospy.Rate(30)
        while self.running and not rospy.is_shutdown():
            t = TransformStamped()
            t.header.stamp = rospy.Time.now()
            t.header.frame_id = "world"
            t.child_frame_id = "glitching_origin"
            t.transform.translation.x = self.x
            t.transform.rotation.w = 1.0
            self.broadcaster.sendTransform(t)
            rate.sleep()


class DisplayAbsurdTfTest(unittest.TestCase):
    def test_rviz_survives_and_the_human_comes_back(self):
        rospy.init_node("test_display_absurd_tf")
        # Kept under ctest's screenshot folder (build/test_screenshots/display_absurd_tf) to be looked at.
        directory = os.path.join(os.environ.get("DRESSED_HUMAN_SCREENSHOTS", tempfile.mkdtemp()),
                                 "display_absurd_tf")
        os.makedirs(directory, exist_ok=True)
        origin = GlitchingOrigin()
        # The camera stays on the world's origin: a view that followed the human to 1e308 m
        # would be rviz's own problem, not the display's.
        replacements = {"RELIEF_MODE": "Bump mapping", "Target Frame: body": "Target Frame: <Fixed Frame>"}
        with Rviz("display_test.rviz", replacements) as rviz:
            first = wait_for_figure(rviz, os.path.join(directory, "sane_0.png"), still=False)
            rospy.loginfo("sane: %d figure pixels", figure_mask(first).sum())
            for step, x in enumerate((1e308, float("inf"), 1e6)):
                origin.x = x
                time.sleep(6.0)
                self.assertTrue(rviz.alive(), "rviz died with the human at x = %g:\n%s" % (x, rviz.output()[-3000:]))
                hidden = figure_mask(grab(os.path.join(directory, "absurd_%d.png" % step))).sum()
                self.assertLess(hidden, 50, "nothing of the human may be drawn at x = %g" % x)
                origin.x = 0.0
                back = wait_for_figure(rviz, os.path.join(directory, "sane_%d.png" % (step + 1)), still=False,
                                       timeout=60.0)
                rospy.loginfo("x = %g: rviz alive, %d figure pixels; back at 0: %d", x, hidden, figure_mask(back).sum())
                self.assertGreater(figure_mask(back).sum(), 0.5 * figure_mask(first).sum())
            output = rviz.output()
        origin.running = False
        # tf2 interpolates between the sane and the absurd stamp: the first position reported may
        # lie anywhere between, but always beyond 100 km.
        pose = r"Pose: frame 'body' in 'world' is "
        self.assertRegex(output, pose + r"at \([0-9.]+e\+30[0-9], ")
        self.assertIn(pose + "not finite", output)
        self.assertRegex(output, pose + r"at \([0-9.]+e\+0[56], ")
        self.assertIn("the human is hidden until its TF is sane again", output)


if __name__ == "__main__":
    rostest.rosrun("dressed_human", "display_absurd_tf", DisplayAbsurdTfTest)
