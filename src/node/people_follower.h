#pragma once
// ROS adapter: the people of another package's topic (a people tracker, pedsim_ros, the people
// stack, the trajectory player) each walking as a human (TrackedCrowd), published like a crowd
// (CrowdOutput: one dressed_human/Crowd message, the root frames on /tf) in the input's frame.
// The topic's type is recognised by itself (people_messages.h).

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ros/ros.h>
#include <topic_tools/shape_shifter.h>

#include "crowd_output.h"
#include "crowd_publisher.h"
#include "dressed_human/core/locomotion/tracked_crowd.h"
#include "tick_clock.h"

namespace dressed_human {

class PeopleFollower {
 public:
  // Throws (ParameterError, SkeletonError, MotionError) naming what is wrong. `settings`: the
  // crowd publisher's (rate, skeleton_tf, frame_prefix, motion and gait files, world_frame until
  // a message names its frame); `topic` the people topic; `smoothing` PersonTrackSettings::smoothing.
  PeopleFollower(ros::NodeHandle node, const CrowdPublisherSettings& settings, const std::string& topic,
                 double smoothing);

  void run();

 private:
  void receive(const topic_tools::ShapeShifter::ConstPtr& message);
  void tick();
  // The time a message's people were seen at: its stamp (and this node's clock mapped onto the
  // stamps' by the smallest lag seen, said when large), or when it came if the stamp is zero.
  double sightingTime(const ros::Time& stamp);

  // Subscribes to the topic (again: roscpp keeps the md5sum of the first type a ShapeShifter
  // subscription took, and refuses every other type from then on).
  void subscribe();

  ros::NodeHandle node_;
  CrowdPublisherSettings settings_;
  std::string topic_;
  Skeleton skeleton_;  // the robot description's, plain
  std::unique_ptr<SpeedGait> gait_;
  std::unique_ptr<TrackedCrowd> crowd_;
  std::map<std::string, Skeleton> suffixed_;  // by id, while its human walks
  std::unique_ptr<CrowdOutput> output_;
  std::vector<CrowdOutput::Human> output_humans_;
  std::string frame_;          // of the newest message
  std::string type_error_;     // the last unknown type reported
  bool unknown_type_ = false;  // a message of an unknown type came, none of a people type since
  ros::WallTime subscribed_;
  std::map<std::string, ros::WallTime> warned_;  // each bad sighting's warning, when last said
  std::optional<double> clock_offset_;           // s: this node's clock less the stamps'
  std::optional<ros::Time> last_stamp_;
  bool zero_stamps_ = false;
  ros::Subscriber subscriber_;
  TickClock clock_{"crowd_publisher", "every person's human starts again"};
};

}  // namespace dressed_human
