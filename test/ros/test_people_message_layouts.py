#!/usr/bin/env python3
"""The people message layouts src/node/people_messages.cpp knows, checked against their .msg texts
(msg_layouts/): genmsg's md5sum of each type must be the constant the .cpp recognises it by, and
the full definition encodeTrackedPersons announces must be genmsg's.

Both sides are read from files, so the test fails if either is wrong: a .msg text that is not the
version publishers use, or a constant mistyped.
Usage: /usr/bin/python3 test_people_message_layouts.py <repository root>   (needs python3-genmsg)
"""
import os
import re
import sys
import unittest

import genmsg
import genmsg.gentools
import genmsg.msg_loader

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", ".."))
SOURCE = os.path.join(ROOT, "src", "node", "people_messages.cpp")
# Debian's std_msgs and geometry_msgs .msg files (ros-std-msgs, ros-geometry-msgs).
SEARCH_PATH = {
    "std_msgs": ["/usr/share/std_msgs/msg"],
    "geometry_msgs": ["/usr/share/geometry_msgs/msg"],
}
for package in ("spencer_tracking_msgs", "pedsim_msgs", "people_msgs"):
    SEARCH_PATH[package] = [os.path.join(ROOT, "msg_layouts", package)]

# The type of each md5 constant of the .cpp.
MD5_CONSTANTS = {
    "kTrackedPersonsMd5": "spencer_tracking_msgs/TrackedPersons",
    "kAgentStatesMd5": "pedsim_msgs/AgentStates",
    "kPeopleMd5": "people_msgs/People",
}


def loaded(message_type):
    context = genmsg.MsgContext.create_default()
    spec = genmsg.msg_loader.load_msg_by_type(context, message_type, SEARCH_PATH)
    genmsg.msg_loader.load_depends(context, spec, SEARCH_PATH)
    return context, spec


def source_text():
    with open(SOURCE, encoding="utf-8") as source:
        return source.read()


class PeopleMessageLayouts(unittest.TestCase):
    def test_each_md5_constant_is_genmsgs_md5_of_its_msg_text(self):
        text = source_text()
        for constant, message_type in MD5_CONSTANTS.items():
            with self.subTest(constant=constant):
                found = re.findall(r'constexpr char %s\[\] = "([0-9a-f]*)";' % constant, text)
                self.assertEqual(len(found), 1, "%s: no single definition of %s" % (SOURCE, constant))
                self.assertEqual(found[0], genmsg.gentools.compute_md5(*loaded(message_type)),
                                 "%s in %s against %s's .msg texts in msg_layouts/" % (constant, SOURCE, message_type))

    def test_embedded_definition_is_genmsgs_full_text(self):
        found = re.findall(r'constexpr char kTrackedPersonsDefinition\[\] = R"definition\((.*?)\)definition";',
                           source_text(), re.DOTALL)
        self.assertEqual(len(found), 1, "%s: no single kTrackedPersonsDefinition raw string" % SOURCE)
        self.assertEqual(found[0], genmsg.gentools.compute_full_text(*loaded("spencer_tracking_msgs/TrackedPersons")))


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
