// crowd_publisher: every human of a crowd walking, one dressed_human/Crowd message per tick. See README.md.
#include <exception>

#include <ros/ros.h>

#include "crowd_publisher.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "crowd_publisher");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try {
    dressed_human::CrowdPublisher publisher(node, private_node);
    publisher.run();
  } catch (const std::exception& error) {
    ROS_FATAL("crowd_publisher: %s", error.what());
    return 1;
  }
  return 0;
}
