#pragma once
// Live steering of a walking human: ~path (nav_msgs/Path) replaces its route, ~cmd_vel
// (geometry_msgs/Twist) drives it like a robot (teleop_twist_keyboard works). A bad message is
// refused with a warning naming the topic and what is wrong; the human keeps its last good route.

#include <string>

#include <geometry_msgs/Twist.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>

#include "dressed_human/core/locomotion/walker.h"

namespace dressed_human {

class WalkCommands {
 public:
  // `closed_paths`: a received path loops (route_end "loop") or ends standing ("stand").
  WalkCommands(ros::NodeHandle& private_node, Walker& walker, std::string world_frame, bool closed_paths);

  // A driven human stops when cmd_vel falls silent for this long (as robot bases do).
  static constexpr double kCommandTimeout = 0.5;  // s
  void checkTimeout(const ros::Time& now);

 private:
  void onPath(const nav_msgs::Path::ConstPtr& path);
  void onTwist(const geometry_msgs::Twist::ConstPtr& twist);

  Walker& walker_;
  std::string world_frame_;
  bool closed_paths_;
  std::string path_topic_, twist_topic_;
  ros::Subscriber path_subscriber_, twist_subscriber_;
  ros::Time last_twist_;
  bool driving_ = false;
};

}  // namespace dressed_human
