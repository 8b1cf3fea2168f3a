"""The people messages of other packages as genpy classes made from msg_layouts/ (their real type
names, md5sums and full definitions, without those packages), and peopleNameId written again in
Python: for the fixture script and the rostests that publish as the real publishers do."""
import functools
import os

import genmsg
import genmsg.gentools
import genmsg.msg_loader
import genpy.dynamic

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
LAYOUTS = os.path.join(ROOT, "msg_layouts")
# pedsim_msgs/TrackedPersons.msg and TrackedPerson.msg are spencer's byte for byte
# (msg_layouts/README.md): found for pedsim_msgs in spencer's directory.
SEARCH_PATH = {
    "std_msgs": ["/usr/share/std_msgs/msg"],
    "geometry_msgs": ["/usr/share/geometry_msgs/msg"],
    "spencer_tracking_msgs": [os.path.join(LAYOUTS, "spencer_tracking_msgs")],
    "pedsim_msgs": [os.path.join(LAYOUTS, "pedsim_msgs"), os.path.join(LAYOUTS, "spencer_tracking_msgs")],
    "people_msgs": [os.path.join(LAYOUTS, "people_msgs")],
}


@functools.lru_cache(maxsize=None)
def message_classes(message_type):
    """genpy's classes for message_type and every type it holds, by type name."""
    context = genmsg.MsgContext.create_default()
    spec = genmsg.msg_loader.load_msg_by_type(context, message_type, SEARCH_PATH)
    genmsg.msg_loader.load_depends(context, spec, SEARCH_PATH)
    return genpy.dynamic.generate_dynamic(message_type, genmsg.gentools.compute_full_text(context, spec))


def name_id(name):
    """peopleNameId (src/node/people_messages.cpp) written again, as the tests' expectation: the
    letters and digits, and where that changed the name (or it ends like a hash), 'x' and its
    32-bit FNV-1a in hex."""
    kept = "".join(c for c in name if c.isascii() and c.isalnum())
    looks_hashed = len(kept) >= 9 and kept[-9] == "x" and all(c in "0123456789abcdef" for c in kept[-8:])
    if kept and kept == name and not looks_hashed:
        return kept
    value = 0x811C9DC5
    for byte in name.encode("utf-8"):
        value = ((value ^ byte) * 0x01000193) & 0xFFFFFFFF
    return "%sx%08x" % (kept, value)
