#include "dressed_human/core/locomotion/planted_feet.h"

#include <utility>

namespace dressed_human {

PlantedFeet::PlantedFeet(FootSoles soles) : soles_(std::move(soles)), relative_(soles_.pointCount()) {}

void PlantedFeet::reset(const Eigen::Vector2d& root_xy) {
  anchored_ = false;
  start_xy_ = root_xy;
}

Eigen::Vector3d PlantedFeet::place(const SkeletonPose& pose_at_origin, double dt) {
  std::size_t lowest = 0;
  for (std::size_t p = 0; p < relative_.size(); ++p) {
    relative_[p] = solePoint(pose_at_origin, p) - pose_at_origin.root.translation;
    if (relative_[p].z() < relative_[lowest].z()) lowest = p;
  }
  Eigen::Vector2d root_xy;
  if (!anchored_) {
    root_xy = start_xy_;
    anchored_ = true;
    anchor_ = lowest;
    anchor_xy_ = root_xy + relative_[lowest].head<2>();
    held_ = false;
    release_ = 0.0;
    shift_.setZero();
  } else {
    root_xy = anchor_xy_ - relative_[anchor_].head<2>();
    if (lowest != anchor_ && relative_[lowest].z() < relative_[anchor_].z() - kHandOver) {
      // The other foot takes over where it is shown (held, it is shown shifted): the body follows it.
      const bool from_held_foot = isLeft(lowest) != isLeft(anchor_);
      Eigen::Vector2d shown = Eigen::Vector2d::Zero();  // how far the hold moves that foot, now
      if (from_held_foot) {
        shown = held_ ? Eigen::Vector2d(held_xy_ - root_xy - relative_[held_point_].head<2>())
                      : Eigen::Vector2d(shift_.head<2>());
      }
      anchor_ = lowest;
      anchor_xy_ = root_xy + relative_[lowest].head<2>() + shown;
      root_xy = anchor_xy_ - relative_[anchor_].head<2>();
      if (from_held_foot) {
        held_ = false;
        release_ = 0.0;
        shift_.setZero();
      }
    }
  }
  const Eigen::Vector3d root(root_xy.x(), root_xy.y(), -relative_[lowest].z());
  holdOtherFoot(root, dt);
  return root;
}

void PlantedFeet::holdOtherFoot(const Eigen::Vector3d& root, double dt) {
  const std::size_t first = soles_.heel(otherFoot());
  std::size_t low = first;
  for (std::size_t p = first; p < first + soles_.pointsPerFoot(); ++p) {
    if (relative_[p].z() < relative_[low].z()) low = p;
  }
  const auto natural = [&](std::size_t p) { return root + relative_[p]; };
  // A foot that skims the ground fast is swinging through, not landing: it is not held but
  // lifted clear (a slow gait's toe clearance is a few millimetres).
  const double ground_speed = dt > 0.0 ? (natural(low).head<2>() - last_low_xy_).norm() / dt : 0.0;
  last_low_xy_ = natural(low).head<2>();
  const bool landing = ground_speed < std::max(kLandingSpeed, walking_speed_);
  // Held at the foot's lowest point where it is shown (natural place + shift); as the foot rolls,
  // the new lowest point is held where it is shown; lifted, the hold lets go.
  if (held_ && low != held_point_) {
    held_point_ = low;
    held_xy_ = natural(low).head<2>() + shift_.head<2>();
  }
  if (held_ && natural(low).z() > kContactBand) held_ = false;
  if (!held_ && landing && natural(low).z() < kContactBand) {
    held_ = true;
    held_point_ = low;
    held_xy_ = natural(low).head<2>() + shift_.head<2>();
    release_ = 1.0;
  }
  if (held_) {
    shift_ << held_xy_ - natural(held_point_).head<2>(), 0.0;
  } else if (release_ > 0.0) {
    const double remaining = std::max(0.0, release_ - dt / kReleaseTime);
    shift_ *= remaining / release_;
    release_ = remaining;
  } else {
    shift_.setZero();
  }
  if (!held_) shift_.z() = std::max(0.0, kSwingClearance - natural(low).z());
}

}  // namespace dressed_human
