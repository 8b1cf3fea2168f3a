#!/usr/bin/python3
"""crowd_publisher (crowd_publisher.test starts it with count 5 at 30 Hz): one dressed_human/Crowd
message per tick for every human, each root frame body_<id> on /tf where the message puts it,
humans walking at their pace; the message survives a rosbag round trip; every bad parameter
stops the node with a message naming it."""
import math
import os
import subprocess
import tempfile
import time
import unittest

import rosbag
import rospkg
import rospy
import rostest
import tf2_ros
from dressed_human.msg import Crowd
from node_runs import run_node

PACKAGE = rospkg.RosPack().get_path("dressed_human")

COUNT = 5


class CrowdPublisherTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_crowd_publisher")
        cls.buffer = tf2_ros.Buffer(rospy.Duration(10.0))
        cls.listener = tf2_ros.TransformListener(cls.buffer)

    def collect(self, seconds):
        messages = []
        subscriber = rospy.Subscriber("/crowd", Crowd, messages.append)
        deadline = time.time() + 30.0
        while not messages and time.time() < deadline:
            time.sleep(0.1)
        self.assertTrue(messages, "no message on /crowd within 30 s")
        del messages[:]
        time.sleep(seconds)
        subscriber.unregister()
        return list(messages)

    def test_one_message_per_tick_for_every_human_and_their_roots_on_tf(self):
        messages = self.collect(3.0)
        rate = (len(messages) - 1) / (messages[-1].header.stamp - messages[0].header.stamp).to_sec()
        self.assertAlmostEqual(rate, 30.0, delta=3.0)
        for message in messages:
            self.assertEqual(message.header.frame_id, "world")
            self.assertEqual([h.id for h in message.humans], [str(i) for i in range(COUNT)])
            for human in message.humans:
                self.assertEqual(len(human.joint_angles), 48)
                self.assertTrue(all(math.isfinite(a) and abs(a) < 2 * math.pi for a in human.joint_angles))
                self.assertGreaterEqual(human.stature, 0.92 - 1e-6)
                self.assertLessEqual(human.stature, 1.08 + 1e-6)
        # Each human walks: its root moves at a walker's pace over the three seconds.
        first, last = messages[0], messages[-1]
        seconds = (last.header.stamp - first.header.stamp).to_sec()
        for a, b in zip(first.humans, last.humans):
            speed = math.hypot(b.root.position.x - a.root.position.x, b.root.position.y - a.root.position.y) / seconds
            self.assertGreater(speed, 0.5, "human %s" % a.id)
            self.assertLess(speed, 2.0, "human %s" % a.id)
            self.assertGreater(b.root.position.z, 0.7)  # the pelvis above the ground
        # body_<id> on /tf where the message of the same stamp puts it.
        message = messages[-2]
        for human in message.humans:
            transform = self.buffer.lookup_transform("world", "body_" + human.id, message.header.stamp,
                                                     rospy.Duration(1.0)).transform
            self.assertAlmostEqual(transform.translation.x, human.root.position.x, places=6)
            self.assertAlmostEqual(transform.translation.y, human.root.position.y, places=6)
            self.assertAlmostEqual(transform.rotation.w, human.root.orientation.w, places=6)
        # Only the roots stream on /tf: no skeleton frames (skeleton_tf is off).
        self.assertFalse(self.buffer.can_transform("world", "l_knee_0", rospy.Time(0)))

    def test_the_message_survives_a_rosbag_round_trip(self):
        bag = os.path.join(tempfile.mkdtemp(), "crowd.bag")
        subprocess.run(["rosbag", "record", "--duration=2", "-O", bag, "/crowd"], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=60)
        with rosbag.Bag(bag) as recorded:
            info = recorded.get_type_and_topic_info().topics["/crowd"]
            self.assertEqual(info.msg_type, "dressed_human/Crowd")
            self.assertGreater(info.message_count, 30)
            for _, message, _ in recorded.read_messages(topics=["/crowd"]):
                self.assertEqual(len(message.humans), COUNT)
                self.assertEqual(len(message.humans[2].joint_angles), 48)

    def assertRejected(self, expected, *arguments):
        node_name = "crowd_" + self.id().split(".")[-1]
        code, output = run_node("crowd_publisher", "__name:=" + node_name, *arguments)
        self.assertNotEqual(code, 0, "crowd_publisher accepted %s:\n%s" % (arguments, output))
        self.assertIn("FATAL", output)
        self.assertIn(expected.replace("{node}", node_name), output)

    def test_bad_count(self):
        self.assertRejected("parameter /{node}/count must be in [0, 1000]", "_count:=-3")

    def test_fractional_count(self):
        self.assertRejected("parameter /{node}/count must be a whole number of humans", "_count:=2.5")

    def test_bad_rate(self):
        self.assertRejected("parameter /{node}/rate must be in [1, 1000]", "_rate:=0.0")

    def test_missing_crowd_file(self):
        self.assertRejected("/nonexistent/crowd.yaml", "_crowd_file:=/nonexistent/crowd.yaml")

    def test_bad_crowd_file(self):
        path = os.path.join(tempfile.mkdtemp(), "crowd.yaml")
        with open(path, "w") as f:
            f.write('humans:\n  "1": {speed: 9}\n')
        self.assertRejected("humans.1.speed", "_crowd_file:=" + path)

    def test_missing_body_file_in_both_modes(self):
        for mode in ([], ["_people_topic:=/people"]):
            self.assertRejected("parameter /{node}/body_file (the body whose feet walk): /nonexistent/body.yaml",
                                "_body_file:=/nonexistent/body.yaml", *mode)

    def test_bad_frame_prefix(self):
        self.assertRejected("parameter /{node}/frame_prefix 'a-b' may hold only letters", "_frame_prefix:=a-b")

    def test_bad_smoothing_of_people(self):
        self.assertRejected("parameter /{node}/smoothing must be in [0, 1]", "_people_topic:=/people", "_smoothing:=2")

    def test_a_motion_fitted_to_one_person_is_refused_in_both_modes(self):
        fitted = os.path.join(PACKAGE, "config", "motions", "cmu_02_01_fitted.yaml")
        for mode in ([], ["_people_topic:=/people"]):
            self.assertRejected("was fitted to one person's body", "_motion_file:=" + fitted, *mode)

    def test_a_suffixed_skeleton_is_refused_in_both_modes(self):
        urdf = subprocess.run([os.path.join(PACKAGE, "scripts", "suffix_urdf.py"),
                               os.path.join(PACKAGE, "urdf", "human.urdf"), "7"],
                              check=True, stdout=subprocess.PIPE, universal_newlines=True).stdout
        rospy.set_param("/suffixed/robot_description", urdf)
        for mode in ([], ["_people_topic:=/people"]):
            self.assertRejected("robot_description's frames carry the suffix '_7'", "__ns:=/suffixed", *mode)


if __name__ == "__main__":
    rostest.rosrun("dressed_human", "crowd_publisher", CrowdPublisherTest)
