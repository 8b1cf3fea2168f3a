#pragma once
// A person's proportions in the URDF itself, so that everything reading robot_description agrees:
// rviz's RobotModel and robot_state_publisher see the joint origins and bone visuals already
// scaled (Eq. 5: a joint at its parent's scaled offset, a bone's visuals scaled by its own factors),
// and the node and the DressedHuman display read the factors back from an element that urdfdom
// ignores:
//
//   <dressed_human_body_shape>
//     <bone name="l_hip" a="0.98" b="0.98" c="1.02"/>   <!-- every bone, Eq. 5 factors -->
//     <bone name="l_pelvis" a="1" b="1" c="1.1" offset="0.03 0 0.01"/>  <!-- BodyShape::offset -->
//   </dressed_human_body_shape>

#include <string>

#include "dressed_human/core/skeleton/skeleton.h"

namespace dressed_human {

// `urdf_xml` (a human URDF without a recorded shape, any suffix) with `shape` applied and
// recorded. Throws SkeletonError for a URDF that already records one (shapes do not stack: shape
// the original) or a factor that is not finite and positive.
std::string shapedUrdf(const std::string& urdf_xml, const BodyShape& shape);

// A crowd human `stature` times the size of `skeleton`, as the crowd publisher walks it and the
// DressedHuman display draws it: the stature it is drawn at (1 within 0.5 % of 1, and for a URDF
// recording a person's proportions of its own, which are not rescaled) and the skeleton at that
// stature (as if its URDF were shaped by it).
double drawnStature(const Skeleton& skeleton, double stature);
Skeleton skeletonAtStature(const Skeleton& skeleton, double stature);

// The shape a URDF records; identity when it records none. Throws SkeletonError naming what is
// wrong with a malformed record (unknown bone, missing or non-positive factor, a bone twice).
BodyShape urdfBodyShape(const std::string& urdf_xml);

}  // namespace dressed_human
