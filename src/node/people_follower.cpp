#include "people_follower.h"

#include <cmath>

#include "dressed_human/core/locomotion/normative_gait.h"
#include "drawn_feet.h"
#include "parameters.h"
#include "people_messages.h"

namespace dressed_human {
namespace {

// Stamps further than this from the node's clock are said to be another clock's.
constexpr double kStampTrust = 0.5;
// s: a lag growing by more than this at once is a new clock (a source restarted), not a late message.
constexpr double kLagJump = 1.0;
// s: each warning about a message's people is said at most this often (each bad track its own).
constexpr double kWarningPeriod = 2.0;
// s: while the topic has a type no people message has, the subscription is made again this often
// so that the right type is taken when it comes.
constexpr double kResubscribePeriod = 1.0;

}  // namespace

PeopleFollower::PeopleFollower(ros::NodeHandle node, const CrowdPublisherSettings& settings, const std::string& topic,
                               double smoothing)
    : node_(node),
      settings_(settings),
      topic_(node.resolveName(topic)),
      skeleton_(crowdSkeleton(Parameters(node).requiredText("robot_description"))) {
  const Motion motion = crowdMotion(settings_.motion_file);
  const BodyDescription body = drawnBody(settings_.body_file, skeleton_, Parameters(ros::NodeHandle("~")));
  gait_ = std::make_unique<SpeedGait>(motion, loadNormativeGaitFile(settings_.gait_file), skeleton_,
                                      skeleton_.bodyShape(), FootSoles(skeleton_, skeleton_.bodyShape(), body));
  TrackedCrowdSettings crowd_settings;
  crowd_settings.track.smoothing = smoothing;
  crowd_ = std::make_unique<TrackedCrowd>(
      [this](const std::string&, const WalkerSettings& walker) {
        return std::make_unique<Walker>(skeleton_, skeleton_.bodyShape(), *gait_, walker);
      },
      crowd_settings);
  frame_ = settings_.world_frame;
  output_ = std::make_unique<CrowdOutput>(node, settings_.skeleton_tf, settings_.frame_prefix);
  subscribe();
  ROS_INFO("crowd_publisher: the people of %s (%s) walking at %.1f Hz on %s; %s on /tf", topic_.c_str(),
           supportedPeopleTypes().c_str(), settings_.rate, output_->topic().c_str(),
           settings_.skeleton_tf ? "whole skeletons" : "root frames body_<id>");
}

void PeopleFollower::subscribe() {
  subscriber_.shutdown();  // first: a second subscriber would join the subscription of the old type
  subscriber_ = node_.subscribe<topic_tools::ShapeShifter>(topic_, 10, &PeopleFollower::receive, this);
  subscribed_ = ros::WallTime::now();
}

void PeopleFollower::run() {
  runAtRate(settings_.rate, [this] { tick(); });
}

double PeopleFollower::sightingTime(const ros::Time& stamp) {
  const ros::Time now = ros::Time::now();
  if (stamp.isZero()) {
    if (!zero_stamps_) {
      ROS_WARN(
          "crowd_publisher: %s: message stamps are zero: the people are placed at the times their messages "
          "come",
          topic_.c_str());
    }
    zero_stamps_ = true;
    clock_offset_ = 0.0;
    return now.toSec();
  }
  zero_stamps_ = false;
  // The people walk on the stamps' clock (when each sample was measured, stamps going back start
  // every human over); this node's clock maps onto it by the smallest lag seen, the transport's,
  // so that a source whose clock differs (a bag played without /use_sim_time, a tracker stamping
  // late) still places its people instead of leaving them silent behind the render time.
  const double lag = (now - stamp).toSec();
  const bool went_back = last_stamp_ && stamp < *last_stamp_;
  if (!clock_offset_ || went_back || lag < *clock_offset_ || lag > *clock_offset_ + kLagJump) {
    const bool report = (!clock_offset_ || went_back || lag > *clock_offset_ + kLagJump) && std::abs(lag) > kStampTrust;
    clock_offset_ = lag;
    if (report) {
      ROS_WARN(
          "crowd_publisher: %s: message stamps are %.1f s %s this node's clock (a bag without /use_sim_time, "
          "or the source's own clock): the people walk on the stamps' clock, shown that much later",
          topic_.c_str(), std::abs(lag), lag > 0.0 ? "behind" : "ahead of");
    }
  }
  last_stamp_ = stamp;
  return stamp.toSec();
}

void PeopleFollower::receive(const topic_tools::ShapeShifter::ConstPtr& message) {
  ObservedPeople people;
  try {
    people = decodePeople(*message, topic_);
  } catch (const PeopleMessageError& error) {
    if (error.what() != type_error_) ROS_ERROR("crowd_publisher: %s", error.what());
    type_error_ = error.what();
    if (!peopleLayoutOf(message->getMD5Sum())) unknown_type_ = true;
    return;
  }
  type_error_.clear();
  unknown_type_ = false;
  if (people.frame_id.empty()) {
    ROS_WARN_THROTTLE(10.0, "crowd_publisher: %s: a message without header.frame_id: its people taken to be in %s",
                      topic_.c_str(), frame_.c_str());
  } else if (people.frame_id != frame_) {
    if (!crowd_->humans().empty()) {
      ROS_WARN("crowd_publisher: %s: the people's frame changed from %s to %s", topic_.c_str(), frame_.c_str(),
               people.frame_id.c_str());
    }
    frame_ = people.frame_id;
  }
  const double time = sightingTime(people.stamp);
  std::vector<PersonSighting> sightings;
  sightings.reserve(people.people.size());
  for (const ObservedPerson& person : people.people) {
    PersonSighting sighting;
    sighting.id = person.id;
    sighting.observation.time = time;
    sighting.observation.position = person.position.head<2>();
    sighting.observation.yaw = person.yaw;
    sighting.observation.occluded = person.occluded;
    if (!person.position.allFinite()) sighting.observation.position.x() = NAN;  // z too: named as not finite
    sightings.push_back(sighting);
  }
  // Not ROS_WARN_THROTTLE: that keeps one time per line of code, so the first warning of a
  // message would silence the others (a duplicate id after a NaN, the time going back).
  const ros::WallTime wall = ros::WallTime::now();
  for (auto it = warned_.begin(); it != warned_.end();) {
    it = (wall - it->second).toSec() >= kWarningPeriod ? warned_.erase(it) : std::next(it);
  }
  for (const std::string& warning : crowd_->observe(time, sightings)) {
    if (warned_.emplace(warning, wall).second) ROS_WARN("crowd_publisher: %s: %s", topic_.c_str(), warning.c_str());
  }
}

void PeopleFollower::tick() {
  if (unknown_type_ && (ros::WallTime::now() - subscribed_).toSec() >= kResubscribePeriod) subscribe();
  const ros::Time now = ros::Time::now();
  double dt = 0.0;
  const TickClock::Tick tick = clock_.advance(now, dt);
  if (tick == TickClock::Tick::kNoTime) return;
  crowd_->advance(now.toSec() - clock_offset_.value_or(0.0), dt);
  output_humans_.clear();
  for (const auto& [id, human] : crowd_->humans()) {
    if (!human.posed) continue;
    auto suffixed = suffixed_.find(id);
    if (suffixed == suffixed_.end()) suffixed = suffixed_.emplace(id, skeleton_.withSuffix("_" + id)).first;
    output_humans_.push_back({suffixed->first, 1.0, suffixed->second, human.angles, human.pose});
  }
  for (auto it = suffixed_.begin(); it != suffixed_.end();) {
    it = crowd_->humans().count(it->first) ? std::next(it) : suffixed_.erase(it);
  }
  output_->publish(now, frame_, output_humans_);
}

}  // namespace dressed_human
