#include "dressed_human/core/model/calibration_poses.h"

#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"

namespace dressed_human {

std::vector<JointAngles> calibrationPoses(const Motion& motion, std::size_t count) {
  MotionEvaluator evaluator(motion);
  std::vector<JointAngles> poses(count);
  RigidTransform root;
  for (std::size_t k = 0; k < count; ++k) {
    // Half a step in: phase 0 is where a walk's series start, and the tests pose the walk there.
    evaluator.evaluate(motion.period * (static_cast<double>(k) + 0.5) / static_cast<double>(count), poses[k], root);
  }
  return poses;
}

std::vector<JointAngles> calibrationPosesFromFile(const std::string& motion_file, std::size_t count) {
  return calibrationPoses(loadMotionFile(motion_file), count);
}

}  // namespace dressed_human
