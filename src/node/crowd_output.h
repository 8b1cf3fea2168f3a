#pragma once
// What the crowd publisher sends per tick for humans that may differ from tick to tick (a crowd
// file's, or the people of a tracker): one dressed_human/Crowd message for all of them (the
// display draws from it) and each root frame body_<id> on /tf (skeleton_tf: every bone, and the
// fixed bones on /tf_static once per human). `frame_prefix` goes before every frame name but the
// world frame, so that another package's body_<id> (REP-155 skeletons) never clashes with ours.

#include <map>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include "dressed_human/Crowd.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace dressed_human {

class CrowdOutput {
 public:
  CrowdOutput(ros::NodeHandle node, bool skeleton_tf, std::string frame_prefix);

  struct Human {
    const std::string& id;
    double stature;            // as drawn (drawnStature)
    const Skeleton& skeleton;  // suffixed with _<id>
    const JointAngles& angles;
    const SkeletonPose& pose;  // in the world frame
  };
  void publish(const ros::Time& stamp, const std::string& world_frame, const std::vector<Human>& humans);

  const std::string& topic() const { return topic_; }

 private:
  // A human's transforms, named once (and again if the world frame changes).
  const std::vector<geometry_msgs::TransformStamped>& transformsOf(const Human& human, const std::string& world_frame,
                                                                   const ros::Time& stamp);

  bool skeleton_tf_;
  std::string frame_prefix_;
  std::string topic_;
  dressed_human::Crowd message_;
  tf2_msgs::TFMessage transforms_;
  struct Named {
    std::string world_frame;
    std::vector<geometry_msgs::TransformStamped> transforms;
  };
  std::map<std::string, Named> named_;  // by id; kept while the human is published
  std::vector<std::string> ids_;        // the humans transforms_ is laid out for, in order
  std::string world_frame_;
  ros::Publisher crowd_publisher_;
  ros::Publisher tf_publisher_;
  tf2_ros::StaticTransformBroadcaster static_broadcaster_;
};

}  // namespace dressed_human
