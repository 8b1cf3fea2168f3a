#pragma once
// An OpenSim motion on its model as a BVH clip: one BVH joint per model joint, named by the body
// it moves, with the model's forward kinematics in its channels. Fitting then treats it as any
// skeleton capture: the body's proportions come from the model's joint layout (its zero pose is
// the rest pose), the reference joint positions and feet from the model's own kinematics,
// including the knee's rolling translation.

#include <string>
#include <vector>

#include "dressed_human/core/motion/bvh_file.h"
#include "dressed_human/core/motion/opensim_model.h"
#include "dressed_human/core/motion/opensim_motion_file.h"

namespace dressed_human {

// Rotational coordinates from degrees when the table says inDegrees=yes; a coordinate the table
// lacks keeps the model's default. Throws OpenSimModelError naming the source when the table has
// none of the model's coordinates, its times are not evenly spaced (within 1 %), the model has
// no joint or several joints on the ground, or a joint's frames are turned in the zero pose (a
// rest pose a BVH offset cannot carry).
BvhClip openSimMotionClip(const OpenSimModel& model, const OpenSimTable& table, const std::string& source_name);

// A generic model's size for a motion computed on a scaled one, when that model is not at hand:
// the uniform factor that puts the resting foot where the model's default pose puts it above the
// floor (y = 0, where OpenSim labs put it). With the pelvis height p, the lowest body origin d
// below the pelvis on the unscaled model and its height h0 in the default pose, p + s d = s h0 in
// every frame a foot rests (moves up or down under 5 cm/s); s is their median. Not estimated
// (factor 1, `why` says so) without a vertical root coordinate in the motion, without ten resting
// frames, for a default pose not standing on the floor, or for a factor outside [0.7, 1.4] (the
// floor is then elsewhere).
struct OpenSimScale {
  double factor = 1.0;
  bool estimated = false;
  std::string why;
};
OpenSimScale estimateOpenSimScale(const OpenSimModel& model, const OpenSimTable& table);

}  // namespace dressed_human
