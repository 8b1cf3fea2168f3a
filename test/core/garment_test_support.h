// Shared set-up of the garment tests: skeleton, default body, walk, outfits.
#pragma once

#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/garments/garment.h"
#include "dressed_human/core/garments/garment_file.h"
#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"

#include <string>
#include <vector>

namespace dressed_human {
namespace garment_test {

inline std::string sourcePath(const std::string& relative) {
  return std::string(DRESSED_HUMAN_SOURCE_DIR) + "/" + relative;
}

inline const Skeleton& skeleton() {
  static const Skeleton s = Skeleton::fromUrdfFile(sourcePath("urdf/human.urdf"));
  return s;
}

inline const BodyDescription& body() {
  static const BodyDescription b = loadBodyDescriptionFile(sourcePath("config/bodies/default.yaml"), skeleton());
  return b;
}

inline GarmentDescription garmentFile(const std::string& name) {
  return loadGarmentFile(sourcePath("config/garments/" + name + ".yaml"), skeleton());
}

// The three outfits of SPEC §3.
inline std::vector<std::pair<std::string, std::vector<std::string>>> outfits() {
  return {{"one_piece", {"one_piece"}}, {"jacket_skirt", {"jacket", "skirt"}}, {"jacket_pants", {"jacket", "pants"}}};
}

// `count` poses evenly over one walk cycle (with the default body's shape).
// `count` poses of a motion file (relative to the source tree) at phases k / count of its period.
inline std::vector<SkeletonPose> motionPoses(const std::string& file, int count, const BodyShape& shape) {
  MotionEvaluator evaluator(loadMotionFile(sourcePath(file)));
  ForwardKinematics fk(skeleton(), shape);
  std::vector<SkeletonPose> poses(static_cast<std::size_t>(count));
  const double period = evaluator.motion().period;
  for (int k = 0; k < count; ++k) {
    JointAngles angles{};
    RigidTransform root;
    evaluator.evaluate(period * k / count, angles, root);
    fk.compute(root, angles, poses[static_cast<std::size_t>(k)]);
  }
  return poses;
}

inline std::vector<SkeletonPose> walkPoses(int count, const BodyShape& shape) {
  return motionPoses("config/motions/walk.yaml", count, shape);
}

}  // namespace garment_test
}  // namespace dressed_human
