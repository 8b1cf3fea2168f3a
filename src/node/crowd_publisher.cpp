#include "crowd_publisher.h"

#include <cctype>
#include <cmath>

#include <ros/package.h>

#include "dressed_human/core/locomotion/normative_gait.h"
#include "dressed_human/core/motion/motion_file.h"
#include "drawn_feet.h"
#include "dressed_human/core/skeleton/urdf_body_shape.h"
#include "parameters.h"
#include "tick_clock.h"
#include "transform_messages.h"

namespace dressed_human {
namespace {

constexpr int kMaxCount = 1000;
constexpr double kMaxRate = 1000.0;

}  // namespace

std::string framePrefixParameter(const Parameters& parameters) {
  const std::string prefix = parameters.text("frame_prefix", "");
  for (const char c : prefix) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '/') {
      throw ParameterError("parameter " + parameters.fullName("frame_prefix") + " '" + prefix +
                           "' may hold only letters, digits, '_' and '/' (it starts TF frame names)");
    }
  }
  return prefix;
}

Motion crowdMotion(const std::string& motion_file) {
  Motion motion = loadMotionFile(motion_file);
  if (motion.body_shape) {
    throw ParameterError("motion file " + motion_file +
                         " was fitted to one person's body; a crowd walks the "
                         "robot description's body at each human's stature: give a motion without body_shape");
  }
  return motion;
}

Skeleton crowdSkeleton(const std::string& urdf) {
  Skeleton plain = Skeleton::fromUrdf(urdf);
  if (!plain.suffix().empty()) {
    throw ParameterError("robot_description's frames carry the suffix '" + plain.suffix() +
                         "'; a crowd names its humans itself (by their ids): give the plain skeleton "
                         "(urdf/human.urdf)");
  }
  return plain;
}

CrowdPublisherSettings CrowdPublisherSettings::fromParameters(const ros::NodeHandle& private_node) {
  const Parameters parameters(private_node);
  CrowdPublisherSettings s;
  const std::string package = ros::package::getPath("dressed_human");
  s.crowd_file = parameters.text("crowd_file", s.crowd_file);
  s.count = static_cast<int>(parameters.numberIn("count", s.count, 0, kMaxCount, "humans"));
  if (parameters.number("count", s.count) != s.count) {
    throw ParameterError("parameter " + parameters.fullName("count") + " must be a whole number of humans");
  }
  s.motion_file = parameters.text("motion_file", package.empty() ? "" : package + "/config/motions/walk.yaml");
  s.gait_file = parameters.text("gait_file", package.empty() ? "" : package + "/config/gait/speed_gaits.yaml");
  s.body_file = bodyFileParameter(parameters, package);
  if (s.motion_file.empty() || s.gait_file.empty()) {
    throw ParameterError("parameters " + parameters.fullName("motion_file") + " and " +
                         parameters.fullName("gait_file") + " are needed: the dressed_human package path is unknown");
  }
  s.rate = parameters.numberIn("rate", s.rate, 1.0, kMaxRate, "Hz");
  s.world_frame = parameters.text("world_frame", s.world_frame);
  if (s.world_frame.empty()) throw ParameterError("parameter " + parameters.fullName("world_frame") + " is empty");
  s.skeleton_tf = parameters.boolean("skeleton_tf", s.skeleton_tf);
  s.frame_prefix = framePrefixParameter(parameters);
  return s;
}

CrowdPublisher::CrowdPublisher(ros::NodeHandle node, ros::NodeHandle private_node)
    : settings_(CrowdPublisherSettings::fromParameters(private_node)) {
  const std::string urdf = Parameters(node).requiredText("robot_description");
  const Motion motion = crowdMotion(settings_.motion_file);
  const NormativeGait gait = loadNormativeGaitFile(settings_.gait_file);
  const std::vector<CrowdWalk> walks = settings_.crowd_file.empty()
                                           ? defaultCrowdWalks(static_cast<std::size_t>(settings_.count))
                                           : loadCrowdWalks(settings_.crowd_file);
  const Skeleton plain = crowdSkeleton(urdf);
  const BodyDescription body = drawnBody(settings_.body_file, plain, Parameters(private_node));
  members_.reserve(walks.size());
  for (const CrowdWalk& walk : walks) addMember(walk, plain, motion, gait, body);

  output_ = std::make_unique<CrowdOutput>(node, settings_.skeleton_tf, settings_.frame_prefix);
  for (const Member& member : members_) {
    output_humans_.push_back({member.walk.id, member.stature, member.skeleton, member.angles, member.pose});
  }
  ROS_INFO("crowd_publisher: %zu humans (%s) at %.1f Hz on %s in %s; %s on /tf", members_.size(),
           settings_.crowd_file.empty() ? "default layout" : settings_.crowd_file.c_str(), settings_.rate,
           output_->topic().c_str(), settings_.world_frame.c_str(),
           settings_.skeleton_tf ? "whole skeletons" : "root frames body_<id>");
}

void CrowdPublisher::addMember(const CrowdWalk& walk, const Skeleton& plain, const Motion& motion,
                               const NormativeGait& gait, const BodyDescription& body) {
  const double stature = drawnStature(plain, walk.stature);
  const Skeleton scaled = skeletonAtStature(plain, walk.stature);
  auto walker = std::make_unique<Walker>(
      scaled, scaled.bodyShape(),
      SpeedGait(motion, gait, scaled, scaled.bodyShape(), FootSoles(scaled, scaled.bodyShape(), body)));
  walker->setCruiseSpeed(walk.speed);
  members_.push_back(Member{walk, stature, scaled.withSuffix("_" + walk.id), std::move(walker), {}, {}});
}

// Each human at its start facing its route's first waypoint (a treadmill walker: its second),
// at its own gait phase.
void CrowdPublisher::place() {
  for (Member& member : members_) {
    const CrowdWalk& walk = member.walk;
    const std::vector<Eigen::Vector2d>& waypoints = walk.route.waypoints;
    const Eigen::Vector2d from = walk.treadmill ? waypoints.front() : walk.start;
    Eigen::Vector2d direction = (walk.treadmill ? waypoints[1] : waypoints.front()) - from;
    if (direction.norm() == 0.0 && waypoints.size() > 1)
      direction = waypoints[1] - from;  // starts on its first waypoint
    const double heading = std::atan2(direction.y(), direction.x());
    member.walker->place(from, heading, walk.start_phase);
    if (walk.treadmill) {
      member.walker->drive(walk.speed, 0.0);
    } else {
      member.walker->followRoute(walk.route);
    }
  }
}

void CrowdPublisher::run() {
  runAtRate(settings_.rate, [this] { tick(); });
}

void CrowdPublisher::tick() {
  const ros::Time now = ros::Time::now();
  double dt = 0.0;
  const TickClock::Tick tick = clock_.advance(now, dt);
  if (tick == TickClock::Tick::kNoTime) return;
  if (tick == TickClock::Tick::kFirst) place();
  for (Member& member : members_) {
    member.walker->step(dt, member.angles, member.pose);
    if (member.walk.treadmill) {  // the ground under it moves back as far as it walked
      member.pose.root.translation.head<2>() += member.walk.route.waypoints.front() - member.walker->position();
    }
  }
  output_->publish(now, settings_.world_frame, output_humans_);
}

}  // namespace dressed_human
