#!/usr/bin/python3
"""crowd_publisher following the people of other packages (people_inputs.test: people.launch with
rviz:=false, once per input, each in its namespace). The test publishes each type as its real
publisher does: with rospy and message classes genpy generates from msg_layouts/ (the type's name,
md5sum and full definition are the real package's), 2-3 people walking straight lines at 1.2 m/s
at 10 Hz for 7 s, and checks over TF (a tf2_ros buffer holding the whole run), each node's
<ns>/crowd and the nodes' log (read on /rosout: each node's rosgraph_msgs/Log, by node name):

- every type: each person's root frame body_<id> appears within the render delay (0.5 s at most,
  with slack) of the first message, in the message's frame, and walks the track (within 0.3 m of
  where the track was a render delay before each stamp, after the first second); <ns>/crowd lists
  the same ids; pedsim's robot (AgentStates type 2) gets no human; a People name is made an id by
  peopleNameId;
- a person dropped from the messages and everyone after an empty message leave within 1.5 s (and
  in fact as soon as their human has walked to their last sample: not only when their track falls
  silent);
- frame_prefix:=hri_ names the frames hri_body_<id>;
- bad input, each named in the log with the topic, and the others walk on: a NaN position, an id
  twice in one message, a stamp 10 s old (named as 10 s behind the node's clock; on the stamps'
  clock the time went back: every human starts over, and walks on with the next messages),
  stamps going back 3 s, a type that is no people message
  (std_msgs/String on the topic, then the right type again);
- every node is alive at the end.
"""
import math
import os
import re
import sys
import time
import unittest

import rosnode
import rospkg
import rospy
import rostest
import tf2_ros
import yaml
from dressed_human.msg import Crowd
from rosgraph_msgs.msg import Log
from std_msgs.msg import String

PACKAGE = rospkg.RosPack().get_path("dressed_human")
sys.path.insert(0, os.path.join(PACKAGE, "scripts"))
from people_layouts import message_classes, name_id  # noqa: E402
MD5 = {  # msg_layouts/README.md
    "spencer_tracking_msgs/TrackedPersons": "21c0b1a57c4933e68f39aa3802861828",
    "pedsim_msgs/TrackedPersons": "21c0b1a57c4933e68f39aa3802861828",
    "pedsim_msgs/AgentStates": "aa81ea94344df8d81e135b65d4d499b1",
    "people_msgs/People": "18722f4b8db20cc2369740732357847b",
}
UNKNOWN_VARIANCE = 99999.0

RATE = 10.0           # Hz of every input
SPEED = 1.2           # m/s of every walker
DURATION = 7.0        # s of the run
CHANGE = 4.0          # s into the run: spencer drops person 3, pedsim sends empty messages
BAD_FROM, BAD_TO = 1.5, 2.5  # s: person 52 at NaN, person 53 twice
OLD_STAMP_AT = 3.0    # s: one message stamped 10 s before it is sent
BACK_AT = 4.5         # s: stamps go back 3 s once (a recording played again)
ZERO_STAMP_AT = 6.0   # s: one message with a zero stamp (taken as when it came)
NO_FRAME_AT = 6.3     # s: one message without header.frame_id (taken as the last frame)
RENDER_DELAY = None   # s: TrackedCrowd's at 10 Hz, max(1.5 x 0.1 s, ~smoothing) within [0.1, 0.5] (setUpClass)
APPEAR_LIMIT = 0.5 + 0.3  # s after the first message: the largest render delay and slack
TRACK_TOLERANCE = 0.3  # m
SETTLE = 1.0          # s after a track starts before its human must be on it
LEAVE_LIMIT = 1.5     # s after the last sample of a person
WALKED_TO_END_SLACK = 0.25  # s: a human leaves once walked to its last sample (the render delay; silent:
                            # 0.5 s later)


class Walk:
    """A straight walk at SPEED from `start` (m) along `heading` (rad) from the run's start."""

    def __init__(self, start, heading):
        self.start, self.heading = start, heading
        self.t0 = None

    def at(self, t):
        d = SPEED * (t - self.t0)
        return self.start[0] + d * math.cos(self.heading), self.start[1] + d * math.sin(self.heading)

    def velocity(self):
        return SPEED * math.cos(self.heading), SPEED * math.sin(self.heading)


def yaw_quaternion(orientation, yaw):
    orientation.x, orientation.y = 0.0, 0.0
    orientation.z, orientation.w = math.sin(yaw / 2.0), math.cos(yaw / 2.0)


class Input:
    """One input topic and the people.launch under test that reads it (namespace `ns`)."""

    def __init__(self, ns, topic, message_type, frame, walks, prefix=""):
        self.ns, self.topic, self.type, self.frame, self.prefix = ns, topic, message_type, frame, prefix
        self.walks = walks  # {human id: Walk}
        self.classes = message_classes(message_type)
        self.message_class = self.classes[message_type]
        self.publisher = None
        self.sent = []  # (stamp as the node takes it, {human id: (x, y)}) of every message
        self.crowd = []  # <ns>/crowd messages
        self.crowd_subscriber = rospy.Subscriber("/%s/crowd" % ns, Crowd, self.crowd.append, queue_size=1000)

    def node(self):
        return "/%s/people_crowd" % self.ns

    def advertise(self):
        self.publisher = rospy.Publisher(self.topic, self.message_class, queue_size=100)

    def frame_of(self, human_id):
        return self.prefix + "body_" + human_id

    def people(self, elapsed):
        """The ids in the message at `elapsed` s: every walker (overridden per input)."""
        return list(self.walks)

    def send(self, elapsed, now):
        ids = self.people(elapsed)
        positions = {i: self.walks[i].at(now.to_sec()) for i in ids}
        self.publish(now, [(i, positions[i], self.walks[i].velocity()) for i in ids])
        self.sent.append((now.to_sec(), positions))

    def header(self, message, stamp):
        message.header.stamp = stamp
        message.header.frame_id = self.frame

    def publish(self, stamp, persons):
        """persons: (human id, (x, y), (vx, vy)); TrackedPersons as a tracker fills it."""
        message = self.message_class()
        self.header(message, stamp)
        person_class = self.classes[self.type.split("/")[0] + "/TrackedPerson"]
        for human_id, (x, y), (vx, vy) in persons:
            track = person_class()
            track.track_id, track.is_occluded, track.is_matched = int(human_id), False, True
            track.detection_id = 1000 + int(human_id)
            track.age.secs = 3
            track.pose.pose.position.x, track.pose.pose.position.y = x, y
            yaw_quaternion(track.pose.pose.orientation, math.atan2(vy, vx))
            track.pose.covariance = [0.0] * 36
            for i, variance in enumerate([0.01, 0.01, UNKNOWN_VARIANCE, UNKNOWN_VARIANCE, UNKNOWN_VARIANCE, 0.05]):
                track.pose.covariance[7 * i] = variance
            track.twist.twist.linear.x, track.twist.twist.linear.y = vx, vy
            track.twist.covariance = [0.0] * 36
            for i, variance in enumerate([0.02, 0.02, UNKNOWN_VARIANCE, UNKNOWN_VARIANCE, UNKNOWN_VARIANCE,
                                          UNKNOWN_VARIANCE]):
                track.twist.covariance[7 * i] = variance
            message.tracks.append(track)
        self.publisher.publish(message)

    # what was sent
    def first_stamp(self):
        return self.sent[0][0]

    def last_stamp_with(self, human_id):
        return max(stamp for stamp, positions in self.sent if human_id in positions)


class DroppingInput(Input):
    """Person `dropped` is absent from the messages from CHANGE on."""

    def __init__(self, *arguments, dropped, **keywords):
        super().__init__(*arguments, **keywords)
        self.dropped = dropped

    def people(self, elapsed):
        return [i for i in self.walks if elapsed < CHANGE or i != self.dropped]


class EmptiedInput(Input):
    """Empty messages from CHANGE on."""

    def people(self, elapsed):
        return list(self.walks) if elapsed < CHANGE else []


class AgentStatesInput(Input):
    """pedsim_simulator's AgentStates: the agents and the robot (type 2), each with its header."""

    def __init__(self, *arguments, robot, **keywords):
        super().__init__(*arguments, **keywords)
        self.robot = robot  # the robot's id: walks too, but must get no human

    def people(self, elapsed):
        return [i for i in self.walks if i != self.robot]

    def send(self, elapsed, now):
        positions = {i: walk.at(now.to_sec()) for i, walk in self.walks.items()}
        message = self.message_class()
        self.header(message, now)
        for index, (human_id, walk) in enumerate(sorted(self.walks.items())):
            agent = self.classes["pedsim_msgs/AgentState"]()
            self.header(agent, now)
            agent.id = int(human_id)
            agent.type = 2 if human_id == self.robot else index % 2
            agent.social_state = "individual_moving"
            agent.pose.position.x, agent.pose.position.y = positions[human_id]
            yaw_quaternion(agent.pose.orientation, walk.heading)
            agent.twist.linear.x, agent.twist.linear.y = walk.velocity()
            agent.forces.desired_force.x = 1.0
            message.agent_states.append(agent)
        self.publisher.publish(message)
        self.sent.append((now.to_sec(), {i: positions[i] for i in self.people(elapsed)}))


class PeopleInput(Input):
    """people_msgs/People: people by name; their human ids are peopleNameId's."""

    def __init__(self, *arguments, names, **keywords):
        super().__init__(*arguments, **keywords)
        self.names = names  # {human id: name}

    def send(self, elapsed, now):
        message = self.message_class()
        self.header(message, now)
        positions = {}
        for human_id, walk in self.walks.items():
            person = self.classes["people_msgs/Person"]()
            person.name = self.names[human_id]
            positions[human_id] = walk.at(now.to_sec())
            person.position.x, person.position.y = positions[human_id]
            person.velocity.x, person.velocity.y = walk.velocity()
            person.reliability = 0.9
            person.tagnames, person.tags = ["shirt"], ["blue"]
            message.people.append(person)
        self.publisher.publish(message)
        self.sent.append((now.to_sec(), positions))


class BadInput(Input):
    """TrackedPersons with bad sightings: from BAD_FROM to BAD_TO person 52 at NaN and person 53
    twice (the second 5 m off); at OLD_STAMP_AT a message stamped 10 s back (its people where they
    are now: every human starts over there); at ZERO_STAMP_AT a zero stamp and at NO_FRAME_AT no
    frame (the people walk on); at BACK_AT one message stamped 3 s back,
    its people where they were then (a recording played again), then on as before."""

    def send(self, elapsed, now):
        step = round(elapsed * RATE)
        stamp, sample_time = now, now.to_sec()  # the stamp sent, the time the node takes
        if step == round(OLD_STAMP_AT * RATE):
            stamp = now - rospy.Duration(10.0)
        elif step == round(BACK_AT * RATE):
            stamp = now - rospy.Duration(3.0)
            sample_time = stamp.to_sec()
        elif step == round(ZERO_STAMP_AT * RATE):
            stamp = rospy.Time(0)
        positions = {i: walk.at(sample_time) for i, walk in self.walks.items()}
        persons = [(i, positions[i], self.walks[i].velocity()) for i in sorted(self.walks)]
        if BAD_FROM <= elapsed < BAD_TO:
            persons[1] = ("52", (float("nan"), positions["52"][1]), self.walks["52"].velocity())
            x, y = positions["53"]
            persons.append(("53", (x + 5.0, y), self.walks["53"].velocity()))
            del positions["52"]
        frame = self.frame
        if step == round(NO_FRAME_AT * RATE):
            self.frame = ""
        self.publish(stamp, persons)
        self.frame = frame
        self.sent.append((sample_time, positions))


def frames_yaml(buffer):
    return yaml.safe_load(buffer.all_frames_as_yaml()) or {}


class PeopleInputsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        global RENDER_DELAY
        rospy.init_node("test_people_inputs")
        RENDER_DELAY = min(max(1.5 / RATE, rospy.get_param("/spencer/people_crowd/smoothing")), 0.5)
        cls.buffer = tf2_ros.Buffer(rospy.Duration(120.0))
        cls.listener = tf2_ros.TransformListener(cls.buffer)
        cls.log = []
        cls.log_subscriber = rospy.Subscriber("/rosout", Log, cls.log.append, queue_size=1000)
        cls.inputs = {
            "spencer": DroppingInput("spencer", "/spencer_people", "spencer_tracking_msgs/TrackedPersons", "odom",
                                     {"1": Walk((0.0, 0.0), 0.0), "2": Walk((6.0, 2.0), math.pi),
                                      "3": Walk((2.0, -3.0), math.pi / 2)}, dropped="3"),
            "pedsim": EmptiedInput("pedsim", "/pedsim_people", "pedsim_msgs/TrackedPersons", "map",
                                   {"11": Walk((0.0, 10.0), 0.5), "12": Walk((5.0, 12.0), -2.5)}),
            "agents": AgentStatesInput("agents", "/pedsim_agents", "pedsim_msgs/AgentStates", "odom",
                                       {"21": Walk((-5.0, 0.0), -math.pi / 2), "22": Walk((-8.0, -4.0), 0.0),
                                        "29": Walk((-6.0, 3.0), 0.3)}, robot="29"),
            "people": PeopleInput("people", "/people", "people_msgs/People", "map",
                                  {name_id("person-1"): Walk((20.0, 0.0), 1.0), "alice": Walk((24.0, 2.0), 2.5)},
                                  names={name_id("person-1"): "person-1", "alice": "alice"}),
            "hri": Input("hri", "/hri_people", "spencer_tracking_msgs/TrackedPersons", "odom",
                         {"41": Walk((0.0, -10.0), 0.0), "42": Walk((3.0, -12.0), math.pi)}, prefix="hri_"),
            "bad": BadInput("bad", "/bad_people", "spencer_tracking_msgs/TrackedPersons", "odom",
                            {"51": Walk((0.0, 20.0), 0.0), "52": Walk((0.0, 22.0), 0.0), "53": Walk((0.0, 24.0), 0.0)}),
            "unknown": Input("unknown", "/unknown_people", "spencer_tracking_msgs/TrackedPersons", "odom",
                             {"61": Walk((-20.0, 0.0), 0.0), "62": Walk((-20.0, 3.0), 0.0)}),
        }
        for name, people_input in cls.inputs.items():
            if name != "unknown":
                people_input.advertise()
        cls.wait_for("the nodes to subscribe to their topics and publish their crowds", lambda: all(
            (i.publisher is None or i.publisher.get_num_connections() > 0) and i.crowd_subscriber.get_num_connections() > 0
            for i in cls.inputs.values()))
        cls.wait_for("TF and the log of every node", lambda: cls.listener.tf_sub.get_num_connections() >= len(cls.inputs)
                     and cls.log_subscriber.get_num_connections() >= len(cls.inputs))

        # An unknown type on /unknown_people for 1 s, then the right one on it.
        string_publisher = rospy.Publisher("/unknown_people", String, queue_size=10)
        cls.wait_for("/unknown/people_crowd to subscribe", lambda: string_publisher.get_num_connections() > 0)
        for _ in range(int(RATE)):
            string_publisher.publish(String("not people"))
            time.sleep(1.0 / RATE)
        time.sleep(0.3)
        cls.log_before_recovery = list(cls.log)
        string_publisher.unregister()
        cls.inputs["unknown"].advertise()
        cls.unknown_followed = cls.wait_for("/unknown/people_crowd to subscribe to TrackedPersons",
                                            lambda: cls.inputs["unknown"].publisher.get_num_connections() > 0,
                                            timeout=5.0, required=False)

        # The run: every input at 10 Hz.
        start = time.time()
        t0 = rospy.Time.now().to_sec()
        for people_input in cls.inputs.values():
            for walk in people_input.walks.values():
                walk.t0 = t0
        for step in range(int(DURATION * RATE)):
            time.sleep(max(0.0, start + step / RATE - time.time()))
            now = rospy.Time.now()
            for people_input in cls.inputs.values():
                people_input.send(step / RATE, now)
        cls.end = rospy.Time.now().to_sec()
        time.sleep(LEAVE_LIMIT + 0.5)  # the crowds after the last message
        cls.frames = frames_yaml(cls.buffer)

    @classmethod
    def wait_for(cls, what, condition, timeout=30.0, required=True):
        deadline = time.time() + timeout
        while not condition():
            if time.time() > deadline:
                if required:
                    raise AssertionError("no %s within %.0f s" % (what, timeout))
                return False
            time.sleep(0.05)
        return True

    # ------------------------------------------------------------------ helpers
    def log_of(self, node, level, log=None):
        return [entry.msg for entry in (self.log if log is None else log) if entry.name == node and entry.level == level]

    def assertAppearsOnTime(self, people_input, human_id):
        frame = people_input.frame_of(human_id)
        self.assertIn(frame, self.frames, "%s: no frame %s on /tf" % (people_input.ns, frame))
        entry = self.frames[frame]
        self.assertEqual(entry["parent"], people_input.frame, "%s: the parent of %s" % (people_input.ns, frame))
        first = min(stamp for stamp, positions in people_input.sent if human_id in positions)
        appeared = float(entry["oldest_transform"]) - first
        rospy.loginfo("%s: %s appeared %.2f s after its first message", people_input.ns, frame, appeared)
        self.assertLessEqual(appeared, APPEAR_LIMIT, "%s: %s appeared %.2f s after its first message" % (
            people_input.ns, frame, appeared))

    def assertOnTrack(self, people_input, human_id, skip=()):
        """Every 0.1 s from SETTLE after its first message to its last, the root within
        TRACK_TOLERANCE of where the track was RENDER_DELAY before; `skip`: (from, to) times
        relative to the run's start left out."""
        frame = people_input.frame_of(human_id)
        walk = people_input.walks[human_id]
        first = min(stamp for stamp, positions in people_input.sent if human_id in positions)
        last = people_input.last_stamp_with(human_id) + RENDER_DELAY - 0.05
        t = first + SETTLE
        errors = []
        while t <= last:
            if not any(walk.t0 + a <= t < walk.t0 + b for a, b in skip):
                try:
                    translation = self.buffer.lookup_transform(people_input.frame, frame, rospy.Time.from_sec(t)
                                                               ).transform.translation
                except tf2_ros.TransformException as error:
                    self.fail("%s: no %s at %.2f s into the run: %s" % (people_input.ns, frame, t - walk.t0, error))
                x, y = walk.at(t - RENDER_DELAY)
                errors.append((math.hypot(translation.x - x, translation.y - y), t - walk.t0))
            t += 0.1
        self.assertGreater(len(errors), 10, "%s: %s checked too briefly" % (people_input.ns, frame))
        worst = max(errors)
        rospy.loginfo("%s: %s off its track by %.3f m at most (%.1f s into the run), %d times", people_input.ns, frame,
                      worst[0], worst[1], len(errors))
        self.assertLessEqual(worst[0], TRACK_TOLERANCE, "%s: %s %.2f m off its track %.1f s into the run" % (
            people_input.ns, frame, worst[0], worst[1]))

    def crowd_ids(self, people_input, since, until=float("inf")):
        """The ids of each <ns>/crowd message stamped within [since, until)."""
        return [sorted(h.id for h in m.humans) for m in people_input.crowd
                if since <= m.header.stamp.to_sec() < until]

    def assertWalks(self, people_input, ids, until=CHANGE):
        for human_id in ids:
            self.assertAppearsOnTime(people_input, human_id)
            self.assertOnTrack(people_input, human_id)
        listed = self.crowd_ids(people_input, people_input.first_stamp() + SETTLE,
                                people_input.walks[ids[0]].t0 + until)
        self.assertGreater(len(listed), 20, "%s: too few messages on /%s/crowd" % (people_input.ns, people_input.ns))
        for ids_listed in listed:
            self.assertEqual(ids_listed, sorted(ids), "/%s/crowd" % people_input.ns)
        # In world_frame until the first message names its frame, in that from then on.
        frames = {m.header.frame_id for m in people_input.crowd if m.header.stamp.to_sec() > people_input.first_stamp() + 0.2}
        self.assertEqual(frames, {people_input.frame}, "the frames of /%s/crowd" % people_input.ns)

    def assertLeaves(self, people_input, human_id):
        """Gone from <ns>/crowd LEAVE_LIMIT after its last sample, and its frame no longer updated
        once its human walked to that sample."""
        last = people_input.last_stamp_with(human_id)
        frame = people_input.frame_of(human_id)
        before = self.crowd_ids(people_input, last - 1.0, last)
        self.assertTrue(before and all(human_id in ids for ids in before),
                        "%s: %s not listed before it left" % (people_input.ns, human_id))
        after = self.crowd_ids(people_input, last + LEAVE_LIMIT, self.end)
        self.assertTrue(after, "%s: no /%s/crowd message after %s left" % (people_input.ns, people_input.ns, human_id))
        self.assertFalse([ids for ids in after if human_id in ids],
                         "%s: %s still listed %.1f s after its last sample" % (people_input.ns, human_id, LEAVE_LIMIT))
        updated = float(self.frames[frame]["most_recent_transform"]) - last
        rospy.loginfo("%s: %s last updated %.2f s after its last sample", people_input.ns, frame, updated)
        self.assertLessEqual(updated, LEAVE_LIMIT, "%s: %s updated %.2f s after its last sample" % (
            people_input.ns, frame, updated))
        self.assertLessEqual(updated, RENDER_DELAY + WALKED_TO_END_SLACK, "%s: %s updated %.2f s after its last sample: left only when "
                             "its track fell silent, not when walked to its end" % (people_input.ns, frame, updated))

    # ------------------------------------------------------------------ the types
    def test_the_types_are_the_real_ones(self):
        published = dict(rospy.get_published_topics())
        for people_input in self.inputs.values():
            self.assertEqual(people_input.message_class._type, people_input.type)
            self.assertEqual(people_input.message_class._md5sum, MD5[people_input.type])
            self.assertEqual(published.get(people_input.topic), people_input.type, people_input.topic)
        self.assertIn("MSG: pedsim_msgs/TrackedPerson\n", self.inputs["pedsim"].message_class._full_text)

    def test_spencer_tracked_persons_walk(self):
        self.assertWalks(self.inputs["spencer"], ["1", "2", "3"])

    def test_pedsim_tracked_persons_walk(self):
        self.assertWalks(self.inputs["pedsim"], ["11", "12"])

    def test_pedsim_agents_walk_and_the_robot_does_not(self):
        agents = self.inputs["agents"]
        self.assertWalks(agents, ["21", "22"], until=DURATION)
        self.assertNotIn("body_29", self.frames, "pedsim's robot (type 2) walks as a human")
        self.assertFalse([m for m in agents.crowd if any(h.id == "29" for h in m.humans)],
                         "pedsim's robot (type 2) on /agents/crowd")

    def test_people_walk_under_their_name_ids(self):
        people = self.inputs["people"]
        person = [f for f in self.frames if re.fullmatch(r"body_person1x[0-9a-f]{8}", f)]
        self.assertEqual(person, ["body_" + name_id("person-1")], "the frame of 'person-1'")
        self.assertWalks(people, [name_id("person-1"), "alice"], until=DURATION)

    def test_frame_prefix(self):
        hri = self.inputs["hri"]
        self.assertWalks(hri, ["41", "42"], until=DURATION)
        for frame in ["body_41", "body_42"]:
            self.assertNotIn(frame, self.frames, "frame_prefix:=hri_ but %s on /tf" % frame)

    # ------------------------------------------------------------------ people leaving
    def test_a_dropped_person_leaves(self):
        spencer = self.inputs["spencer"]
        self.assertLeaves(spencer, "3")
        for frame in ["body_1", "body_2"]:  # the others walk on
            self.assertGreater(float(self.frames[frame]["most_recent_transform"]), spencer.sent[-1][0], frame)

    def test_an_empty_message_sends_everyone_away(self):
        for human_id in ["11", "12"]:
            self.assertLeaves(self.inputs["pedsim"], human_id)

    # ------------------------------------------------------------------ bad input
    def test_bad_sightings_are_named_and_the_others_walk_on(self):
        bad = self.inputs["bad"]
        warnings = self.log_of(bad.node(), Log.WARN)
        self.assertTrue([w for w in warnings if "/bad_people" in w and "track 52:" in w and "not finite" in w],
                        "no warning naming /bad_people and track 52's NaN; warnings: %s" % warnings)
        self.assertTrue([w for w in warnings if "/bad_people" in w and "track 53 appears twice" in w],
                        "no warning naming /bad_people and track 53 twice; warnings: %s" % warnings)
        # The others walk on through the bad messages (53's second sighting is left out), and
        # again once the stamps have gone back.
        for human_id in ["51", "53"]:
            self.assertAppearsOnTime(bad, human_id)
            self.assertOnTrack(bad, human_id, skip=[(OLD_STAMP_AT, OLD_STAMP_AT + SETTLE + 0.2),
                                                    (BACK_AT, BACK_AT + SETTLE + 0.2)])
            self.assertGreater(float(self.frames["body_" + human_id]["most_recent_transform"]), bad.sent[-1][0])

    def test_a_zero_stamp_and_a_missing_frame_are_named(self):
        warnings = self.log_of(self.inputs["bad"].node(), Log.WARN)
        for said in ("message stamps are zero", "a message without header.frame_id"):
            self.assertTrue([w for w in warnings if "/bad_people" in w and said in w],
                            "no warning naming /bad_people and '%s'; warnings: %s" % (said, warnings))

    def test_an_old_stamp_is_named(self):
        warnings = self.log_of(self.inputs["bad"].node(), Log.WARN)
        self.assertTrue([w for w in warnings if "/bad_people" in w and re.search(r"are 10\.\d s behind this node's clock", w)],
                        "no warning naming /bad_people and a stamp 10 s old; warnings: %s" % warnings)

    def test_stamps_going_back_are_named_and_the_humans_go_on(self):
        bad = self.inputs["bad"]
        warnings = self.log_of(bad.node(), Log.WARN)
        self.assertTrue([w for w in warnings if "/bad_people" in w and re.search(r"time went back (2\.[89]|3\.0)\d* s", w)
                         and "every human starts over" in w],
                        "no warning naming /bad_people and the time going back 3 s; warnings: %s" % warnings)
        t0 = bad.walks["51"].t0
        for human_id in ["51", "53"]:
            listed = self.crowd_ids(bad, t0 + BACK_AT + SETTLE + 0.2, bad.sent[-1][0])
            self.assertTrue(listed and all(human_id in ids for ids in listed),
                            "%s not on /bad/crowd after the time went back" % human_id)

    def test_an_unknown_type_is_named_and_the_right_one_followed_again(self):
        unknown = self.inputs["unknown"]
        errors = [e for e in self.log_of(unknown.node(), Log.ERROR, self.log_before_recovery) if "std_msgs/String" in e]
        self.assertEqual(len(errors), 1, "not one error for 10 std_msgs/String messages: %s" % errors)
        for part in ["'/unknown_people'", "std_msgs/String", "spencer_tracking_msgs/TrackedPersons",
                     "pedsim_msgs/TrackedPersons", "pedsim_msgs/AgentStates", "people_msgs/People"]:
            self.assertIn(part, errors[0])
        self.assertTrue(self.unknown_followed, "/unknown/people_crowd did not subscribe to TrackedPersons on "
                        "/unknown_people after std_msgs/String came on it (roscpp's ShapeShifter keeps the first "
                        "type's md5sum)")
        self.assertWalks(unknown, ["61", "62"], until=DURATION)

    def test_every_node_is_alive(self):
        for people_input in self.inputs.values():
            self.assertTrue(rosnode.rosnode_ping(people_input.node(), max_count=1), people_input.node())


if __name__ == "__main__":
    rostest.rosrun("dressed_human", "people_inputs", PeopleInputsTest)
