#pragma once
// The soles of the feet: where a foot rests on the ground, as points on the underside of its bone
// in the bone's frame (+x toward the sole, +z from the ankle toward the toes), heel first. Either
// the URDF foot's cylinder (its radius below the axis, from under the ankle to under the bone's
// end) or the drawn foot of a body description (the bottom of each of its sections, then over
// the dome of its toe cap to the tip). A foot stands flat when its heel and ball are level. The
// walker plants them (PlantedFeet), the fit measures them against a capture's floor
// (fit_accuracy.h).

#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace dressed_human {

class FootSoles {
 public:
  // The URDF cylinders of the foot bones (l_ankle, r_ankle) with `shape` applied: heel, mid-foot
  // and ball. Throws std::invalid_argument naming a missing foot bone.
  FootSoles(const Skeleton& skeleton, const BodyShape& shape);
  // The feet as `body` draws them, `shape` applied. Throws std::invalid_argument naming a foot bone
  // the body has no segment for.
  FootSoles(const Skeleton& skeleton, const BodyShape& shape, const BodyDescription& body);

  std::size_t pointsPerFoot() const { return points_per_foot_; }
  std::size_t pointCount() const { return in_foot_.size(); }  // left foot's points first
  std::size_t heel(std::size_t side) const { return side * points_per_foot_; }
  std::size_t ball(std::size_t side) const { return side * points_per_foot_ + ball_; }
  bool isLeft(std::size_t point) const { return point < points_per_foot_; }

  // A sole point in its foot bone's frame.
  const Eigen::Vector3d& inFoot(std::size_t point) const { return in_foot_[point]; }
  // A sole point in the world of `pose`.
  Eigen::Vector3d point(const SkeletonPose& pose, std::size_t point) const {
    const RigidTransform& foot = pose.bone_in_world[static_cast<std::size_t>(foot_bone_[isLeft(point) ? 0 : 1])];
    return foot.translation + foot.rotation * in_foot_[point];
  }
  // The lowest sole point of foot `side` (0 left, 1 right) in `pose`: its height.
  double lowest(const SkeletonPose& pose, std::size_t side) const;
  std::size_t lowestPoint(const SkeletonPose& pose, std::size_t side) const;  // its index
  // The height of the lowest of foot `side`'s ball and the toe cap beyond it (the heel's: point()).
  double forefoot(const SkeletonPose& pose, std::size_t side) const;
  // The pitch of the foot bone's axis (rad, toes up positive) at which the heel and the ball of
  // the left foot are level, the foot not rolled: how the foot stands flat.
  double flatPitch() const;

 private:
  std::array<int, 2> foot_bone_{};        // left, right
  std::vector<Eigen::Vector3d> in_foot_;  // in the foot bone's frame
  std::size_t points_per_foot_ = 0;
  std::size_t ball_ = 0;  // of a foot's points
};

}  // namespace dressed_human
