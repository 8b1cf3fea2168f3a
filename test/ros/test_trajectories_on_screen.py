#!/usr/bin/python3
"""A recorded crowd on screen: trajectories.launch plays the shared Jülich corridor recording
(juelich_uni_corr_500_01.txt: 148 people walking along a 10 m corridor, about 15 at a time, 75 s
at 25 fps) with skeleton_tf, turned and shifted into the view by the launch's yaw and offsets.
For over 40 s:
  - a screenshot every 2.5 s: every human on TF at that instant is drawn in its box, nothing is
    drawn outside the boxes (on_screen.judge_humans; people walk close together and their boxes
    overlap, so a figure pixel counts only for the human whose frames project nearest to it; the
    figure is every pixel neither background nor grid, dark garments too);
  - every TF tick: each human's root body_<id> is within 0.30 m (95th percentile) of where the
    recording has person <id> a render delay before the tick's stamp, and the humans on TF are
    the recording's people at that time (one may come up to 0.5 s late and leave up to 1 s late);
  - the player's every message is a frame of the file placed by the same yaw and offsets;
  - no errors of this package in the launch log.
Screenshots, each one's verdict (summary.json), the root errors (roots.json), every root on TF and
the player's stamps (trail.json) and the launch log go to $DRESSED_HUMAN_SCREENSHOTS/trajectories.
"""
import json
import math
import os
import re
import tempfile
import threading
import time
import unittest

import genpy.dynamic
import numpy
import roslib.packages
import rospy
import rostest
import tf2_ros

from on_screen import (BODY_MARGIN_METRES, HumansOnTf, Launch, LoopingTfListener, OrbitView, ROOT_FRAME, bone_frames,
                       drawn_mask, edited_config, observe, wait_for_view)
from screenshots import package_errors

PACKAGE = roslib.packages.get_pkg_dir("dressed_human")
# The shared data next to the repository, as the core tests find it (DRESSED_HUMAN_SHARED_DIR).
CORRIDOR = os.path.join(PACKAGE, "..", "shared", "data", "people", "juelich_uni_corr_500_01.txt")
# The corridor (x -5.5..4.7 m, y 0.2..4.7 m) turned to run along y and centred on the origin:
# x -2.25..2.25, y -5.1..5.1. A yaw other than zero checks that player and checker place alike.
YAW = math.pi / 2
OFFSET = (2.45, 0.4)
# Looking down the x axis from high up, the corridor's length across the square view, every
# person in it whole in view (checked below against the view's real size).
VIEW = {"Distance": 17.5, "Pitch": 1.2, "Yaw": 0.0, "Focal Point": {"X": 0.0, "Y": 0.0, "Z": 0.5},
        "Target Frame": "<Fixed Frame>"}
CORRIDOR_PLACED = ((-2.25, 2.25), (-5.1, 5.1))
# rviz draws a human behind the TF this test reads before a screenshot (its render delay and a
# frame not yet swapped: up to ~0.3 m at walking speed seen): each box covers the human's poses
# over LAG_SECONDS before it too, which stretches it behind the walker only; grown all round by
# the body's reach alone, so that a figure drawn ~0.5 m off its place shows outside every box.
LAG_SECONDS = 0.5
ROOT_ERROR_P95_METRES = 0.30
# people.launch's promise: a human comes within ~0.5 s of its track's start and leaves within
# ~1 s of its end (at the render time); and the stamps the player sent map to the recording
# only to within a tick of its timer.
APPEAR_SECONDS, LEAVE_SECONDS, STAMP_SLACK_SECONDS = 0.5, 1.0, 0.1


def place(x, y):
    c, s = math.cos(YAW), math.sin(YAW)
    return c * x - s * y + OFFSET[0], s * x + c * y + OFFSET[1]


class Recording:
    """A Jülich text file (`# framerate: R` header; `id frame x y z` rows), placed by YAW and
    OFFSET, read in recording seconds r: frame = first frame + r * rate, looped the way
    trajectory_player loops (after the last frame the first one comes next)."""

    def __init__(self, path):
        self.frames = {}
        rate = None
        with open(path) as text:
            for line in text:
                if line.startswith("#"):
                    found = re.search(r"framerate:\s*([0-9.]+)", line)
                    rate = float(found.group(1)) if found else rate
                    continue
                fields = line.split()
                if fields:
                    self.frames.setdefault(int(fields[1]), {})[fields[0]] = place(float(fields[2]), float(fields[3]))
        if rate is None:
            raise ValueError(path + ": no '# framerate:' header")
        self.rate = rate
        self.first, self.last = min(self.frames), max(self.frames)
        self.period = (self.last - self.first + 1) / rate
        stays = {}
        for frame in sorted(self.frames):
            for person in self.frames[frame]:
                stays.setdefault(person, [frame, frame])[1] = frame
        # Each person's first and last recording second (a person's rows are consecutive frames).
        self.stays = {person: ((a - self.first) / rate, (b - self.first) / rate) for person, (a, b) in stays.items()}

    def seconds_of_frame(self, frame, loops):
        return (frame - self.first) / self.rate + loops * self.period

    def position(self, person, seconds):
        """Where the person is at recording second `seconds` (between frames, on the line between
        them), or None where the recording does not have it."""
        frame = self.first + (seconds % self.period) * self.rate
        below = math.floor(frame)
        a = self.frames.get(below, {}).get(person)
        b = self.frames.get(below + 1, {}).get(person)
        if a is None or b is None:
            return a or b
        share = frame - below
        return ((1 - share) * a[0] + share * b[0], (1 - share) * a[1] + share * b[1])

    def people_between(self, seconds, came_before, stays_until):
        """The people whose stay in some loop began by `came_before` and lasts until `stays_until`
        (recording seconds)."""
        people = set()
        loop = math.floor(seconds / self.period)
        for person, (start, end) in self.stays.items():
            for k in (loop - 1, loop, loop + 1):
                if start + k * self.period <= came_before and end + k * self.period >= stays_until:
                    people.add(person)
        return people


class PlayedFrames:
    """trajectory_player's messages on /tracked_persons, each matched to the recording's frame
    whose people it carries: the stamps at which it played each recording second. The type
    (spencer_tracking_msgs) is not installed: decoded with the definition the publisher sends."""

    def __init__(self, recording):
        self.recording = recording
        self.played = []  # (stamp, recording seconds)
        self.unmatched = []  # stamps of messages that are no frame of the file
        self.frame, self.loops = None, 0
        self.classes = {}
        self.lock = threading.Lock()
        self.subscriber = rospy.Subscriber("/tracked_persons", rospy.AnyMsg, self.on_message, queue_size=100)

    def decode(self, message):
        header = message._connection_header
        definition = header["message_definition"]
        if definition not in self.classes:
            self.classes[definition] = genpy.dynamic.generate_dynamic(header["type"], definition)[header["type"]]
        return self.classes[definition]().deserialize(message._buff)

    def matches(self, frame, people):
        in_file = self.recording.frames.get(frame, {})
        return set(in_file) == set(people) and all(
            math.hypot(in_file[p][0] - people[p][0], in_file[p][1] - people[p][1]) < 1e-6 for p in people)

    def on_message(self, message):
        decoded = self.decode(message)
        people = {str(t.track_id): (t.pose.pose.position.x, t.pose.pose.position.y) for t in decoded.tracks}
        stamp = decoded.header.stamp.to_sec()
        with self.lock:
            if self.frame is not None:
                following = self.recording.first if self.frame == self.recording.last else self.frame + 1
                if self.matches(following, people):
                    self.loops += following < self.frame
                    self.frame = following
                    self.played.append((stamp, self.recording.seconds_of_frame(following, self.loops)))
                    return
            # The first message, or one that is not the next frame: which frame it is at all.
            found = [f for f in self.recording.frames if people and self.matches(f, people)]
            if len(found) != 1:
                self.unmatched.append(stamp)
                return
            if self.frame is not None and found[0] < self.frame:
                self.loops += 1
            self.frame = found[0]
            self.played.append((stamp, self.recording.seconds_of_frame(self.frame, self.loops)))

    def recording_seconds(self, stamps):
        """The recording seconds played at ROS times `stamps`: between the messages received on
        the line through them, before the first and after the last at the recording's own pace."""
        with self.lock:
            played = numpy.array(self.played)
        stamps = numpy.asarray(stamps, dtype=float)
        seconds = numpy.interp(stamps, played[:, 0], played[:, 1])
        seconds = numpy.where(stamps < played[0, 0], played[0, 1] + (stamps - played[0, 0]), seconds)
        return numpy.where(stamps > played[-1, 0], played[-1, 1] + (stamps - played[-1, 0]), seconds)


class RootTrail:
    """Every root frame body_<id> the crowd publisher put on /tf: (stamp, id, x, y)."""

    def __init__(self):
        self.roots = []
        self.prefix = ROOT_FRAME + "_"

    def on_message(self, message):
        # Called under LoopingTfListener's lock, one message at a time.
        for transform in message.transforms:
            child = transform.child_frame_id
            if child.startswith(self.prefix):
                t = transform.transform.translation
                self.roots.append((transform.header.stamp.to_sec(), child[len(self.prefix):], t.x, t.y))


def render_delay(sample_rate):
    """The delay crowd_publisher walks its people behind their tracks: 1.5 sample intervals or
    its smoothing window, whichever is longer, within 0.1-0.5 s (TrackedCrowd)."""
    smoothing = rospy.get_param("/people_crowd/smoothing")
    return min(max(1.5 / sample_rate, smoothing, 0.1), 0.5)


class TrajectoriesOnScreenTest(unittest.TestCase):
    def test_every_recorded_person_drawn_where_its_track_says(self):
        self.assertTrue(os.path.exists(CORRIDOR), "the shared recording is missing: " + CORRIDOR)
        output = os.path.join(os.environ.get("DRESSED_HUMAN_SCREENSHOTS", tempfile.mkdtemp()), "trajectories")
        os.makedirs(output, exist_ok=True)
        recording = Recording(CORRIDOR)
        config = edited_config(os.path.join(PACKAGE, "rviz", "people.rviz"), os.path.join(output, "view.rviz"),
                               view_changes=VIEW)
        rospy.init_node("test_trajectories_on_screen")
        buffer = tf2_ros.Buffer(rospy.Duration(10.0))
        trail = RootTrail()
        self.listener = LoopingTfListener(buffer, on_message=trail.on_message)
        played = PlayedFrames(recording)
        view = OrbitView.from_config(config)
        arguments = ["file:=" + CORRIDOR, "yaw:=%r" % YAW, "offset_x:=%r" % OFFSET[0], "offset_y:=%r" % OFFSET[1],
                     "skeleton_tf:=true", "rviz_config:=" + config, "rviz_args:=--disable-anti-aliasing"]

        launch = Launch("trajectories.launch", arguments, os.path.join(output, "launch.log"))
        try:
            humans = HumansOnTf(self.listener, bone_frames(open(os.path.join(PACKAGE, "urdf", "human.urdf")).read()))
            wait_for_view(launch, buffer, view, humans, os.path.join(output, "first.png"))
            time.sleep(6.0)  # the display's first frames and skin relief maps
            delay = render_delay(recording.rate)
            started = rospy.get_time()
            results = observe(launch, buffer, view, humans, output, 42.0, 2.5, BODY_MARGIN_METRES, nearest_pixels=True,
                              lag_seconds=LAG_SECONDS, mask_of=drawn_mask)
            ended = rospy.get_time()
            log = launch.output()
        finally:
            launch.stop()

        with open(os.path.join(output, "trail.json"), "w") as f:  # to study a failure again offline
            json.dump({"roots": trail.roots, "played": played.played, "started": started, "ended": ended}, f)
        # From the TF tick the first screenshot was judged by on.
        started = min(started, results[0].get("tf_stamp", started))
        with self.listener.lock:
            roots = [root for root in trail.roots if started <= root[0] <= ended]
        ticks = {}
        for stamp, person, _, _ in roots:
            ticks.setdefault(stamp, set()).add(person)

        # Without the player's frames the recording cannot be read at the humans' stamps.
        self.assertTrue(played.played, "no message of trajectory_player on /tracked_persons is a frame of the file "
                        "placed alike (%d messages that are not)" % len(played.unmatched))

        def check_setup():
            self.check_corridor_in_view(view, results[0]["view"])
            self.assertEqual(played.unmatched, [], "player messages that are no frame of the file placed alike")
            self.assertGreater(len(ticks), 30 * 40 * 0.8, "too few crowd_publisher ticks on /tf (30 Hz) seen")

        # Every check runs and reports (rosunit's XML drops unittest's subTest failures).
        failures = []
        for check in (check_setup, lambda: self.check_screenshots(results, ticks, output),
                      lambda: self.check_roots(recording, played, roots, delay, output),
                      lambda: self.check_people_on_tf(recording, played, ticks, delay, results),
                      lambda: self.assertEqual(package_errors(log), [], "errors in the launch log")):
            try:
                check()
            except AssertionError as error:
                failures.append(str(error))
        if failures:
            self.fail("\n\n".join(failures))

    def check_corridor_in_view(self, view, size):
        """The setup itself: every person in the corridor, standing, projects inside the view."""
        (x0, x1), (y0, y1) = CORRIDOR_PLACED
        corners = numpy.array([[x, y, z] for x in (x0, x1) for y in (y0, y1) for z in (0.0, 1.9)])
        columns, rows, _, _ = view.project(corners, numpy.zeros(3), *size)
        self.assertTrue((columns > 0).all() and (columns < size[0]).all() and (rows > 0).all() and
                        (rows < size[1]).all(), "the corridor is not all in view: %s %s" % (columns, rows))

    def check_screenshots(self, results, ticks, output):
        """Every screenshot: each human on TF drawn in its box, nothing drawn outside them; and
        most of the humans on TF judged, not excused as coming, going or at the edge."""
        failed = [r for r in results if not r["ok"]]
        self.assertGreaterEqual(results[-1]["seconds"], 40.0)
        self.assertEqual([r["shot"] for r in results if "humans" not in r], [], "screenshots without a view")
        present = [len(ticks.get(r["tf_stamp"], ())) for r in results]
        judged = [sum(h["state"] == "in" for h in r["humans"].values()) for r in results]
        rospy.loginfo("trajectories: %d screenshots over %.0f s; humans on TF per shot %s, judged in their box %s "
                      "(%d of %d); %d failed (%s)", len(results), results[-1]["seconds"], present, judged, sum(judged),
                      sum(present), len(failed), output)
        self.assertEqual(failed, [], "%d of %d screenshots do not show each human where TF says it is (or show "
                         "a figure where none is): %s" % (len(failed), len(results), failed))
        self.assertNotIn(0, present, "a screenshot with nobody on TF")
        self.assertGreaterEqual(sum(judged), 0.6 * sum(present), "too few humans judged")

    def check_roots(self, recording, played, roots, delay, output):
        """Each root body_<id> against the recording's person <id> a render delay before its stamp."""
        self.assertTrue(roots, "no root frame on /tf during the observation")
        seconds = played.recording_seconds([stamp - delay for stamp, _, _, _ in roots])
        errors, missing, worst = [], [], {}
        for (stamp, person, x, y), second in zip(roots, seconds):
            expected = recording.position(person, second)
            if expected is None:
                missing.append((round(stamp, 2), person, round(float(second), 2)))
                continue
            errors.append(math.hypot(x - expected[0], y - expected[1]))
            worst[person] = max(worst.get(person, 0.0), errors[-1])
        errors = numpy.array(errors)
        summary = {"render_delay": delay, "samples": len(errors), "median": float(numpy.median(errors)),
                   "p95": float(numpy.percentile(errors, 95)), "max": float(errors.max()),
                   "people_off_by_over_0.5_m": {p: round(e, 2) for p, e in sorted(worst.items()) if e > 0.5},
                   "not_in_recording": missing[:50]}
        with open(os.path.join(output, "roots.json"), "w") as f:
            json.dump(summary, f, indent=1)
        rospy.loginfo("trajectories: roots against the recording %.2f s before: %d samples, median %.3f m, p95 %.3f m, "
                      "max %.3f m (people off by over 0.5 m: %s); %d samples of people the recording lacks then", delay,
                      len(errors), summary["median"], summary["p95"], summary["max"],
                      summary["people_off_by_over_0.5_m"], len(missing))
        self.assertLessEqual(summary["p95"], ROOT_ERROR_P95_METRES, "roots off the recording: %s" % summary)
        # A human on TF whose person the recording lacks at the render time: one that should have left.
        self.assertLessEqual(len(missing), 0.01 * len(roots),
                             "humans where the recording has nobody: %s" % missing[:20])

    def check_people_on_tf(self, recording, played, ticks, delay, results):
        """At every tick the humans on TF are the recording's people at the render time, give or
        take those that came in the last 0.5 s or went in the last 1 s: people leave."""
        stamps = sorted(ticks)
        seconds = played.recording_seconds([stamp - delay for stamp in stamps])
        wrong = []
        for stamp, second in zip(stamps, seconds):
            must = recording.people_between(second, second - APPEAR_SECONDS, second + STAMP_SLACK_SECONDS)
            may = recording.people_between(second, second + STAMP_SLACK_SECONDS, second - LEAVE_SECONDS)
            on_tf = ticks[stamp]
            if not must <= on_tf <= may:
                wrong.append({"stamp": round(stamp, 3), "recording_seconds": round(float(second), 2),
                              "missing": sorted(must - on_tf), "extra": sorted(on_tf - may)})
        shot_seconds = played.recording_seconds([r["tf_stamp"] - delay for r in results])
        counts = [(len(ticks.get(r["tf_stamp"], ())), len(recording.people_between(s, s, s)))
                  for r, s in zip(results, shot_seconds)]
        rospy.loginfo("trajectories: (humans on TF, people in the recording) per shot: %s; %d of %d ticks off", counts,
                      len(wrong), len(stamps))
        self.assertEqual(wrong, [], "ticks whose humans on TF are not the recording's people")


if __name__ == "__main__":
    rostest.rosrun("dressed_human", "human_on_screen_trajectories", TrajectoriesOnScreenTest)
