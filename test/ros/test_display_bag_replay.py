#!/usr/bin/python3
"""A recorded bag, replayed without the node, drives the DressedHuman display (across loops)."""
import os
import subprocess
import tempfile
import time
import unittest

import roslib.packages
import rospy
import rostest

from screenshots import Rviz, figure_mask, package_errors, wait_for_figure


class DisplayBagReplayTest(unittest.TestCase):
    def test_replayed_bag_drives_the_display(self):
        rospy.init_node("test_display_bag_replay")
        directory = tempfile.mkdtemp()
        bag = os.path.join(directory, "walk.bag")
        node = subprocess.Popen([roslib.packages.find_node("dressed_human", "skeleton_publisher")[0]])
        try:
            time.sleep(2.0)
            subprocess.run(["rosbag", "record", "--duration=4", "-O", bag, "/tf", "/tf_static"], check=True,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=60)
        finally:
            node.terminate()
            node.wait(timeout=20)
        self.assertTrue(os.path.exists(bag))

        rospy.set_param("/use_sim_time", True)
        player = subprocess.Popen(["rosbag", "play", "--clock", "--loop", "--quiet", bag],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            with Rviz("display_test.rviz", {"RELIEF_MODE": "Bump mapping"}) as rviz:
                first = wait_for_figure(rviz, os.path.join(directory, "first.png"), settle=2.0, still=False)
                time.sleep(6.0)  # the 4 s bag loops at least once: time jumps back, rviz resets
                second = wait_for_figure(rviz, os.path.join(directory, "second.png"), settle=2.0, still=False)
                output = rviz.output()
        finally:
            player.terminate()
            player.wait(timeout=20)
        rospy.loginfo("figure pixels: %d, then %d after the loop", figure_mask(first).sum(), figure_mask(second).sum())
        self.assertGreater(figure_mask(first).sum(), 20000)
        self.assertGreater(figure_mask(second).sum(), 20000)
        errors = package_errors(output)
        self.assertEqual(errors, [])


if __name__ == "__main__":
    rostest.rosrun("dressed_human", "display_bag_replay", DisplayBagReplayTest)
