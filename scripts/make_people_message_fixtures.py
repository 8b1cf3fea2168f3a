#!/usr/bin/env python3
"""Writes test/data/people_messages/*.yaml: one serialized message of each people layout this
package reads (src/node/people_messages.h), made without this package's C++ code.

genmsg reads the .msg texts in msg_layouts/ (with Debian's std_msgs and geometry_msgs), genpy
generates Python message classes from them, and those serialize a message filled below. Each file
holds the type, its md5sum (genpy's), the header, what decodePeople should make of every person,
and the bytes in hex. test/ros/test_people_messages.cpp reads them.

tracked_persons.yaml is filled the way encodeTrackedPersons fills a TrackedPersons message (see
encode_conventions below), so that the test can compare that function's bytes with these;
tracked_persons_tracker.yaml is filled the way spencer's tracker and mocks fill one.

Usage: /usr/bin/python3 scripts/make_people_message_fixtures.py   (genmsg and genpy: Debian's
python3-genmsg, python3-genpy)
"""
import io
import math
import os
import sys

from people_layouts import message_classes, name_id

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
OUTPUT = os.path.join(ROOT, "test", "data", "people_messages")
UNKNOWN_VARIANCE = 99999.0  # spencer's mark of a value its tracker does not estimate
STAMP = (1700000000, 123456789)


def yaw_quaternion(orientation, yaw, scale=1.0):
    orientation.x, orientation.y = 0.0, 0.0
    orientation.z, orientation.w = scale * math.sin(yaw / 2.0), scale * math.cos(yaw / 2.0)


def fill_header(header, frame_id):
    header.stamp.secs, header.stamp.nsecs = STAMP
    header.frame_id = frame_id


# ---------------------------------------------------------------- TrackedPersons
# (track_id, is_occluded, position, velocity, yaw or None for an unknown orientation)
ENCODED_TRACKS = [
    (3, False, (1.5, -2.25, 0.0), (0.8, 0.1, 0.0), 0.7),
    (18446744073709551615, True, (-4.0, 3.5, 0.125), (0.0, -1.2, 0.0), -3.0),  # the largest uint64
    (42, False, (10.0, 0.5, 0.0), (-0.3, 0.4, 0.0), None),
]


def encode_conventions(track, track_id, occluded, position, velocity, yaw):
    """What encodeTrackedPersons writes for a person: a ground truth's small variance (1e-4),
    99999 for what is not known (roll, pitch, an unknown yaw, angular velocity), matched unless
    occluded, no detection id, no age."""
    known = 1e-4
    track.track_id, track.is_occluded, track.is_matched = track_id, occluded, not occluded
    track.pose.pose.position.x, track.pose.pose.position.y, track.pose.pose.position.z = position
    if yaw is None:
        track.pose.pose.orientation.w = 1.0
    else:
        yaw_quaternion(track.pose.pose.orientation, yaw)
    pose_diagonal = [known, known, known, UNKNOWN_VARIANCE, UNKNOWN_VARIANCE,
                     UNKNOWN_VARIANCE if yaw is None else known]
    track.pose.covariance = [pose_diagonal[i // 6] if i % 7 == 0 else 0.0 for i in range(36)]
    track.twist.twist.linear.x, track.twist.twist.linear.y, track.twist.twist.linear.z = velocity
    twist_diagonal = [known, known, known, UNKNOWN_VARIANCE, UNKNOWN_VARIANCE, UNKNOWN_VARIANCE]
    track.twist.covariance = [twist_diagonal[i // 6] if i % 7 == 0 else 0.0 for i in range(36)]


def encoded_tracked_persons():
    classes = message_classes("spencer_tracking_msgs/TrackedPersons")
    message = classes["spencer_tracking_msgs/TrackedPersons"]()
    fill_header(message.header, "odom")
    expected = []
    for track_id, occluded, position, velocity, yaw in ENCODED_TRACKS:
        track = classes["spencer_tracking_msgs/TrackedPerson"]()
        encode_conventions(track, track_id, occluded, position, velocity, yaw)
        message.tracks.append(track)
        expected.append(dict(id=str(track_id), position=position, velocity=velocity, yaw=yaw, occluded=occluded))
    return message, expected


def tracker_tracked_persons():
    """As spencer's tracker and its mocks write them: full covariances, 999999 (the mocks' value)
    or 99999 for what is not estimated, matched or not, ages and detection ids."""
    classes = message_classes("spencer_tracking_msgs/TrackedPersons")
    message = classes["spencer_tracking_msgs/TrackedPersons"]()
    fill_header(message.header, "map")
    # (track_id, occluded, matched, detection_id, position, velocity, yaw, quaternion scale,
    #  yaw variance, yaw expected)
    tracks = [
        (7, False, True, 1234, (0.25, 0.5, 0.0), (1.0, 0.0, 0.0), 1.0, 1.0, 0.05, 1.0),
        (8, False, False, 0, (2.0, -1.0, 0.0), (0.0, 0.5, 0.0), 2.0, 1.0, 999999.0, None),
        (9, True, False, 0, (-3.0, -3.0, 0.0), (0.2, 0.2, 0.0), -1.5, 2.0, 99998.5, -1.5),  # a quaternion of norm 2
    ]
    expected = []
    for track_id, occluded, matched, detection_id, position, velocity, yaw, scale, variance, shown in tracks:
        track = classes["spencer_tracking_msgs/TrackedPerson"]()
        track.track_id, track.is_occluded = track_id, occluded
        track.is_matched, track.detection_id = matched, detection_id
        track.age.secs, track.age.nsecs = 12, 500000000
        track.pose.pose.position.x, track.pose.pose.position.y, track.pose.pose.position.z = position
        yaw_quaternion(track.pose.pose.orientation, yaw, scale)
        # every entry set, so that a reader taking the wrong index would see it
        track.pose.covariance = [0.01 * (i + 1) for i in range(36)]
        track.pose.covariance[35] = variance
        track.twist.twist.linear.x, track.twist.twist.linear.y, track.twist.twist.linear.z = velocity
        track.twist.twist.angular.z = 0.3
        track.twist.covariance = [float(i) for i in range(36)]
        message.tracks.append(track)
        expected.append(dict(id=str(track_id), position=position, velocity=velocity, yaw=shown, occluded=occluded))
    return message, expected


# ---------------------------------------------------------------- AgentStates
def agent_states():
    classes = message_classes("pedsim_msgs/AgentStates")
    message = classes["pedsim_msgs/AgentStates"]()
    fill_header(message.header, "odom")
    # (id, type, social_state, position, velocity, quaternion (x, y, z, w), yaw expected)
    agents = [
        (1, 0, "individual_moving", (2.0, 3.0, 0.0), (0.5, 0.625, 0.0), None, 1.2),
        (99, 2, "standing", (0.0, 0.0, 0.0), (0.25, 0.0, 0.0), None, 0.0),  # the robot: left out
        (1234567890123, 3, "standing", (-7.5, 1.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0), None),
        (5, 1, "group_moving", (4.0, -6.0, 0.0), (-0.75, 0.0, 0.0), None, -2.0),
    ]
    expected = []
    for number, (agent_id, agent_type, social_state, position, velocity, quaternion, yaw) in enumerate(agents):
        agent = classes["pedsim_msgs/AgentState"]()
        fill_header(agent.header, "agent_frame_%d" % number)  # not the message's frame: must be skipped
        agent.id, agent.type, agent.social_state = agent_id, agent_type, social_state
        agent.pose.position.x, agent.pose.position.y, agent.pose.position.z = position
        if quaternion is None:
            yaw_quaternion(agent.pose.orientation, yaw, scale=3.0)  # pedsim's need not be unit
        else:
            orientation = agent.pose.orientation
            orientation.x, orientation.y, orientation.z, orientation.w = quaternion
        agent.twist.linear.x, agent.twist.linear.y, agent.twist.linear.z = velocity
        agent.twist.angular.z = -0.4
        for index, force in enumerate(["desired_force", "obstacle_force", "social_force", "group_coherence_force",
                                       "group_gaze_force", "group_repulsion_force", "random_force"]):
            getattr(agent.forces, force).x = index + 0.5
        message.agent_states.append(agent)
        if agent_type != 2:
            expected.append(dict(id=str(agent_id), position=position, velocity=velocity, yaw=yaw, occluded=False))
    return message, expected


# ---------------------------------------------------------------- People
def people():
    classes = message_classes("people_msgs/People")
    message = classes["people_msgs/People"]()
    fill_header(message.header, "base_link")
    # (name, position, velocity, tagnames, tags)
    persons = [
        ("alice", (1.0, 2.0, 0.0), (0.125, 0.25, 0.0), ["shirt"], ["red"]),
        ("bob-2", (-1.5, 0.75, 0.0), (0.0, -0.5, 0.0), [], []),
        ("", (3.0, 3.0, 0.0), (0.0, 0.0, 0.0), ["a", "b"], ["c", "d"]),
    ]
    expected = []
    for name, position, velocity, tagnames, tags in persons:
        person = classes["people_msgs/Person"]()
        person.name = name
        person.position.x, person.position.y, person.position.z = position
        person.velocity.x, person.velocity.y, person.velocity.z = velocity
        person.reliability, person.tagnames, person.tags = 0.875, tagnames, tags
        message.people.append(person)
        expected.append(dict(id=name_id(name), position=position, velocity=velocity, yaw=None, occluded=False))
    return message, expected


# ---------------------------------------------------------------- output
def yaml_number(value):
    return "null" if value is None else repr(float(value))


def write_fixture(file_name, message, expected):
    buffer = io.BytesIO()
    message.serialize(buffer)
    hex_bytes = buffer.getvalue().hex()
    lines = ["# Made by scripts/make_people_message_fixtures.py (genpy from msg_layouts/); do not edit.",
             "type: %s" % message._type,
             "md5sum: %s" % message._md5sum,
             "stamp: {secs: %d, nsecs: %d}" % STAMP,
             "frame_id: %s" % message.header.frame_id,
             "# what decodePeople should make of it (yaw null: none)",
             "people:"]
    for person in expected:
        lines.append("  - {id: '%s', position: [%s], velocity: [%s], yaw: %s, occluded: %s}" % (
            person["id"], ", ".join(map(yaml_number, person["position"])),
            ", ".join(map(yaml_number, person["velocity"])), yaml_number(person["yaw"]),
            "true" if person["occluded"] else "false"))
    lines.append("bytes: |")
    lines += ["  " + hex_bytes[i:i + 64] for i in range(0, len(hex_bytes), 64)]
    with open(os.path.join(OUTPUT, file_name), "w") as output:
        output.write("\n".join(lines) + "\n")
    print("%s: %s, %d bytes, %d people expected" % (file_name, message._type, len(hex_bytes) // 2, len(expected)))


def main():
    os.makedirs(OUTPUT, exist_ok=True)
    write_fixture("tracked_persons.yaml", *encoded_tracked_persons())
    write_fixture("tracked_persons_tracker.yaml", *tracker_tracked_persons())
    write_fixture("agent_states.yaml", *agent_states())
    write_fixture("people.yaml", *people())
    return 0


if __name__ == "__main__":
    sys.exit(main())
