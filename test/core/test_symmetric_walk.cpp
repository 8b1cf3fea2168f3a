// The walker's gait has one step for both sides (issue 39): each half cycle the mirror image of
// the other, whatever the capture's own asymmetry; a skeleton whose sides differ is refused.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "dressed_human/core/locomotion/symmetric_walk.h"
#include "locomotion_test_support.h"

namespace dressed_human {
namespace {

using namespace locomotion_test;

// The farthest any joint, or any point of the drawn soles, is from the mirror image of its
// partner half a cycle later, over a cycle (m).
double mirrorMismatch(const Motion& motion) {
  const Skeleton& s = skeleton();
  const ForwardKinematics kinematics(s);
  const FootSoles feet = soles();
  MotionEvaluator evaluator(motion);
  const auto posed = [&](double phase) {
    JointAngles angles;
    RigidTransform root;
    evaluator.evaluate(phase, angles, root);
    SkeletonPose pose;
    kinematics.compute({Eigen::Vector3d::Zero(), root.rotation}, angles, pose);
    return pose;
  };
  const auto reflected = [](const Eigen::Vector3d& v) { return Eigen::Vector3d(v.x(), -v.y(), v.z()); };
  const auto partner = [&](const std::string& name) {
    if (name.rfind("l_", 0) == 0) return "r_" + name.substr(2);
    if (name.rfind("r_", 0) == 0) return "l_" + name.substr(2);
    return name;
  };
  double worst = 0.0;
  for (int i = 0; i < 40; ++i) {
    const SkeletonPose now = posed(i / 40.0), later = posed(i / 40.0 + 0.5);
    for (std::size_t b = 0; b < s.bones().size(); ++b) {
      const auto m = static_cast<std::size_t>(s.findBone(partner(s.bone(b).name)));
      worst =
          std::max(worst, (reflected(now.bone_in_world[b].translation) - later.bone_in_world[m].translation).norm());
    }
    for (std::size_t k = 0; k < feet.pointsPerFoot(); ++k) {
      const std::size_t left = feet.heel(0) + k, right = feet.heel(1) + k;
      worst = std::max(worst, (reflected(feet.point(now, left)) - feet.point(later, right)).norm());
      worst = std::max(worst, (reflected(feet.point(now, right)) - feet.point(later, left)).norm());
    }
  }
  return worst;
}

TEST(SymmetricWalk, EachHalfCycleIsTheMirrorImageOfTheOther) {
  const Motion captured = walkInCycles(walk());
  // The capture is one person's: its sides differ by centimetres (else this test proves nothing).
  EXPECT_GT(mirrorMismatch(captured), 0.02);
  EXPECT_LT(mirrorMismatch(symmetricWalk(captured, skeleton())), 1e-6);
}

TEST(SymmetricWalk, ASkeletonWhoseSidesDifferIsRefusedByName) {
  std::ifstream file(sourcePath("urdf/human.urdf"));
  std::stringstream text;
  text << file.rdbuf();
  std::string urdf = text.str();
  const std::string right_hip = "<origin xyz=\"0.0 0.0 0.108166538264\" rpy=\"-0.982793723247 0.0 0.0\"/>";
  const std::size_t at = urdf.find(right_hip);
  ASSERT_NE(at, std::string::npos);
  urdf.replace(at, right_hip.size(), "<origin xyz=\"0.0 0.0 0.13\" rpy=\"-0.982793723247 0.0 0.0\"/>");
  try {
    symmetricWalk(walkInCycles(walk()), Skeleton::fromUrdf(urdf));
    FAIL() << "a skeleton with one hip wider than the other was taken as symmetric";
  } catch (const LocomotionError& error) {
    EXPECT_NE(std::string(error.what()).find("r_hip"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace dressed_human
