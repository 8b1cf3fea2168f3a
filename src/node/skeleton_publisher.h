#pragma once
// ROS adapter: evaluates the motion at ROS time and publishes the skeleton as TF and JointState.

#include <memory>
#include <string>
#include <vector>

#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_msgs/TFMessage.h>

#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/locomotion/walker.h"
#include "dressed_human/core/motion/motion_evaluator.h"
#include "tick_clock.h"
#include "walk_commands.h"

namespace dressed_human {

struct SkeletonPublisherSettings {
  std::string motion_file;
  // "walk": along a route (waypoints, ~path, ~cmd_vel) with a speed-dependent gait and planted
  // feet; "replay": the motion as recorded, its root moving along origin_yaw at its own speed.
  std::string mode = "walk";
  std::vector<Eigen::Vector2d> waypoints;  // fixed frame; empty: a loop around origin_x, origin_y
  std::string route_end = "loop";          // "loop" or "stand" (stop at the last waypoint)
  double speed = 1.2;                      // m/s along the route; 0: stand
  std::string gait_file;                   // the normative gait table (config/gait/speed_gaits.yaml)
  std::string body_file;                   // the drawn body, whose feet the walk plants (drawn_feet.h)
  double rate = 100.0;                     // Hz
  double speed_factor = 1.0;               // motion seconds per ROS second
  double start_phase = 0.0;                // radians of the motion cycle at start
  bool loop = true;                        // false: play one cycle, then hold the last pose
  std::string body_id;                     // frames get "_<id>" unless the URDF already has it
  std::string world_frame = "world";
  double origin_x = 0.0, origin_y = 0.0, origin_yaw = 0.0;  // where the walk starts in world_frame
  bool publish_joint_states = true;

  // Reads the private parameters of `private_node`; throws ParameterError naming the bad one.
  static SkeletonPublisherSettings fromParameters(const ros::NodeHandle& private_node);
};

class SkeletonPublisher {
 public:
  // Throws (ParameterError, SkeletonError, MotionError) with a message naming what is wrong.
  SkeletonPublisher(ros::NodeHandle node, ros::NodeHandle private_node);

  // Publishes at the configured rate until ROS shuts down (runAtRate).
  void run();

 private:
  void tick();
  void startWalking(const Skeleton& skeleton, const Motion& motion, ros::NodeHandle& private_node);
  void walk(const ros::Time& now, double dt);
  void replay(const ros::Time& now);
  void placeWalker();
  void publishStaticTransforms(const ros::Time& stamp);
  std::string published(const std::string& urdf_name) const { return urdf_name + extra_suffix_; }

  SkeletonPublisherSettings settings_;
  std::unique_ptr<ForwardKinematics> kinematics_;
  std::unique_ptr<MotionEvaluator> evaluator_;
  std::unique_ptr<Walker> walker_;          // mode walk
  std::unique_ptr<WalkCommands> commands_;  // its live steering
  JointAngles previous_angles_{};
  std::string extra_suffix_;  // appended to URDF names when body_id is set and the URDF has none

  JointAngles angles_{};
  JointAngles velocities_{};
  SkeletonPose pose_;
  // Root, then the 48 DOFs; frame names are set once and the message is published in place
  // (tf2_ros::TransformBroadcaster would copy every frame name on every tick).
  tf2_msgs::TFMessage transforms_;
  sensor_msgs::JointState joint_state_;

  ros::Publisher tf_publisher_;
  tf2_ros::StaticTransformBroadcaster static_broadcaster_;
  ros::Publisher joint_state_publisher_;
  ros::Time start_time_;
  TickClock clock_{"skeleton_publisher", "restarting the motion"};
};

}  // namespace dressed_human
