// libFuzzer target: parseMotionYaml must either return a motion or throw MotionError; a motion it
// returns must evaluate to finite joint angles and root pose (what the node publishes on /tf).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  dressed_human::Motion motion;
  try {
    motion = dressed_human::parseMotionYaml(text, "fuzz.yaml");
  } catch (const dressed_human::MotionError&) {
    return 0;
  }
  dressed_human::MotionEvaluator evaluator(motion);
  dressed_human::JointAngles angles{};
  dressed_human::RigidTransform root;
  for (double time : {0.0, 0.5, 1e4}) {
    evaluator.evaluate(time, angles, root);
    for (double angle : angles) {
      if (!std::isfinite(angle)) std::abort();
    }
    if (!root.translation.allFinite() || !root.rotation.coeffs().allFinite()) std::abort();
  }
  return 0;
}
