#!/usr/bin/python3
"""skeleton_publisher: exact frame set, rate, agreement with robot_state_publisher, bag replay.

--fitted-body: robot_description is a fitted person's (human_urdf): it must record the body shape,
and the joints must sit at that person's proportions (robot_state_publisher reads the same URDF).
"""
import os
import re
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import rosbag
import rospy
import rostest
import tf2_ros
from tf2_msgs.msg import TFMessage

from skeleton_tf import is_unit, median, transform_difference, urdf_edges

COLLECT_SECONDS = 4.0


class SkeletonPublisherTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_skeleton_publisher")
        cls.urdf = rospy.get_param("/robot_description")
        cls.lock = threading.Lock()
        cls.ours, cls.ours_static, cls.rsp = [], [], {}
        cls.receipt_times = []
        subscribers = [
            rospy.Subscriber("/tf", TFMessage, cls.on_ours, queue_size=1000),
            rospy.Subscriber("/tf_static", TFMessage, cls.on_ours_static, queue_size=10),
            rospy.Subscriber("/rsp/tf", TFMessage, cls.on_rsp, queue_size=1000),
        ]
        deadline = time.time() + 30
        while time.time() < deadline and not (cls.ours and cls.rsp):
            time.sleep(0.1)
        with cls.lock:
            del cls.ours[:]
            del cls.receipt_times[:]
            cls.rsp.clear()
        cls.bag_path = os.path.join(tempfile.mkdtemp(), "walk.bag")
        recorder = subprocess.Popen(["rosbag", "record", "--duration=3", "-O", cls.bag_path, "/tf", "/tf_static"],
                                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        time.sleep(COLLECT_SECONDS)
        recorder.wait(timeout=30)
        for subscriber in subscribers:
            subscriber.unregister()

    @classmethod
    def on_ours(cls, message):
        with cls.lock:
            cls.ours.append(message)
            cls.receipt_times.append(time.monotonic())

    @classmethod
    def on_ours_static(cls, message):
        with cls.lock:
            cls.ours_static.append(message)

    @classmethod
    def on_rsp(cls, message):
        with cls.lock:
            for transform in message.transforms:
                cls.rsp.setdefault(transform.header.stamp, {})[transform.child_frame_id] = transform

    def test_exact_frame_set(self):
        moving, fixed = urdf_edges(self.urdf)
        expected = moving | {("world", "body")}
        self.assertEqual(len(expected), 49)
        self.assertGreater(len(self.ours), 100)
        for message in self.ours:
            edges = [(t.header.frame_id, t.child_frame_id) for t in message.transforms]
            self.assertEqual(len(edges), len(set(edges)), "a frame published twice in one message")
            self.assertEqual(set(edges), expected, "one TFMessage per tick with every moving frame")
            self.assertEqual(len({t.header.stamp for t in message.transforms}), 1)
            self.assertTrue(all(is_unit(t.transform.rotation) for t in message.transforms))
        static_edges = {(t.header.frame_id, t.child_frame_id) for m in self.ours_static for t in m.transforms}
        self.assertEqual(static_edges, fixed)
        self.assertEqual(len(fixed), 4)

    def test_body_of_the_description(self):
        fitted = "--fitted-body" in sys.argv
        self.assertEqual("<dressed_human_body_shape>" in self.urdf, fitted)
        # The thigh's length in TF: the knee's offset from the hip, as the URDF's joint origin says.
        knee = [t.transform.translation for m in self.ours for t in m.transforms if t.child_frame_id == "l_knee_ry_link"]
        self.assertTrue(knee)
        thigh = (knee[-1].x ** 2 + knee[-1].y ** 2 + knee[-1].z ** 2) ** 0.5
        if fitted:
            c = float(re.search(r'<bone name="l_hip" a="[^"]*" b="[^"]*" c="([^"]*)"', self.urdf).group(1))
            self.assertNotAlmostEqual(c, 1.0, places=2)
            self.assertAlmostEqual(thigh, 0.42 * c, places=6)
        else:
            self.assertAlmostEqual(thigh, 0.42, places=9)

    def test_rate_within_five_percent(self):
        stamps = [m.transforms[0].header.stamp.to_sec() for m in self.ours]
        stamp_period = median([b - a for a, b in zip(stamps, stamps[1:])])
        # Receipt times carry this test's own scheduling jitter: judge them over the whole window.
        receipt_rate = (len(self.receipt_times) - 1) / (self.receipt_times[-1] - self.receipt_times[0])
        rospy.loginfo("median period of stamps %.5f s, mean receipt rate %.2f Hz", stamp_period, receipt_rate)
        self.assertAlmostEqual(stamp_period, 0.01, delta=0.0005)
        self.assertAlmostEqual(receipt_rate, 100.0, delta=5.0)

    def test_equals_robot_state_publisher(self):
        compared, worst = 0, 0.0
        for message in self.ours:
            stamp = message.transforms[0].header.stamp
            theirs = self.rsp.get(stamp)
            if theirs is None:
                continue
            for transform in message.transforms[1:]:  # the root is not a URDF joint
                reference = theirs[transform.child_frame_id]
                self.assertEqual(reference.header.frame_id, transform.header.frame_id)
                worst = max(worst, transform_difference(transform.transform, reference.transform))
            compared += 1
        rospy.loginfo("compared %d ticks with robot_state_publisher, worst difference %.3g", compared, worst)
        self.assertGreater(compared, 50)
        self.assertLessEqual(worst, 1e-9)

    def test_recorded_bag_replays_into_tf2_identically(self):
        buffer = tf2_ros.BufferCore(rospy.Duration(60))
        count = 0
        with rosbag.Bag(self.bag_path) as bag:
            for topic, message, _ in bag.read_messages(topics=["/tf", "/tf_static"]):
                for transform in message.transforms:
                    if topic == "/tf_static":
                        buffer.set_transform_static(transform, "bag")
                    else:
                        buffer.set_transform(transform, "bag")
                count += topic == "/tf"
        self.assertGreater(count, 200)
        live = {m.transforms[0].header.stamp: m for m in self.ours}
        checked, worst = 0, 0.0
        with rosbag.Bag(self.bag_path) as bag:
            for _, message, _ in bag.read_messages(topics=["/tf"]):
                stamp = message.transforms[0].header.stamp
                if stamp not in live:
                    continue
                for transform in live[stamp].transforms:
                    looked_up = buffer.lookup_transform_core(transform.header.frame_id, transform.child_frame_id, stamp)
                    worst = max(worst, transform_difference(looked_up.transform, transform.transform))
                checked += 1
        rospy.loginfo("bag replay: %d ticks looked up in tf2, worst difference %.3g", checked, worst)
        self.assertGreater(checked, 200)
        self.assertLessEqual(worst, 1e-12)
        # Chains resolve too: a foot in the world frame, through static and moving joints.
        stamp = sorted(live)[len(live) // 2]
        foot = buffer.lookup_transform_core("world", "l_ankle", stamp)
        self.assertLess(foot.transform.translation.z, 0.4)


if __name__ == "__main__":
    rostest.rosrun("dressed_human", "skeleton_publisher", SkeletonPublisherTest)
