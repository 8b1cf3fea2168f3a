#include "walk_commands.h"

#include <cmath>
#include <utility>

namespace dressed_human {

WalkCommands::WalkCommands(ros::NodeHandle& private_node, Walker& walker, std::string world_frame, bool closed_paths)
    : walker_(walker), world_frame_(std::move(world_frame)), closed_paths_(closed_paths) {
  path_subscriber_ = private_node.subscribe("path", 2, &WalkCommands::onPath, this);
  twist_subscriber_ = private_node.subscribe("cmd_vel", 10, &WalkCommands::onTwist, this);
  path_topic_ = path_subscriber_.getTopic();
  twist_topic_ = twist_subscriber_.getTopic();
}

void WalkCommands::onPath(const nav_msgs::Path::ConstPtr& path) {
  const std::string& frame = path->header.frame_id;
  if (!frame.empty() && frame != world_frame_ && frame != "/" + world_frame_) {
    ROS_WARN(
        "skeleton_publisher: %s: the path is in frame '%s', not the human's world frame '%s'; ignored, "
        "still walking the last route",
        path_topic_.c_str(), frame.c_str(), world_frame_.c_str());
    return;
  }
  Route route;
  route.closed = closed_paths_;
  for (const geometry_msgs::PoseStamped& pose : path->poses) {
    route.waypoints.emplace_back(pose.pose.position.x, pose.pose.position.y);
  }
  try {
    validateRoute(route, path_topic_);
  } catch (const LocomotionError& error) {
    ROS_WARN("skeleton_publisher: %s; ignored, still walking the last route", error.what());
    return;
  }
  driving_ = false;
  walker_.followRoute(std::move(route));
  ROS_INFO("skeleton_publisher: %s: walking a new route of %zu waypoint(s)", path_topic_.c_str(), path->poses.size());
}

void WalkCommands::onTwist(const geometry_msgs::Twist::ConstPtr& twist) {
  const double speed = twist->linear.x, turn = twist->angular.z;
  if (!std::isfinite(speed) || !std::isfinite(turn)) {
    ROS_WARN_THROTTLE(2.0, "skeleton_publisher: %s: linear.x %g, angular.z %g: not finite; ignored",
                      twist_topic_.c_str(), speed, turn);
    return;
  }
  if (speed < 0.0 || speed > WalkerSettings::kMaxSpeed) {
    ROS_WARN_THROTTLE(2.0,
                      "skeleton_publisher: %s: linear.x %g m/s is outside the walking range [0, %g] (no walking "
                      "backward, no running); clamped",
                      twist_topic_.c_str(), speed, WalkerSettings::kMaxSpeed);
  }
  if (std::abs(twist->linear.y) > 1e-6 || std::abs(twist->linear.z) > 1e-6) {
    ROS_WARN_THROTTLE(10.0, "skeleton_publisher: %s: linear.y and linear.z are ignored (a walker goes where it faces)",
                      twist_topic_.c_str());
  }
  if (!driving_)
    ROS_INFO("skeleton_publisher: %s: driven by velocity commands (a ~path message returns to a route)",
             twist_topic_.c_str());
  driving_ = true;
  last_twist_ = ros::Time::now();
  walker_.drive(speed, turn);
}

void WalkCommands::checkTimeout(const ros::Time& now) {
  if (driving_ && (now - last_twist_).toSec() > kCommandTimeout &&
      walker_.speed() + std::abs(walker_.turnRate()) > 0.0) {
    walker_.drive(0.0, 0.0);
  }
}

}  // namespace dressed_human
