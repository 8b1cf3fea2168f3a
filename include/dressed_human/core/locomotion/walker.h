#pragma once
// A human walking where the scene needs it: along a route (RouteFollower) or driven like a robot
// (speed and turn rate), with a gait that follows the speed (SpeedGait), the travel coming from
// planted feet (PlantedFeet), a lean into turns, and standing (with a slight idle sway) when the
// speed is zero; starting and stopping blend in and out of standing within about a step.

#include <array>
#include <optional>

#include "dressed_human/core/locomotion/leg_ik.h"
#include "dressed_human/core/locomotion/planted_feet.h"
#include "dressed_human/core/locomotion/route.h"
#include "dressed_human/core/locomotion/speed_gait.h"

namespace dressed_human {

struct WalkerSettings {
  RouteFollowerSettings route;
  double acceleration = 1.5;                // m/s^2: from standing to a brisk walk within a step or two
  double lean = 0.5;                        // of the angle a rigid body would lean at (atan(v w / g))
  double lean_time = 0.3;                   // s: the lean follows the turn this smoothly
  static constexpr double kMaxSpeed = 3.0;  // m/s: faster is a run, which this gait is not
};

class Walker {
 public:
  Walker(const Skeleton& skeleton, const BodyShape& shape, SpeedGait gait, WalkerSettings settings = {});
  Walker(const Walker&) = delete;  // the leg IK refers to the kinematics
  Walker& operator=(const Walker&) = delete;

  // Where the walk starts: the root's ground point, heading (rad), gait phase (cycles) and the
  // speed it is already walking at (m/s; a person seen first in mid-walk).
  void place(const Eigen::Vector2d& position, double heading, double phase = 0.0, double speed = 0.0);
  // Walks `route` (validated by the caller) at `cruise_speed` (m/s, 0 = stand where it is).
  void followRoute(Route route);
  void setCruiseSpeed(double speed) { cruise_speed_ = speed; }
  // Drives like a robot until the next followRoute(): forward speed and turn rate (rad/s),
  // both clamped to what a walker can do.
  void drive(double speed, double turn_rate);

  // Advances `dt` seconds; the pose (root included) and the joint angles.
  void step(double dt, JointAngles& angles, SkeletonPose& pose);

  const Eigen::Vector2d& position() const { return position_; }
  double heading() const { return heading_; }
  double speed() const { return speed_; }
  double turnRate() const { return turn_rate_; }
  double phase() const { return phase_; }
  double walking() const { return walking_; }
  const RouteFollower& follower() const { return follower_; }
  const SpeedGait& gait() const { return gait_; }
  const PlantedFeet& feet() const { return feet_; }

 private:
  void idleSway(double dt, JointAngles& angles);
  void updateStanceTwist(double turned, double dt);

  SpeedGait gait_;
  WalkerSettings settings_;
  ForwardKinematics kinematics_;
  PlantedFeet feet_;
  LegIk leg_ik_;
  RouteFollower follower_;
  std::optional<std::pair<double, double>> driven_;  // speed, turn rate
  double cruise_speed_ = 1.2;
  Eigen::Vector2d position_ = Eigen::Vector2d::Zero();
  double heading_ = 0.0;
  double speed_ = 0.0;
  double turn_rate_ = 0.0;
  double lean_ = 0.0;
  double phase_ = 0.0;
  double walking_ = 0.0;
  double stride_ =
      0.0;  // of the gait's steps taken: 0 standing, 1 full steps (at a lower cadence below the slowest gait)
  double idle_time_ = 0.0;
  std::size_t waist_ = 0, torso_ = 0;  // angle indices of the idle sway
  // Per side (left, right): how far the leg is turned at the hip (LegIk::turnLeg) so that the
  // carrying foot keeps its direction on the ground while the body turns above it.
  std::array<double, 2> stance_twist_{};
  bool carrying_foot_flat_ = false;  // heel and forefoot on the ground, after the last step
};

}  // namespace dressed_human
