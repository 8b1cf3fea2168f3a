#pragma once
// ROS adapter: plays a recorded crowd (a Jülich/PeTrack or ETH/UCY obsmat trajectory file) as
// spencer_tracking_msgs/TrackedPersons on `tracked_persons`, one message per sample of the
// recording at its rate, every person present in that sample, stamped with ROS time.

#include <cstddef>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "dressed_human/core/io/pedestrian_trajectories.h"
#include "dressed_human/core/model/recorded_crowd.h"
#include "people_messages.h"

namespace dressed_human {

struct TrajectoryPlayerSettings {
  std::string file;            // required
  TrajectoryReadOptions read;  // format and frame rate (0: the file's); once the file is read, the format it had
  bool loop = true;            // start over after the last sample
  double time_scale = 1.0;     // 2: twice as fast (velocities too)
  ScenePlacement placement;    // the recording rotated about the origin, then shifted
  std::string frame_id = "world";

  // Reads the private parameters of `private_node`; throws ParameterError naming the bad one.
  static TrajectoryPlayerSettings fromParameters(const ros::NodeHandle& private_node);
};

class TrajectoryPlayer {
 public:
  // Throws ParameterError naming a bad parameter and PedestrianTrajectoryError naming the
  // file (and line) of a bad recording.
  TrajectoryPlayer(ros::NodeHandle node, ros::NodeHandle private_node);

  // Publishes at the recording's rate times time_scale until ROS shuts down (runAtRate).
  void run();

 private:
  // The file as settings_ say (settings_ first in the members: it is set when this runs).
  RecordedCrowd loadRecording();
  void tick();

  TrajectoryPlayerSettings settings_;
  RecordedCrowd crowd_;
  double publish_rate_;  // Hz
  ros::Publisher publisher_;
  std::size_t next_sample_ = 0;
  std::size_t loops_ = 0;
  std::vector<TrackedPersonOut> persons_;  // reused by every tick
};

}  // namespace dressed_human
