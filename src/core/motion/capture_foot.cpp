#include "dressed_human/core/motion/capture_foot.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace dressed_human {

double tipHeight(const BvhClip& clip, const BvhPose& pose, const ToeTip& tip, std::size_t ankle,
                 const Eigen::Matrix3d& to_ours) {
  return (to_ours * (bvhPointPosition(clip, pose, tip.point) - pose.position[ankle])).z() / tip.rest_length;
}

std::vector<std::size_t> stillestFrames(const std::vector<BvhPose>& poses, std::size_t ankle,
                                        const Eigen::Matrix3d& to_ours) {
  std::vector<std::pair<double, std::size_t>> speed_and_frame;
  for (std::size_t f = 1; f + 1 < poses.size(); ++f) {
    const Eigen::Vector3d moved = to_ours * (poses[f + 1].position[ankle] - poses[f - 1].position[ankle]);
    speed_and_frame.emplace_back(moved.head<2>().norm(), f);
  }
  if (speed_and_frame.empty()) return {};
  const std::size_t still = std::max<std::size_t>(1, speed_and_frame.size() / 10);
  std::nth_element(speed_and_frame.begin(), speed_and_frame.begin() + static_cast<std::ptrdiff_t>(still - 1),
                   speed_and_frame.end());
  std::vector<std::size_t> frames;
  for (std::size_t i = 0; i < still; ++i) frames.push_back(speed_and_frame[i].second);
  return frames;
}

double flatHeight(const BvhClip& clip, const std::vector<BvhPose>& poses, const ToeTip& tip, std::size_t ankle,
                  const Eigen::Matrix3d& to_ours) {
  if (poses.size() < 3) return tip.flat_height;
  std::vector<double> heights;
  for (const std::size_t f : stillestFrames(poses, ankle, to_ours)) {
    heights.push_back(tipHeight(clip, poses[f], tip, ankle, to_ours));
  }
  std::nth_element(heights.begin(), heights.begin() + static_cast<std::ptrdiff_t>(heights.size() / 2), heights.end());
  return heights[heights.size() / 2];
}

Eigen::Vector3d footAim(const BvhClip& clip, const BvhPose& pose, const ToeTip& toe_tip, std::size_t ankle,
                        const Eigen::Matrix3d& to_ours, const OurFoot& foot, double scale) {
  const Eigen::Vector3d line = to_ours * (bvhPointPosition(clip, pose, toe_tip.point) - pose.position[ankle]);
  const Eigen::Vector3d heading(line.x(), line.y(), 0.0);
  const double reach = std::hypot(foot.along, foot.below);
  if (!(toe_tip.rest_length > 1e-9) || heading.norm() < 1e-9 || !(reach > 1e-9)) return line;
  const double wanted =
      foot.tipHeight(foot.flat_pitch) +
      (scale * toe_tip.rest_length) * (tipHeight(clip, pose, toe_tip, ankle, to_ours) - toe_tip.flat_height);
  const double pitch = std::atan2(foot.below, foot.along) + std::asin(std::clamp(wanted / reach, -1.0, 1.0));
  return heading.normalized() * std::cos(pitch) + Eigen::Vector3d(0, 0, std::sin(pitch));
}

Eigen::Matrix3d aimedFoot(const Eigen::Matrix3d& foot, const Eigen::Vector3d& aim, double roll) {
  const Eigen::Matrix3d aimed =
      Eigen::Quaterniond::FromTwoVectors(foot.col(2), aim).normalized().toRotationMatrix() * foot;
  return aimed * Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ());
}

double flatRoll(const std::vector<BvhPose>& poses, std::size_t ankle, const Eigen::Matrix3d& to_ours,
                const std::function<Eigen::Matrix3d(const BvhPose&)>& aimed_foot) {
  std::vector<double> rolls;
  for (const std::size_t f : stillestFrames(poses, ankle, to_ours)) {
    const Eigen::Matrix3d foot = aimed_foot(poses[f]);
    // foot * Rz(a) has the y axis -sin(a) x + cos(a) y: level where tan(a) = y.z / x.z, the sole
    // still facing the way it did.
    if (std::abs(foot(2, 0)) > 1e-9) rolls.push_back(std::atan(foot(2, 1) / foot(2, 0)));
  }
  if (rolls.empty()) return 0.0;
  std::nth_element(rolls.begin(), rolls.begin() + static_cast<std::ptrdiff_t>(rolls.size() / 2), rolls.end());
  return rolls[rolls.size() / 2];
}

}  // namespace dressed_human
