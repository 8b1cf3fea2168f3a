#pragma once
// The captured person's proportions as Eq. 5 shape factors of our skeleton, read from the
// capture's rest pose (BVH OFFSETs), so that our skeleton driven by the fitted motion puts its
// joints where the capture's were, not only bends them by the same angles.
//
// Per bone, c = the source segment's length / our bone's length: joint to joint where both ends
// are mapped (thigh: hip to knee); for the foot, ankle to the farthest point below it (toe tip).
// The fixed bones take the widths: c of the hip bones makes our hip joints as far apart as the
// source's, c of the clavicles our shoulder joints. The other bones (head, hands, unmapped ones)
// and a, b (thickness) of every bone take the overall factor: the mean c of the limbs.
//
// Eq. 5 scales lengths along our bones; it cannot move a joint across them. Where a capture's
// skeleton is laid out differently (CMU's hip joints sit 3.5 cm in front of its lumbar joint, ours
// straight below; its shoulders 2 cm behind our clavicles' ends), the hip bones and clavicles
// move by BodyShape::offset so that the middle of each pair sits where the capture's does,
// relative to the spine joint below it.

#include <array>
#include <string>

#include "dressed_human/core/motion/bvh_file.h"
#include "dressed_human/core/motion/mocap_joint_map.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/skeleton/skeleton.h"

namespace dressed_human {

struct BodyProportions {
  BodyShape shape;
  double overall = 1.0;  // the limbs' mean c
  // Metres: the source segment of each measured bone (the width between the left and right joint
  // for the hip bones and clavicles); 0 where the bone took the overall factor.
  std::array<double, kBoneCount> source_length{};
};

// `metres_per_unit`: the capture's length unit (capture_units.h). Throws MotionError naming the
// segment for a mapped bone of zero length at rest, or a factor outside [kMinShapeScale,
// kMaxShapeScale] (a source that is no human at this unit).
BodyProportions fitBodyProportions(const BvhClip& clip, const BvhJointMap& map, const Skeleton& skeleton,
                                   double metres_per_unit, const std::string& source_name);

}  // namespace dressed_human
