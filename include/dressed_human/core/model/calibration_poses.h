#pragma once
// The poses a human's level of detail is calibrated in (HumanModelSettings::calibration_poses):
// a motion's joint angles at evenly spread phases of its period. The display and the scene
// tools take the shipped walk (config/motions/walk.yaml), the motion crowds and demos play, so the
// calibration sees the joints bent as they will be drawn.

#include <cstddef>
#include <string>
#include <vector>

#include "dressed_human/core/motion/motion.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace dressed_human {

constexpr std::size_t kCalibrationPoseCount = 8;

// `count` poses of `motion` at phases (k + 1/2) / count of its period; none for count 0.
std::vector<JointAngles> calibrationPoses(const Motion& motion, std::size_t count = kCalibrationPoseCount);
// The same from a motion file; throws what loadMotionFile throws, naming the file.
std::vector<JointAngles> calibrationPosesFromFile(const std::string& motion_file,
                                                  std::size_t count = kCalibrationPoseCount);

}  // namespace dressed_human
