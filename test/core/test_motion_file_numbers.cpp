// Issue 23: whatever numbers a motion file holds (finite, non-finite, huge, tiny), either the file
// is rejected with a MotionError or every value the node would publish on /tf is finite and where
// a person can be. Randomized over many files: each number of a valid motion drawn from a pool of
// ordinary and hostile values.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/skeleton/skeleton.h"

namespace dressed_human {
namespace {

const std::vector<std::string> kHostileNumbers = {
    "0",         "1e-300", "-1e-300", "4.9e-324", "1e300", "-1e300", "1e308", "-1.7976931348623157e308",
    ".nan",      ".inf",   "-.inf",   "1e5",      "-1e5",  "0.1",    "60",    "60.000001",
    "0.0999999", "12.5",   "-12.6",   "3.14159",  "7",     "-7",     "1e-9"};

// The numbers of `text` (after a ':' or '[' or ','), each replaced with probability `rate`.
std::string mutateNumbers(const std::string& text, std::mt19937& rng, double rate) {
  std::uniform_real_distribution<double> chance(0.0, 1.0);
  std::uniform_int_distribution<std::size_t> pick(0, kHostileNumbers.size() - 1);
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    const bool starts_number = (std::isdigit(static_cast<unsigned char>(c)) || c == '-') && i > 0 &&
                               (text[i - 1] == ' ' || text[i - 1] == '[');
    if (!starts_number) {
      out += c;
      ++i;
      continue;
    }
    std::size_t end = i + 1;
    while (end < text.size() && std::string("0123456789.eE+-").find(text[end]) != std::string::npos) ++end;
    out += chance(rng) < rate ? kHostileNumbers[pick(rng)] : text.substr(i, end - i);
    i = end;
  }
  return out;
}

bool finiteTransform(const RigidTransform& transform) {
  return transform.translation.allFinite() && transform.rotation.coeffs().allFinite() &&
         std::abs(transform.rotation.norm() - 1.0) < 1e-6;
}

TEST(MotionFileNumbers, NoHostileNumberReachesTheSkeletonOrTheRoot) {
  const std::string source = DRESSED_HUMAN_SOURCE_DIR;
  const Skeleton skeleton = Skeleton::fromUrdfFile(source + "/urdf/human.urdf");
  const ForwardKinematics kinematics(skeleton);
  std::ostringstream walk_text;
  writeMotionYaml(loadMotionFile(source + "/config/motions/walk.yaml"), walk_text);
  std::mt19937 rng(23);
  int accepted = 0, rejected = 0;
  for (int file = 0; file < 400; ++file) {
    const double rate = file < 200 ? 0.002 : 0.02;  // one or two numbers changed, then many
    const std::string text = mutateNumbers(walk_text.str(), rng, rate);
    Motion motion;
    try {
      motion = parseMotionYaml(text, "random.yaml");
    } catch (const MotionError&) {
      ++rejected;
      continue;
    }
    ++accepted;
    MotionEvaluator evaluator(motion);
    JointAngles angles{};
    RigidTransform root;
    SkeletonPose pose;
    for (double time : {0.0, 0.37, 1.0, 59.9, 3600.0, 86400.0 * 7}) {
      evaluator.evaluate(time, angles, root);
      kinematics.compute(root, angles, pose);
      for (double angle : angles) ASSERT_TRUE(std::isfinite(angle)) << "file " << file << " at " << time << " s";
      ASSERT_TRUE(finiteTransform(root)) << "file " << file << " at " << time << " s";
      // Where a person can be: forward speed times time, plus the series' bound of 10 m.
      ASSERT_LE(std::abs(root.translation.x()), MotionLimits::kMaxForwardSpeed * time + MotionLimits::kMaxTranslation);
      ASSERT_LE(root.translation.tail<2>().norm(), 2.0 * MotionLimits::kMaxTranslation);
      for (const RigidTransform& bone : pose.bone_in_world) ASSERT_TRUE(finiteTransform(bone)) << "file " << file;
      for (const RigidTransform& joint : pose.dof_transforms) ASSERT_TRUE(finiteTransform(joint)) << "file " << file;
    }
  }
  // Both branches ran: the test says something about accepted files, and hostile ones are caught.
  EXPECT_GT(accepted, 40);
  EXPECT_GT(rejected, 100);
  std::cout << accepted << " files accepted and posed, " << rejected << " rejected\n";
}

}  // namespace
}  // namespace dressed_human
