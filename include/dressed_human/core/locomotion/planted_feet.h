#pragma once
// Planted feet: the root's travel comes from the feet (their soles: FootSoles). Of all sole
// points the lowest one carries the body: it stays where it touched down while the skeleton
// moves about it, and the body sits so that it is on the ground (z = 0). When another point gets
// lower (the heel of the swinging foot at heel strike, the ball as the heel rises), it takes
// over where it is: nothing jumps, no stance foot slides, no foot goes through the ground.
// The other foot, while it is on the ground too (double support), is held where it touched down:
// place() says by how much the leg must move it (LegIk), and lets go smoothly once it lifts.

#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dressed_human/core/skeleton/foot_sole.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace dressed_human {

class PlantedFeet {
 public:
  // The foot bones (l_ankle, r_ankle) of `skeleton` with `shape` applied.
  PlantedFeet(const Skeleton& skeleton, const BodyShape& shape) : PlantedFeet(FootSoles(skeleton, shape)) {}
  explicit PlantedFeet(FootSoles soles);

  // Starts over: the next place() puts the root's ground projection at `root_xy`.
  void reset(const Eigen::Vector2d& root_xy);

  // The root translation for `pose`, computed with its root translation zero (rotation as wanted),
  // `dt` seconds after the previous call. Allocation-free.
  Eigen::Vector3d place(const SkeletonPose& pose_at_origin, double dt);
  // After place(): the foot that does not carry the body (0 left, 1 right) and the world shift
  // that holds it where it touched down (zero while it is in the air).
  std::size_t otherFoot() const { return isLeft(anchor_) ? 1 : 0; }
  const Eigen::Vector3d& otherFootShift() const { return shift_; }

  // A sole point in the world of `pose` (any root translation).
  Eigen::Vector3d solePoint(const SkeletonPose& pose, std::size_t point) const { return soles_.point(pose, point); }
  std::size_t carryingPoint() const { return anchor_; }
  const FootSoles& soles() const { return soles_; }
  bool isLeft(std::size_t point) const { return soles_.isLeft(point); }

  // A point must get this much lower than the carrying one to take over: feet flat side by side
  // (standing) do not hand the body back and forth.
  static constexpr double kHandOver = 0.001;  // m
  // A sole point this near the ground is on it (the tests' measure of stance too).
  static constexpr double kContactBand = 0.005;  // m
  // Once the held foot lifts, the hold fades over this long (in the air: no slide, no pop).
  static constexpr double kReleaseTime = 0.15;  // s
  // A foot near the ground moving faster than this (or than the walk) is swinging, not landing.
  static constexpr double kLandingSpeed = 0.5;      // m/s
  static constexpr double kSwingClearance = 0.008;  // m: a swinging foot passes at least this high
  void setWalkingSpeed(double speed) { walking_speed_ = speed; }

 private:
  FootSoles soles_;
  std::vector<Eigen::Vector3d> relative_;  // scratch: relative to the root, per sole point
  bool anchored_ = false;
  std::size_t anchor_ = 0;
  Eigen::Vector2d anchor_xy_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d start_xy_ = Eigen::Vector2d::Zero();
  void holdOtherFoot(const Eigen::Vector3d& root, double dt);
  bool held_ = false;  // the other foot is held at held_xy_
  std::size_t held_point_ = 0;
  Eigen::Vector2d held_xy_ = Eigen::Vector2d::Zero();
  double release_ = 0.0;  // 1 while held, fading to 0 after lift-off
  Eigen::Vector3d shift_ = Eigen::Vector3d::Zero();
  Eigen::Vector2d last_low_xy_ = Eigen::Vector2d::Zero();
  double walking_speed_ = 0.0;
};

}  // namespace dressed_human
