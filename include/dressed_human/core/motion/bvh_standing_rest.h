#pragma once
// A BVH clip as the retarget reads it: the pelvis at the root and a zero pose that stands. Some
// rigs have neither. Bandai-Namco's captures hang the pelvis ('Hips') below a 'joint_Root' (still,
// or carrying the walk's forward travel as game engines' root motion), and their zero pose is folded (every bone along its parent's x axis: the spine and
// the legs point the same way), so the zero pose gives neither the body's axes nor its height nor
// a twist that a person's segment has. Such a clip is re-expressed, exactly, on a standing frame
// of its own: the same world poses in every frame, from a zero pose that is that frame.

#include <string>
#include <vector>

#include "dressed_human/core/motion/bvh_file.h"
#include "dressed_human/core/motion/mocap_joint_map.h"

namespace dressed_human {

struct StandingRest {
  BvhClip clip;       // the pelvis (map.root) its root; every joint's rotation channels Y X Z
  bool lifted = false;   // the pelvis had joints above it, now dropped (their motion is the pelvis's)
  int rest_frame = -1;   // the frame the zero pose is now; -1: the file's own zero pose stands
};

// `clip`'s subtree at `root`, re-expressed on the zero pose whose world rotations are `rest` (one per
// joint of `clip`): `root` the new root, every joint's rotation channels Y X Z, offsets and end sites
// turned with their joint's rest, and every frame's world poses those of `clip` (rotations times
// the joint's rest inverse).
BvhClip bvhOnZeroPose(const BvhClip& clip, std::size_t root, const std::vector<Eigen::Matrix3d>& rest);

// `clip` as above, or as it is where it needs nothing (its pelvis the root, its zero pose
// standing: head above the pelvis, both ankles below it). Throws JointMapError (naming
// `source_name`) for a clip that stands in no frame.
StandingRest standingRest(const BvhClip& clip, const BvhJointMap& map, const std::string& source_name);

}  // namespace dressed_human
