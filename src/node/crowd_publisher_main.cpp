// crowd_publisher: every human of a crowd walking, one dressed_human/Crowd message per tick; with
// ~people_topic, the people of another package's topic walking. See README.md.
#include <exception>

#include <ros/ros.h>

#include "crowd_publisher.h"
#include "parameters.h"
#include "people_follower.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "crowd_publisher");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try {
    const dressed_human::Parameters parameters(private_node);
    const std::string people_topic = parameters.text("people_topic", "");
    if (people_topic.empty()) {
      dressed_human::CrowdPublisher publisher(node, private_node);
      publisher.run();
    } else {
      for (const char* unused : {"count", "crowd_file"}) {
        if (private_node.hasParam(unused)) {
          ROS_WARN("crowd_publisher: %s is ignored: the people come from %s", parameters.fullName(unused).c_str(),
                   people_topic.c_str());
        }
      }
      const double smoothing =
          parameters.numberIn("smoothing", dressed_human::PersonTrackSettings().smoothing, 0.0, 1.0, "s");
      dressed_human::PeopleFollower follower(node, dressed_human::CrowdPublisherSettings::fromParameters(private_node),
                                             people_topic, smoothing);
      follower.run();
    }
  } catch (const std::exception& error) {
    ROS_FATAL("crowd_publisher: %s", error.what());
    return 1;
  }
  return 0;
}
