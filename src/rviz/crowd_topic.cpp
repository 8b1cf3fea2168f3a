#include "crowd_topic.h"

#include <algorithm>
#include <set>

#include <OgreQuaternion.h>
#include <OgreVector3.h>
#include <ros/master.h>
#include <rviz/frame_manager.h>

#include "display_status.h"

namespace dressed_human {
namespace {

// rviz slower than the publisher: older messages than these are dropped, the newest kept.
constexpr std::size_t kInboxLimit = 30;
// A message this much older than a human's newest pose is a replay starting over: its track too.
constexpr double kTimeJumpSeconds = 0.5;

const char* const kTopicStatus = "Topic";
const char* const kMessageStatus = "Crowd Message";

// The type `topic` is published with, "" if nobody publishes it yet.
std::string publishedType(const std::string& topic) {
  ros::master::V_TopicInfo topics;
  if (!ros::master::getTopics(topics)) return "";
  for (const ros::master::TopicInfo& info : topics) {
    if (info.name == topic) return info.datatype;
  }
  return "";
}

}  // namespace

void CrowdTopic::subscribe(ros::NodeHandle& node, const std::string& topic, DisplayStatus& status) {
  unsubscribe(status);
  topic_ = topic;
  if (topic.empty()) {
    status.error(kTopicStatus, "no topic set: choose one publishing dressed_human/Crowd (crowd_publisher's /crowd)");
    return;
  }
  const std::string wanted = ros::message_traits::datatype<Crowd>();
  const std::string type = publishedType(node.resolveName(topic));
  if (!type.empty() && type != wanted) {
    status.error(kTopicStatus, "topic '" + topic + "' carries " + type + ", not " + wanted);
    return;
  }
  try {
    subscriber_ = node.subscribe(topic, 10, &CrowdTopic::receive, this);
    status.warn(kTopicStatus, "no message on '" + topic + "' yet");
  } catch (const ros::Exception& error) {
    status.error(kTopicStatus, "cannot subscribe to '" + topic + "': " + error.what());
  }
}

void CrowdTopic::unsubscribe(DisplayStatus& status) {
  subscriber_.shutdown();
  inbox_.clear();
  clear();
  status.clear(kTopicStatus);
  status.clear(kMessageStatus);
}

void CrowdTopic::clear() {
  humans_.clear();
  reported_ = false;
}

void CrowdTopic::receive(const Crowd::ConstPtr& message) {
  inbox_.push_back(message);
  while (inbox_.size() > kInboxLimit) inbox_.pop_front();
}

std::vector<CrowdTopic::NewHuman> CrowdTopic::takeMessages(rviz::FrameManager& frames, DisplayStatus& status) {
  std::vector<NewHuman> added;
  if (inbox_.empty()) return added;
  std::vector<std::string> problems;
  for (const Crowd::ConstPtr& message : inbox_) take(*message, frames, added, problems);
  inbox_.clear();
  if (!reported_ || reported_count_ != humans_.size()) {
    status.ok(kTopicStatus, std::to_string(humans_.size()) + " humans in the messages on '" + topic_ + "'");
    reported_ = true;
    reported_count_ = humans_.size();
  }
  if (problems.empty()) {
    status.clear(kMessageStatus);
  } else {
    std::string text = problems.front();
    if (problems.size() > 1) text += " (and " + std::to_string(problems.size() - 1) + " more)";
    status.error(kMessageStatus, text);
  }
  return added;
}

void CrowdTopic::take(const Crowd& message, rviz::FrameManager& frames, std::vector<NewHuman>& added,
                      std::vector<std::string>& problems) {
  const std::string where = "'" + topic_ + "'";
  if (message.header.frame_id.empty()) {
    problems.push_back(where + ": the message's header.frame_id is empty; refused");
    return;
  }
  // A zero stamp (a hand-written message) holds now.
  const ros::Time stamp = message.header.stamp.isZero() ? ros::Time::now() : message.header.stamp;
  Ogre::Vector3 position;
  Ogre::Quaternion orientation;
  if (!frames.getTransform(message.header.frame_id, stamp, position, orientation) &&
      !frames.getTransform(message.header.frame_id, ros::Time(), position, orientation)) {
    problems.push_back(where + ": frame '" + message.header.frame_id + "' has no transform to the fixed frame '" +
                       frames.getFixedFrame() + "'; message refused");
    return;
  }
  RigidTransform frame;
  frame.translation = {position.x, position.y, position.z};
  frame.rotation = Eigen::Quaterniond(orientation.w, orientation.x, orientation.y, orientation.z);
  std::set<std::string> seen;
  const ros::WallTime now = ros::WallTime::now();
  for (const HumanState& state : message.humans) {
    if (!isHumanId(state.id)) {
      problems.push_back(where + ": human id '" + state.id + "' is not letters and digits; refused");
      continue;
    }
    if (!seen.insert(state.id).second) {
      problems.push_back(where + ": human '" + state.id + "' appears twice in one message; the second refused");
      continue;
    }
    PoseSample sample;
    sample.time = stamp.toSec();
    sample.root.translation = {state.root.position.x, state.root.position.y, state.root.position.z};
    sample.root.rotation = Eigen::Quaterniond(state.root.orientation.w, state.root.orientation.x,
                                              state.root.orientation.y, state.root.orientation.z);
    const std::vector<double> angles(state.joint_angles.begin(), state.joint_angles.end());
    const std::string problem = humanStateProblem(sample.root, angles, state.stature);
    if (!problem.empty()) {
      problems.push_back(where + ": human '" + state.id + "': " + problem + "; refused");
      continue;
    }
    std::copy(angles.begin(), angles.end(), sample.angles.begin());
    sample.root.rotation.normalize();
    sample.root.translation = frame.translation + frame.rotation * sample.root.translation;
    sample.root.rotation = frame.rotation * sample.root.rotation;
    auto found = humans_.find(state.id);
    if (found == humans_.end()) {
      found = humans_.emplace(state.id, Human{std::make_shared<PoseTrack>(), now}).first;
      added.push_back({state.id, state.stature});
    }
    Human& human = found->second;
    human.last_seen = now;
    if (!human.track->empty() && sample.time < human.track->newest().time - kTimeJumpSeconds) human.track->clear();
    human.track->add(sample);
  }
  // A crowd message holds the whole crowd: whoever it leaves out has left (CrowdTopic::takeLeft).
  for (auto& [id, human] : humans_) human.absent = seen.count(id) == 0;
}

std::vector<std::string> CrowdTopic::takeLeft() {
  std::vector<std::string> left;
  const ros::WallTime now = ros::WallTime::now();
  for (auto human = humans_.begin(); human != humans_.end();) {
    // Left out of the newest message: gone once its last pose has been drawn (the render delay
    // after it), not frozen for the timeout. Silent (no messages at all): after the timeout.
    const PoseTrack& track = *human->second.track;
    const bool walked_out = human->second.absent &&
                            (track.empty() || ros::Time::now().toSec() - track.renderDelay() >= track.newest().time);
    if (walked_out || (now - human->second.last_seen).toSec() > kTimeoutSeconds) {
      left.push_back(human->first);
      human = humans_.erase(human);
    } else {
      ++human;
    }
  }
  return left;
}

std::shared_ptr<const PoseTrack> CrowdTopic::track(const std::string& id) const {
  const auto found = humans_.find(id);
  return found == humans_.end() ? nullptr : found->second.track;
}

}  // namespace dressed_human
