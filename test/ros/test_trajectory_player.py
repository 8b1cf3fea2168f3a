#!/usr/bin/python3
"""trajectory_player (trajectory_player.test plays test/data/trajectories/three_people.txt, 25 fps,
turned by 90 degrees and shifted by (10, -2)): spencer_tracking_msgs/TrackedPersons at the file's
rate, each message the people of one frame where the placement puts them, frame after frame and
over the loop with the stamps going on; the shared Jülich corridor plays as well; a missing or
malformed file and bad parameters stop the node with a FATAL naming them. The message type is not
installed: messages arrive as rospy.AnyMsg and are decoded with classes genpy builds from the
definition the publisher sends."""
import math
import os
import subprocess
import tempfile
import time
import unittest

import genpy.dynamic
import roslib.packages
import rospkg
import rospy
import rostest
from node_runs import run_node

TYPE = "spencer_tracking_msgs/TrackedPersons"
MD5 = "21c0b1a57c4933e68f39aa3802861828"
PACKAGE = rospkg.RosPack().get_path("dressed_human")
FIXTURE = os.path.join(PACKAGE, "test", "data", "trajectories", "three_people.txt")
# The shared data next to the repository, as the core tests find it (DRESSED_HUMAN_SHARED_DIR).
CORRIDOR = os.path.join(PACKAGE, "..", "shared", "data", "people", "juelich_uni_corr_500_01.txt")
YAW = math.pi / 2
OFFSET = (10.0, -2.0)
UNKNOWN_VARIANCE = 99999.0


def read_frames(path):
    """{frame: {id: (x, y)}} of a Jülich text file."""
    frames = {}
    with open(path) as text:
        for line in text:
            fields = line.split()
            if fields and not fields[0].startswith("#"):
                frames.setdefault(int(fields[1]), {})[int(fields[0])] = (float(fields[2]), float(fields[3]))
    return frames


def place(x, y, yaw=YAW, offset=OFFSET):
    c, s = math.cos(yaw), math.sin(yaw)
    return c * x - s * y + offset[0], s * x + c * y + offset[1]


_classes = {}


def decode(message):
    header = message._connection_header
    definition = header["message_definition"]
    if definition not in _classes:
        _classes[definition] = genpy.dynamic.generate_dynamic(header["type"], definition)[header["type"]]
    return _classes[definition]().deserialize(message._buff)


def frame_of(decoded, frames, **placement):
    """The file's frame whose people are exactly the message's, each where the placement puts
    them; None if there is none."""
    people = {track.track_id: (track.pose.pose.position.x, track.pose.pose.position.y) for track in decoded.tracks}
    for frame, in_file in frames.items():
        if set(in_file) == set(people) and all(
                math.hypot(*(a - b for a, b in zip(place(*in_file[i], **placement), people[i]))) < 1e-6 for i in people):
            return frame
    return None


def collect(topic, seconds=None, count=None):
    """AnyMsg messages of `topic` (after the first one arrived, `seconds` of them, or the first `count`)."""
    messages = []
    subscriber = rospy.Subscriber(topic, rospy.AnyMsg, messages.append, queue_size=1000)
    deadline = time.time() + 30.0
    while not messages and time.time() < deadline:
        time.sleep(0.05)
    if seconds is not None:
        del messages[:]
        time.sleep(seconds)
    else:
        while len(messages) < count and time.time() < deadline:
            time.sleep(0.05)
    subscriber.unregister()
    return list(messages)


class TrajectoryPlayerTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_trajectory_player")
        cls.frames = read_frames(FIXTURE)
        cls.raw = collect("/tracked_persons", seconds=3.0)  # the 2 s recording and a loop
        cls.decoded = [decode(message) for message in cls.raw]

    def test_the_type_is_spencers_tracked_persons(self):
        self.assertTrue(self.raw, "no message on /tracked_persons within 30 s")
        header = self.raw[0]._connection_header
        self.assertEqual(header["type"], TYPE)
        self.assertEqual(header["md5sum"], MD5)
        self.assertEqual(type(self.decoded[0])._md5sum, MD5)  # the definition sent is the one of that md5sum
        self.assertTrue(all(d.header.frame_id == "world" for d in self.decoded))

    def test_the_rate_is_the_files_and_the_stamps_go_on_over_the_loop(self):
        stamps = [d.header.stamp.to_sec() for d in self.decoded]
        self.assertGreater(len(stamps), 50)
        rate = (len(stamps) - 1) / (stamps[-1] - stamps[0])
        self.assertAlmostEqual(rate, 25.0, delta=2.5)
        self.assertTrue(all(b > a for a, b in zip(stamps, stamps[1:])), "stamps went back")

    def test_each_message_is_the_next_frame_placed(self):
        played = [frame_of(d, self.frames) for d in self.decoded]
        self.assertNotIn(None, played, "a message matches no frame of the file placed by yaw and offset")
        for decoded, frame in zip(self.decoded, played):
            self.assertEqual(len(decoded.tracks), len(self.frames[frame]), "frame %d" % frame)
        for a, b in zip(played, played[1:]):
            self.assertEqual(b, (a + 1) % 50, "frame %d followed by %d" % (a, b))
        self.assertIn(0, played[1:], "no loop back to frame 0 in 3 s of a 2 s recording")
        # Person 1's first position (1, 0.5), turned by 90 degrees and shifted by (10, -2).
        first = self.decoded[played.index(0, 1)]
        position = next(t.pose.pose.position for t in first.tracks if t.track_id == 1)
        self.assertAlmostEqual(position.x, 9.5, places=6)
        self.assertAlmostEqual(position.y, -1.0, places=6)
        self.assertEqual(position.z, 0.0)

    def test_velocity_and_yaw_of_walkers_and_no_yaw_for_who_stands(self):
        frame_30 = self.decoded[[frame_of(d, self.frames) for d in self.decoded].index(30)]
        tracks = {t.track_id: t for t in frame_30.tracks}
        # 1 walks +x at 1 m/s, 2 walks -x at 0.5 m/s: turned by 90 degrees, +y and -y.
        for track_id, vy, yaw in ((1, 1.0, math.pi / 2), (2, -0.5, -math.pi / 2)):
            track = tracks[track_id]
            self.assertAlmostEqual(track.twist.twist.linear.x, 0.0, places=3)
            self.assertAlmostEqual(track.twist.twist.linear.y, vy, places=3)
            q = track.pose.pose.orientation
            self.assertAlmostEqual(2 * math.atan2(q.z, q.w), yaw, places=3)
            self.assertLess(track.pose.covariance[35], 1.0)
        self.assertGreaterEqual(tracks[3].pose.covariance[35], UNKNOWN_VARIANCE)
        self.assertEqual(tracks[3].twist.twist.linear.x, 0.0)
        self.assertFalse(any(t.is_occluded for t in frame_30.tracks))

    def test_the_shared_corridor_recording_plays(self):
        if not os.path.exists(CORRIDOR):
            self.skipTest("no shared recording at " + CORRIDOR)
        executable = roslib.packages.find_node("dressed_human", "trajectory_player")[0]
        player = subprocess.Popen([executable, "__name:=corridor_player", "_file:=" + CORRIDOR, "tracked_persons:=/corridor"],
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, universal_newlines=True)
        try:
            messages = collect("/corridor", count=1)
        finally:
            player.terminate()
            output, _ = player.communicate(timeout=10)
        self.assertTrue(messages, "no message on /corridor within 30 s:\n" + output)
        self.assertIn("148 persons", output)
        # The first message received (which frame it is depends on when the subscription connected).
        frames = read_frames(CORRIDOR)
        first = decode(messages[0])
        frame = frame_of(first, frames, yaw=0.0, offset=(0.0, 0.0))
        self.assertIsNotNone(frame, "the first message matches no frame of the corridor file")
        self.assertEqual(len(first.tracks), len(frames[frame]))
        self.assertGreater(len(first.tracks), 0)

    def assertRejected(self, expected, *arguments):
        node_name = "player_" + self.id().split(".")[-1]
        code, output = run_node("trajectory_player", "__name:=" + node_name, *arguments)
        self.assertNotEqual(code, 0, "trajectory_player accepted %s:\n%s" % (arguments, output))
        self.assertIn("FATAL", output)
        self.assertIn(expected.replace("{node}", node_name), output)

    def write(self, text):
        path = os.path.join(tempfile.mkdtemp(), "people.txt")
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_missing_file(self):
        self.assertRejected("/nonexistent/people.txt: cannot open the trajectory file: No such file or directory",
                            "_file:=/nonexistent/people.txt")

    def test_malformed_file(self):
        path = self.write("# framerate: 25 fps\n1 0 0.0 0.5 1.7\n1 1 0.04 abc 1.7\n")
        self.assertRejected(path + ":3: column y is not a number: 'abc'", "_file:=" + path)

    def test_file_without_frame_rate(self):
        path = self.write("1 0 0.0 0.5 1.7\n")
        self.assertRejected(path + ": the header states no frame rate", "_file:=" + path)

    def test_no_file_parameter(self):
        self.assertRejected("parameter /{node}/file is not set")

    def test_unknown_format(self):
        self.assertRejected("parameter /{node}/format must be auto, juelich or obsmat, got 'csv'",
                            "_file:=" + FIXTURE, "_format:=csv")

    def test_format_not_the_files(self):
        self.assertRejected(FIXTURE + ":6: 5 columns; the obsmat format has 8", "_file:=" + FIXTURE, "_format:=obsmat")

    def test_bad_time_scale(self):
        self.assertRejected("parameter /{node}/time_scale must be in [0.01, 100]", "_file:=" + FIXTURE, "_time_scale:=0")

    def test_bad_frame_rate(self):
        self.assertRejected("parameter /{node}/frame_rate must be in [0, 1000] Hz (0: the file's), got -25",
                            "_file:=" + FIXTURE, "_frame_rate:=-25")

    def test_loop_not_a_boolean(self):
        self.assertRejected("parameter /{node}/loop must be true or false", "_file:=" + FIXTURE, "_loop:=sometimes")


if __name__ == "__main__":
    rostest.rosrun("dressed_human", "trajectory_player", TrajectoryPlayerTest)
