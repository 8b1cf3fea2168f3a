#!/usr/bin/env python3
"""Keep an OpenSim 4 model's joints (what fit_motion's forward kinematics reads) and drop the
rest (muscles, geometry, inertia, markers, comments), so that a 576 KB model ships as a few KB.

  /usr/bin/python3 scripts/trim_opensim_model.py MODEL.osim OUT.osim "source note"

config/opensim/gait2392_joints.osim was made from opensim-org/opensim-models
@20a888b9655e73fb84963d6e03eee3752cf6074b, Models/Gait2392_Simbody/gait2392_thelen2003muscle.osim
(Delp et al. 1990, Anderson and Pandy 1999; CC BY 3.0, credits kept in the file).
"""
import sys
import xml.etree.ElementTree as ET

KEEP_IN_JOINT = {"socket_parent_frame", "socket_child_frame", "coordinates", "frames", "SpatialTransform"}
KEEP_IN_COORDINATE = {"default_value", "range"}
KEEP_IN_FRAME = {"socket_parent", "translation", "orientation"}


def prune(element, keep):
    for child in list(element):
        if child.tag not in keep:
            element.remove(child)


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    source, target, note = sys.argv[1:]
    tree = ET.parse(source)
    root = tree.getroot()
    model = root.find("Model")
    if model is None:
        sys.exit(source + ": no <Model> element")
    for child in list(model):
        if child.tag not in ("credits", "publications", "length_units", "BodySet", "JointSet"):
            model.remove(child)
    for body in model.iter("Body"):
        for child in list(body):
            body.remove(child)
        body.text = None
    for joint in model.find("JointSet").find("objects"):
        prune(joint, KEEP_IN_JOINT)
        for coordinate in joint.iter("Coordinate"):
            prune(coordinate, KEEP_IN_COORDINATE)
        for frame in joint.iter("PhysicalOffsetFrame"):
            prune(frame, KEEP_IN_FRAME)
    ET.indent(tree, space="  ")
    with open(target, "w") as out:
        out.write('<?xml version="1.0" encoding="UTF-8" ?>\n<!-- ' + note + ' -->\n')
        out.write(ET.tostring(root, encoding="unicode"))
        out.write("\n")


if __name__ == "__main__":
    main()
