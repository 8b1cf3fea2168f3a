// skeleton_publisher: the human skeleton walking on TF. See README.md for parameters.
#include <exception>

#include <ros/ros.h>

#include "skeleton_publisher.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "skeleton_publisher");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try {
    dressed_human::SkeletonPublisher publisher(node, private_node);
    publisher.run();
  } catch (const std::exception& error) {
    ROS_FATAL("skeleton_publisher: %s", error.what());
    return 1;
  }
  return 0;
}
