#include "skeleton_publisher.h"

#include <cctype>
#include <cmath>
#include <sstream>
#include <utility>

#include <ros/package.h>

#include "dressed_human/core/motion/motion_file.h"
#include "drawn_feet.h"
#include "parameters.h"
#include "tick_clock.h"
#include "transform_messages.h"

namespace dressed_human {
namespace {

constexpr double kMaxRate = 10000.0;
constexpr double kMaxSpeedFactor = 10.0;
constexpr double kMaxOriginMetres = 1e5;  // the DressedHuman display's drawable range

// A motion fitted to a person (fit_motion) moves that person's bones: on another body its feet
// slide and miss the ground, so a robot_description without those proportions is an error.
void requireSameBody(const Motion& motion, const Skeleton& skeleton, const std::string& motion_file) {
  if (!motion.body_shape) return;
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    const Eigen::Vector3d& wanted = motion.body_shape->scale[b];
    const Eigen::Vector3d& carried = skeleton.bodyShape().scale[b];
    const Eigen::Vector3d& wanted_offset = motion.body_shape->offset[b];
    const Eigen::Vector3d& carried_offset = skeleton.bodyShape().offset[b];
    if ((wanted - carried).cwiseAbs().maxCoeff() > 1e-5 * wanted.cwiseAbs().maxCoeff() ||
        (wanted_offset - carried_offset).cwiseAbs().maxCoeff() > 1e-6) {
      std::ostringstream message;
      message << "motion file " << motion_file << " was fitted to a body whose " << skeleton.bone(b).name
              << " is [a, b, c] = [" << wanted.transpose() << "] offset [" << wanted_offset.transpose()
              << "], but robot_description carries [" << carried.transpose() << "] offset ["
              << carried_offset.transpose() << "]: set robot_description from `scripts/human_urdf.py "
              << "<urdf> --motion " << motion_file << "` (skeleton.launch does)";
      throw ParameterError(message.str());
    }
  }
}

// The walking parameters. A wrong mode or gait file is fatal (nothing sensible to do instead); a
// bad route or speed is an error the human survives: it walks the default loop or speed.
void readWalkSettings(const Parameters& parameters, const std::string& package, SkeletonPublisherSettings& s) {
  s.mode = parameters.text("mode", s.mode);
  if (s.mode != "walk" && s.mode != "replay") {
    throw ParameterError("parameter " + parameters.fullName("mode") + " must be 'walk' or 'replay', got '" + s.mode +
                         "'");
  }
  s.route_end = parameters.text("route_end", s.route_end);
  if (s.route_end != "loop" && s.route_end != "stand") {
    throw ParameterError("parameter " + parameters.fullName("route_end") + " must be 'loop' or 'stand', got '" +
                         s.route_end + "'");
  }
  s.gait_file = parameters.text("gait_file", package.empty() ? "" : package + "/config/gait/speed_gaits.yaml");
  s.body_file = bodyFileParameter(parameters, package);
  try {
    s.speed = parameters.numberIn("speed", s.speed, 0.0, WalkerSettings::kMaxSpeed, "m/s");
  } catch (const ParameterError& error) {
    ROS_ERROR("skeleton_publisher: %s (no walking backward, no running); walking at %.1f m/s instead", error.what(),
              1.2);
    s.speed = 1.2;
  }
  try {
    if (parameters.points("waypoints", s.waypoints)) {
      validateRoute(Route{s.waypoints, s.route_end == "loop"}, "parameter " + parameters.fullName("waypoints"));
    }
  } catch (const std::exception& error) {  // ParameterError, LocomotionError
    ROS_ERROR("skeleton_publisher: %s; walking the default loop instead", error.what());
    s.waypoints.clear();
  }
}

}  // namespace

SkeletonPublisherSettings SkeletonPublisherSettings::fromParameters(const ros::NodeHandle& private_node) {
  const Parameters parameters(private_node);
  SkeletonPublisherSettings s;
  const std::string package = ros::package::getPath("dressed_human");
  s.motion_file = parameters.text("motion_file", package.empty() ? "" : package + "/config/motions/walk.yaml");
  if (s.motion_file.empty()) {
    throw ParameterError("parameter " + parameters.fullName("motion_file") +
                         " is not set and the dressed_human package path is unknown");
  }
  s.rate = parameters.number("rate", s.rate);
  if (s.rate <= 0.0 || s.rate > kMaxRate) {
    throw ParameterError("parameter " + parameters.fullName("rate") + " must be in (0, " +
                         std::to_string(static_cast<int>(kMaxRate)) + "] Hz, got " + std::to_string(s.rate));
  }
  // Physical ranges: a replay from frozen to ten times as fast; positions a map holds (and that
  // rviz can draw a human at, in float); a heading and phase in radians, not degrees.
  s.speed_factor =
      parameters.numberIn("speed_factor", s.speed_factor, 0.0, kMaxSpeedFactor, "(times the motion's speed)");
  s.start_phase = parameters.numberIn("start_phase", s.start_phase, -2.0 * M_PI, 2.0 * M_PI, "rad");
  s.loop = parameters.boolean("loop", s.loop);
  s.body_id = parameters.text("body_id", s.body_id);
  for (unsigned char c : s.body_id) {
    if (!std::isalnum(c)) {
      throw ParameterError("parameter " + parameters.fullName("body_id") + " must be letters and digits only, got '" +
                           s.body_id + "'");
    }
  }
  s.world_frame = parameters.text("world_frame", s.world_frame);
  if (s.world_frame.empty()) throw ParameterError("parameter " + parameters.fullName("world_frame") + " is empty");
  s.origin_x = parameters.numberIn("origin_x", s.origin_x, -kMaxOriginMetres, kMaxOriginMetres, "m");
  s.origin_y = parameters.numberIn("origin_y", s.origin_y, -kMaxOriginMetres, kMaxOriginMetres, "m");
  s.origin_yaw = parameters.numberIn("origin_yaw", s.origin_yaw, -2.0 * M_PI, 2.0 * M_PI, "rad");
  s.publish_joint_states = parameters.boolean("publish_joint_states", s.publish_joint_states);
  readWalkSettings(parameters, package, s);
  return s;
}

SkeletonPublisher::SkeletonPublisher(ros::NodeHandle node, ros::NodeHandle private_node)
    : settings_(SkeletonPublisherSettings::fromParameters(private_node)) {
  const Parameters parameters(node);
  const Skeleton skeleton = Skeleton::fromUrdf(parameters.requiredText("robot_description"));
  const std::string wanted_suffix = settings_.body_id.empty() ? "" : "_" + settings_.body_id;
  if (!wanted_suffix.empty() && skeleton.suffix() != wanted_suffix) {
    if (!skeleton.suffix().empty()) {
      throw ParameterError("parameter " + private_node.resolveName("body_id") + " is '" + settings_.body_id +
                           "' but robot_description's frames carry the suffix '" + skeleton.suffix() + "'");
    }
    extra_suffix_ = wanted_suffix;
  }
  Motion motion = loadMotionFile(settings_.motion_file);
  requireSameBody(motion, skeleton, settings_.motion_file);
  // A fitted person's URDF carries its proportions (urdf_body_shape.h): TF puts the joints there.
  kinematics_ = std::make_unique<ForwardKinematics>(skeleton, skeleton.bodyShape());
  if (settings_.mode == "walk") startWalking(skeleton, motion, private_node);
  evaluator_ = std::make_unique<MotionEvaluator>(std::move(motion));

  transforms_.transforms = movingTransforms(skeleton, settings_.world_frame, extra_suffix_);
  for (const ArticulatedJoint& joint : skeleton.joints()) {
    for (const std::string& name : joint.urdf_joints) joint_state_.name.push_back(published(name));
  }
  joint_state_.position.resize(kDofCount);
  joint_state_.velocity.resize(kDofCount);

  tf_publisher_ = node.advertise<tf2_msgs::TFMessage>("/tf", 100);
  if (settings_.publish_joint_states) {
    joint_state_publisher_ = node.advertise<sensor_msgs::JointState>("joint_states", 10);
  }
  ROS_INFO("skeleton_publisher: %s at %.1f Hz (speed x%.2f), root %s in %s, %s", settings_.motion_file.c_str(),
           settings_.rate, settings_.speed_factor, published(skeleton.rootFrame()).c_str(),
           settings_.world_frame.c_str(), walker_ ? "walking a route" : "replaying the motion");
}

void SkeletonPublisher::startWalking(const Skeleton& skeleton, const Motion& motion, ros::NodeHandle& private_node) {
  const NormativeGait normative = loadNormativeGaitFile(settings_.gait_file);  // LocomotionError names the file
  const BodyDescription body = drawnBody(settings_.body_file, skeleton, Parameters(private_node));
  try {
    walker_ = std::make_unique<Walker>(
        skeleton, skeleton.bodyShape(),
        SpeedGait(motion, normative, skeleton, skeleton.bodyShape(), FootSoles(skeleton, skeleton.bodyShape(), body)));
  } catch (const LocomotionError& error) {
    ROS_ERROR("skeleton_publisher: %s; replaying it as recorded (parameter %s is 'walk')", error.what(),
              private_node.resolveName("mode").c_str());
    return;
  }
  walker_->setCruiseSpeed(settings_.speed);
  placeWalker();
  commands_ =
      std::make_unique<WalkCommands>(private_node, *walker_, settings_.world_frame, settings_.route_end == "loop");
}

// The walk starts at origin_x, origin_y facing origin_yaw, on the route from its first waypoint.
void SkeletonPublisher::placeWalker() {
  const Eigen::Vector2d origin(settings_.origin_x, settings_.origin_y);
  Route route = settings_.waypoints.empty() ? defaultLoop(origin, settings_.origin_yaw)
                                            : Route{settings_.waypoints, settings_.route_end == "loop"};
  if (settings_.waypoints.empty()) {
    // Start on the loop's first leg, not in its middle: at the last corner, facing the first.
    const Eigen::Vector2d from = route.waypoints.back(), to = route.waypoints.front();
    walker_->place(from, std::atan2(to.y() - from.y(), to.x() - from.x()), settings_.start_phase / (2.0 * M_PI));
  } else {
    walker_->place(origin, settings_.origin_yaw, settings_.start_phase / (2.0 * M_PI));
  }
  walker_->followRoute(std::move(route));
}

void SkeletonPublisher::publishStaticTransforms(const ros::Time& stamp) {
  static_broadcaster_.sendTransform(fixedBoneTransforms(*kinematics_, stamp, extra_suffix_));
}

void SkeletonPublisher::run() {
  runAtRate(settings_.rate, [this] { tick(); });
}

void SkeletonPublisher::tick() {
  const ros::Time now = ros::Time::now();
  double ros_dt = 0.0;
  const TickClock::Tick tick = clock_.advance(now, ros_dt);
  if (tick == TickClock::Tick::kNoTime) return;
  if (tick == TickClock::Tick::kFirst) {
    start_time_ = now;
    publishStaticTransforms(now);
    if (walker_) placeWalker();
  }
  const double dt = ros_dt * settings_.speed_factor;
  if (walker_) {
    walk(now, dt);
  } else {
    replay(now);
  }

  auto& transforms = transforms_.transforms;
  copyTransform(pose_.root, transforms[0].transform);
  for (std::size_t i = 0; i < kDofCount; ++i) copyTransform(pose_.dof_transforms[i], transforms[i + 1].transform);
  for (auto& transform : transforms) transform.header.stamp = now;
  tf_publisher_.publish(transforms_);

  if (settings_.publish_joint_states) {
    joint_state_.header.stamp = now;
    for (std::size_t i = 0; i < kDofCount; ++i) {
      joint_state_.position[i] = angles_[i];
      joint_state_.velocity[i] = velocities_[i];
    }
    joint_state_publisher_.publish(joint_state_);
  }
}

void SkeletonPublisher::walk(const ros::Time& now, double dt) {
  commands_->checkTimeout(now);
  walker_->step(dt, angles_, pose_);
  for (std::size_t i = 0; i < kDofCount; ++i) {
    velocities_[i] = dt > 0.0 ? (angles_[i] - previous_angles_[i]) / dt * settings_.speed_factor : 0.0;
  }
  previous_angles_ = angles_;
}

void SkeletonPublisher::replay(const ros::Time& now) {
  const double cycle = evaluator_->motion().period;
  double elapsed = (now - start_time_).toSec() * settings_.speed_factor;
  if (!settings_.loop) elapsed = std::min(elapsed, cycle);
  const double time = elapsed + settings_.start_phase / (2.0 * M_PI) * cycle;

  RigidTransform root;
  evaluator_->evaluate(time, angles_, root, &velocities_);
  for (double& velocity : velocities_) velocity *= settings_.speed_factor;
  const Eigen::AngleAxisd heading(settings_.origin_yaw, Eigen::Vector3d::UnitZ());
  root.translation = Eigen::Vector3d(settings_.origin_x, settings_.origin_y, 0.0) + heading * root.translation;
  root.rotation = heading * root.rotation;
  kinematics_->compute(root, angles_, pose_);
}

}  // namespace dressed_human
