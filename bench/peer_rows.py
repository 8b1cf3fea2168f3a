#!/usr/bin/python3
"""The crowd peer's input at the places of bench/crowd_scaling.py's humans: spencer_tracking_msgs/
TrackedPersons, one message for every person at RATE Hz in frame `world`, each person on a
treadmill (fixed position, facing +x, walking at 1.2 m/s so that the walking-man animation plays),
as ../shared/peers/spencer/publish_persons.py publishes them, but in the rows our humans stand in.
usage: peer_rows.py RATE X,Y [X,Y ...]   (source the peer workspace's devel/setup.bash first)"""
import sys

import rospy
from spencer_tracking_msgs.msg import TrackedPerson, TrackedPersons

rate_hz = float(sys.argv[1])
places = [tuple(float(v) for v in place.split(",")) for place in sys.argv[2:]]
rospy.init_node("peer_rows", anonymous=True)
publisher = rospy.Publisher("/tracked_persons", TrackedPersons, queue_size=2)
message = TrackedPersons()
message.header.frame_id = "world"
for i, (x, y) in enumerate(places):
    person = TrackedPerson(track_id=i, is_matched=True, age=rospy.Duration(5))
    person.pose.pose.position.x = x
    person.pose.pose.position.y = y
    person.pose.pose.orientation.w = 1.0
    person.twist.twist.linear.x = 1.2
    message.tracks.append(person)
rate = rospy.Rate(rate_hz)
while not rospy.is_shutdown():
    message.header.stamp = rospy.Time.now()
    publisher.publish(message)
    rate.sleep()
