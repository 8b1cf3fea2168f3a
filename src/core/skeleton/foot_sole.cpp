#include "dressed_human/core/skeleton/foot_sole.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dressed_human {
namespace {

constexpr std::array<const char*, 2> kFeet = {"l_ankle", "r_ankle"};

int footBone(const Skeleton& skeleton, std::size_t side) {
  const int bone = skeleton.findBone(kFeet[side]);
  if (bone < 0) throw std::invalid_argument(std::string("the skeleton has no foot bone ") + kFeet[side]);
  return bone;
}

// Down the toe cap's dome, from the last section's bottom to the tip: enough points that the
// foot rolls over it rather than tipping from one to the next.
constexpr int kCapPoints = 4;

}  // namespace

FootSoles::FootSoles(const Skeleton& skeleton, const BodyShape& shape) {
  points_per_foot_ = 3;
  ball_ = 2;
  for (std::size_t side = 0; side < 2; ++side) {
    foot_bone_[side] = footBone(skeleton, side);
    const Bone& foot = skeleton.bone(static_cast<std::size_t>(foot_bone_[side]));
    const Eigen::Vector3d& scale = shape.scale[static_cast<std::size_t>(foot_bone_[side])];
    for (std::size_t k = 0; k < points_per_foot_; ++k) {
      const double along = foot.length * static_cast<double>(k) / static_cast<double>(points_per_foot_ - 1);
      in_foot_.emplace_back(foot.radius * scale.x(), 0.0, along * scale.z());
    }
  }
}

FootSoles::FootSoles(const Skeleton& skeleton, const BodyShape& shape, const BodyDescription& body) {
  for (std::size_t side = 0; side < 2; ++side) {
    foot_bone_[side] = footBone(skeleton, side);
    const auto segment = std::find_if(body.segments.begin(), body.segments.end(),
                                      [&](const SkinSegmentSpec& s) { return s.bone == kFeet[side]; });
    if (segment == body.segments.end() || segment->sections.size() < 2) {
      throw std::invalid_argument("body '" + body.name + "' draws no foot on bone " + kFeet[side]);
    }
    const Eigen::Vector3d& scale = shape.scale[static_cast<std::size_t>(foot_bone_[side])];
    const std::size_t first = in_foot_.size();
    for (const SkinSection& section : segment->sections) {
      in_foot_.emplace_back(section.radius_x * scale.x(), 0.0, section.z * scale.z());
    }
    ball_ = in_foot_.size() - first - 1;
    const SkinSection& last = segment->sections.back();
    for (int k = 1; k <= kCapPoints && segment->distal_cap > 0.0; ++k) {
      const double angle = 0.5 * M_PI * static_cast<double>(k) / kCapPoints;
      in_foot_.emplace_back(last.radius_x * std::cos(angle) * scale.x(), 0.0,
                            (last.z + segment->distal_cap * std::sin(angle)) * scale.z());
    }
    points_per_foot_ = in_foot_.size() - first;
  }
}

double FootSoles::lowest(const SkeletonPose& pose, std::size_t side) const {
  return point(pose, lowestPoint(pose, side)).z();
}

std::size_t FootSoles::lowestPoint(const SkeletonPose& pose, std::size_t side) const {
  std::size_t low = heel(side);
  double low_z = point(pose, low).z();
  for (std::size_t k = heel(side) + 1; k < heel(side) + points_per_foot_; ++k) {
    const double z = point(pose, k).z();
    if (z < low_z) {
      low = k;
      low_z = z;
    }
  }
  return low;
}

double FootSoles::forefoot(const SkeletonPose& pose, std::size_t side) const {
  double low = point(pose, ball(side)).z();
  for (std::size_t p = ball(side) + 1; p < heel(side) + points_per_foot_; ++p) low = std::min(low, point(pose, p).z());
  return low;
}

double FootSoles::flatPitch() const {
  // With the axis level and +x down, a point x below the axis at z along it; heel and ball level
  // once the axis turns toes-down by the angle their depths differ by over their distance.
  const Eigen::Vector3d& heel_point = in_foot_[heel(0)];
  const Eigen::Vector3d& ball_point = in_foot_[ball(0)];
  return -std::atan2(heel_point.x() - ball_point.x(), ball_point.z() - heel_point.z());
}

}  // namespace dressed_human
