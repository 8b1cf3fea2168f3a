#include "dressed_human/core/locomotion/walker.h"

#include <algorithm>
#include <cmath>

namespace dressed_human {
namespace {

constexpr double kGravity = 9.81;
// Standing is never a frozen pose: the trunk sways and breathes a little (~4 s cycle).
constexpr double kIdleRate = 0.25;     // Hz
constexpr double kIdleSway = 0.015;    // rad, the waist side to side
constexpr double kIdleBreath = 0.008;  // rad, the torso forward and back
// Of the slowest gait's speed: from here down to standing the steps shrink (and the cadence
// stays); above it they keep the slowest gait's length and only the cadence drops.
constexpr double kFullStrides = 0.12;
constexpr double kStrideChange = 0.4;  // s from standing to full steps and back: about a step
// A foot flat on the ground does not spin with the body: the hip twists under a turn instead, up
// to a hip's range of rotation, and unwinds once the foot is in the air.
constexpr double kMaxStanceTwist = 0.5;   // rad
constexpr double kTwistUnwindTime = 0.1;  // s
// The foot is flat (and does not turn) while its heel and its forefoot are this near the ground;
// the skin about a sole point reaches a few millimetres lower than the point (FootSoles).
constexpr double kFlatBand = 0.01;  // m

}  // namespace

Walker::Walker(const Skeleton& skeleton, const BodyShape& shape, SpeedGait gait, WalkerSettings settings)
    : gait_(std::move(gait)),
      settings_(settings),
      kinematics_(skeleton, shape),
      feet_(gait_.soles()),
      leg_ik_(kinematics_),
      follower_(settings.route) {
  waist_ =
      static_cast<std::size_t>(skeleton.findJoint("waist")) * kDofsPerJoint + static_cast<std::size_t>(JointAxis::kX);
  torso_ =
      static_cast<std::size_t>(skeleton.findJoint("torso")) * kDofsPerJoint + static_cast<std::size_t>(JointAxis::kY);
}

void Walker::place(const Eigen::Vector2d& position, double heading, double phase, double speed) {
  position_ = position;
  heading_ = heading;
  phase_ = phase;
  speed_ = std::clamp(speed, 0.0, WalkerSettings::kMaxSpeed);
  stride_ = speed_ > 0.0 ? 1.0 : 0.0;
  stance_twist_ = {};
  carrying_foot_flat_ = false;
  feet_.reset(position);
}

void Walker::followRoute(Route route) {
  driven_.reset();
  follower_.setRoute(std::move(route));
}

void Walker::drive(double speed, double turn_rate) {
  driven_ = std::make_pair(std::clamp(speed, 0.0, WalkerSettings::kMaxSpeed),
                           std::clamp(turn_rate, -settings_.route.max_turn_rate, settings_.route.max_turn_rate));
}

void Walker::step(double dt, JointAngles& angles, SkeletonPose& pose) {
  dt = std::max(dt, 0.0);
  double wanted_speed = 0.0;
  double wanted_turn = 0.0;
  if (driven_) {
    wanted_speed = driven_->first;
    wanted_turn = driven_->second;
  } else if (follower_.hasRoute()) {
    const RouteFollower::Steering steering = follower_.steer(position_, heading_, speed_);
    wanted_speed = follower_.arrived() ? 0.0 : std::min(cruise_speed_, steering.speed_limit);
    wanted_turn = steering.turn_rate;
  }
  wanted_speed = std::clamp(wanted_speed, 0.0, WalkerSettings::kMaxSpeed);
  speed_ += std::clamp(wanted_speed - speed_, -settings_.acceleration * dt, settings_.acceleration * dt);
  turn_rate_ = wanted_turn;
  heading_ = std::remainder(heading_ + turn_rate_ * dt, 2.0 * M_PI);
  const double turned = turn_rate_ * dt;
  // A lean that follows the centripetal acceleration, smoothly: toward the inside of the turn.
  const double wanted_lean = -settings_.lean * std::atan(speed_ * turn_rate_ / kGravity);
  lean_ += (wanted_lean - lean_) * (1.0 - std::exp(-dt / settings_.lean_time));

  // Below the slowest gait a person takes the slowest gait's steps more slowly, which the planted
  // feet turn into the speed; only near standing do the steps shrink too. (Shrinking the steps
  // at the slowest gait's cadence carried the body backwards below 0.4 m/s: the swing foot,
  // barely lifted, took over as the lowest point mid-swing.)
  // The steps open and close over kStrideChange seconds, however fast the speed comes and goes:
  // legs snapping together in one frame would move the body by half a step.
  walking_ = std::clamp(speed_ / gait_.slowestSpeed(), 0.0, 1.0);
  const double wanted_stride = std::clamp(walking_ / kFullStrides, 0.0, 1.0);
  stride_ += std::clamp(wanted_stride - stride_, -dt / kStrideChange, dt / kStrideChange);
  // Above the fastest gait the same steps come faster: a person hurrying (a tracked pedestrian
  // at 2.5 m/s) is followed rather than left behind at the gait table's top speed.
  const double hurry = std::max(1.0, speed_ / gait_.fastestSpeed());
  if (walking_ > 0.0 && stride_ > 0.0) {
    phase_ = std::fmod(phase_ + dt * gait_.cycleRate(speed_) * std::min(1.0, walking_ / stride_) * hurry, 1.0);
  }
  Eigen::Quaterniond pelvis;
  gait_.evaluate(phase_, speed_, stride_, angles, pelvis);
  idleSway(dt, angles);
  updateStanceTwist(turned * walking_, dt);

  const Eigen::Quaterniond body = Eigen::AngleAxisd(heading_, Eigen::Vector3d::UnitZ()) *
                                  Eigen::AngleAxisd(lean_, Eigen::Vector3d::UnitX()) * pelvis;
  kinematics_.compute({Eigen::Vector3d::Zero(), body}, angles, pose);
  // Turned before the feet are placed, so that they plant the feet as drawn.
  for (std::size_t side = 0; side < 2; ++side) {
    if (stance_twist_[side] == 0.0) continue;
    const bool carrying = feet_.isLeft(feet_.carryingPoint()) == (side == 0);
    const std::size_t pivot = carrying ? feet_.carryingPoint() : feet_.soles().lowestPoint(pose, side);
    leg_ik_.turnLeg(side, stance_twist_[side], feet_.solePoint(pose, pivot), angles, pose);
  }
  feet_.setWalkingSpeed(speed_);
  const Eigen::Vector3d root = feet_.place(pose, dt);
  pose.root.translation = root;
  for (RigidTransform& bone : pose.bone_in_world) bone.translation += root;
  if (feet_.otherFootShift().squaredNorm() > 0.0)
    leg_ik_.shiftFoot(feet_.otherFoot(), feet_.otherFootShift(), angles, pose);
  position_ = root.head<2>();
  const FootSoles& soles = feet_.soles();
  const std::size_t carrying = feet_.isLeft(feet_.carryingPoint()) ? 0 : 1;
  carrying_foot_flat_ =
      soles.point(pose, soles.heel(carrying)).z() < kFlatBand && soles.forefoot(pose, carrying) < kFlatBand;
}

void Walker::updateStanceTwist(double turned, double dt) {
  // On its heel or its ball alone the foot turns about that point without sliding: the hip
  // unwinds there, as people pivot on the ball of the foot in a turn.
  const std::size_t carrying = feet_.isLeft(feet_.carryingPoint()) ? 0 : 1;
  const double unwind = std::exp(-dt / kTwistUnwindTime);
  if (carrying_foot_flat_) {
    stance_twist_[carrying] = std::clamp(stance_twist_[carrying] - turned, -kMaxStanceTwist, kMaxStanceTwist);
  } else {
    stance_twist_[carrying] *= unwind;
  }
  stance_twist_[1 - carrying] *= unwind;
}

void Walker::idleSway(double dt, JointAngles& angles) {
  idle_time_ += dt;
  const double standing = 1.0 - walking_;
  const double t = 2.0 * M_PI * kIdleRate * idle_time_;
  angles[waist_] += standing * kIdleSway * std::sin(t);
  angles[torso_] += standing * kIdleBreath * std::sin(2.0 * t);
}

}  // namespace dressed_human
