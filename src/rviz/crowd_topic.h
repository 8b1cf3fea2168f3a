#pragma once
// A DressedHuman display's crowd from one topic (dressed_human/Crowd, "Humans: From Topic"):
// the subscription, each human's recent poses (PoseTrack) in the fixed frame, which humans are
// new and which have left, and what is wrong with a message ("Crowd Message" status, naming the
// human and the field).

#include <deque>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "dressed_human/Crowd.h"
#include "dressed_human/core/skeleton/pose_track.h"

namespace rviz {
class FrameManager;
}  // namespace rviz

namespace dressed_human {

class DisplayStatus;

class CrowdTopic {
 public:
  // A human left out of a message leaves once its last pose is drawn; one whose messages stop
  // altogether (the topic silent) leaves after this long.
  static constexpr double kTimeoutSeconds = 1.0;

  // Subscribes to `topic` ("": none) on `node` (the display's update queue: messages arrive in
  // rviz's thread). A topic published with another type is an error in the "Topic" status.
  void subscribe(ros::NodeHandle& node, const std::string& topic, DisplayStatus& status);
  void unsubscribe(DisplayStatus& status);
  // Every human forgotten (the display drew them anew, or time jumped back).
  void clear();

  struct NewHuman {
    std::string id;
    double stature;
  };
  // The messages received since the last call into the tracks (roots into the fixed frame),
  // reporting what is refused; the humans seen for the first time.
  std::vector<NewHuman> takeMessages(rviz::FrameManager& frames, DisplayStatus& status);
  // The humans that left (left out of the newest message and drawn to their last pose, or
  // absent for kTimeoutSeconds), forgotten here.
  std::vector<std::string> takeLeft();
  std::shared_ptr<const PoseTrack> track(const std::string& id) const;
  std::size_t humanCount() const { return humans_.size(); }
  const std::string& topic() const { return topic_; }

 private:
  void receive(const Crowd::ConstPtr& message);
  // The message's humans into their tracks; its problems appended to `problems`.
  void take(const Crowd& message, rviz::FrameManager& frames, std::vector<NewHuman>& added,
            std::vector<std::string>& problems);

  struct Human {
    std::shared_ptr<PoseTrack> track;
    ros::WallTime last_seen;
    bool absent = false;  // left out of the newest message
  };
  std::map<std::string, Human> humans_;
  std::deque<Crowd::ConstPtr> inbox_;
  ros::Subscriber subscriber_;
  std::string topic_;
  std::size_t reported_count_ = 0;  // humans the "Topic" status last said; it changes only with them
  bool reported_ = false;
};

}  // namespace dressed_human
