// trajectory_player: a recorded crowd as spencer_tracking_msgs/TrackedPersons. See README.md.
#include <exception>

#include <ros/ros.h>

#include "trajectory_player.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "trajectory_player");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try {
    dressed_human::TrajectoryPlayer player(node, private_node);
    player.run();
  } catch (const std::exception& error) {
    ROS_FATAL("trajectory_player: %s", error.what());
    return 1;
  }
  return 0;
}
