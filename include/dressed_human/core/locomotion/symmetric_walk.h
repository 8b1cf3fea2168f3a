#pragma once
// A walk whose two sides are one step: the walk averaged with its own mirror image half a cycle
// later (left and right swapped, reflected through the sagittal plane). One captured person limps
// a little (CMU 02_01: the left foot leaves the ground 6 % of a cycle earlier than the right),
// and the changes with speed come from normative curves of one side, applied to both; a walker
// in a scene walks the person's gait without the one subject's asymmetry.

#include "dressed_human/core/motion/motion.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace dressed_human {

// `walk_in_cycles`: every series of period 1 (SpeedGait's walk in cycles). The mirror of each
// DOF is the same DOF of the "l_"/"r_" partner joint (a joint without a prefix is its own), its
// sign found by moving both joints of the unshaped skeleton and comparing the reflected motion of
// their bones. Throws LocomotionError when the skeleton is not left-right symmetric at rest or a
// DOF has no mirror image.
Motion symmetricWalk(const Motion& walk_in_cycles, const Skeleton& skeleton);

}  // namespace dressed_human
