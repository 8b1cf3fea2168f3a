#pragma once
// The shipped skeleton, default body and walk, as the benchmarks of the core pose them: `count`
// poses over one gait cycle (poses[i] at i / count of the period), built once per process.

#include <string>
#include <vector>

#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"
#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace dressed_human {

inline std::string benchmarkSourcePath(const std::string& relative) {
  return std::string(DRESSED_HUMAN_SOURCE_DIR) + "/" + relative;
}

struct WalkFixture {
  Skeleton skeleton = Skeleton::fromUrdfFile(benchmarkSourcePath("urdf/human.urdf"));
  BodyDescription body = loadBodyDescriptionFile(benchmarkSourcePath("config/bodies/default.yaml"), skeleton);
  std::vector<SkeletonPose> poses;

  explicit WalkFixture(std::size_t count) {
    const ForwardKinematics kinematics(skeleton, body.shape);
    MotionEvaluator walk(loadMotionFile(benchmarkSourcePath("config/motions/walk.yaml")));
    JointAngles angles;
    RigidTransform root;
    poses.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
      walk.evaluate(walk.motion().period * static_cast<double>(i) / static_cast<double>(count), angles, root);
      kinematics.compute(root, angles, poses[i]);
    }
  }
};

// 64 poses of the walk, shared by a benchmark binary's cases.
inline const WalkFixture& walkFixture() {
  static const WalkFixture fixture(64);
  return fixture;
}

}  // namespace dressed_human
