#include "dressed_human/core/locomotion/tracked_crowd.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace dressed_human {
namespace {

bool sane(const TrackObservation& observation) {
  return observation.position.allFinite() &&
         observation.position.cwiseAbs().maxCoeff() <= TrackedCrowdSettings::kMaxCoordinate &&
         (!observation.yaw || std::isfinite(*observation.yaw));
}

double angleBetween(double to, double from) { return std::remainder(to - from, 2.0 * M_PI); }

}  // namespace

TrackedCrowd::TrackedCrowd(WalkerFactory make_walker, TrackedCrowdSettings settings)
    : make_walker_(std::move(make_walker)),
      settings_(settings),
      delay_(std::clamp(settings.track.smoothing, settings.min_delay, settings.max_delay)) {}

std::vector<std::string> TrackedCrowd::observe(double time, const std::vector<PersonSighting>& people) {
  std::vector<std::string> warnings;
  if (last_time_ && time < *last_time_) {
    warnings.push_back("time went back " + std::to_string(*last_time_ - time) +
                       " s (a recording played again?): every human starts over");
    humans_.clear();
  }
  last_time_ = time;
  std::set<std::string> present;
  for (const PersonSighting& person : people) {
    if (!present.insert(person.id).second) {
      warnings.push_back("track " + person.id + " appears twice in one message: the second left out");
      continue;
    }
    if (!sane(person.observation)) {
      warnings.push_back("track " + person.id + ": a position or heading that is not finite or beyond " +
                         std::to_string(static_cast<int>(TrackedCrowdSettings::kMaxCoordinate)) + " m: left out");
      continue;
    }
    auto found = humans_.find(person.id);
    if (found != humans_.end() && found->second.ended) {
      // Back before its human has left (a tracker that missed it in a message or two): it walks
      // on; only a prediction (occluded) does not bring it back.
      if (person.observation.occluded) continue;
      found->second.ended = false;
    }
    if (found == humans_.end()) {
      if (person.observation.occluded) continue;
      Human human{PersonTrack(settings_.track), make_walker_(person.id, walkerSettings()), {}, {}};
      found = humans_.emplace(person.id, std::move(human)).first;
    }
    Human& human = found->second;
    TrackObservation observation = person.observation;
    observation.time = time;
    if (human.track.add(observation) == PersonTrack::Added::kJumped) human.place = true;
    if (human.track.occludedFor() > settings_.occlusion_limit) human.ended = true;
  }
  for (auto& [id, human] : humans_) {
    if (present.count(id) == 0) human.ended = true;
  }
  // The delay follows the slowest source among the tracks (one message carries them all).
  double interval = 0.0;
  for (const auto& entry : humans_) interval = std::max(interval, entry.second.track.typicalInterval());
  delay_ = std::clamp(std::max(1.5 * interval, settings_.track.smoothing), settings_.min_delay, settings_.max_delay);
  return warnings;
}

void TrackedCrowd::advance(double now, double dt) {
  const double render_time = now - delay_;
  for (auto it = humans_.begin(); it != humans_.end();) {
    Human& human = it->second;
    const double newest = human.track.newestTime();
    const bool walked_to_end = human.ended && render_time >= newest;
    const bool silent = render_time > newest + settings_.silence_limit;
    if (walked_to_end || silent) {
      it = humans_.erase(it);
      continue;
    }
    if (render_time >= human.track.firstTime()) {
      steer(human, render_time);
      human.walker->step(dt, human.angles, human.pose);
      human.posed = true;
    }
    ++it;
  }
}

void TrackedCrowd::steer(Human& human, double render_time) {
  Walker& walker = *human.walker;
  const PersonTrack::Point target = human.track.at(render_time);
  const double target_speed = target.velocity.norm();
  if (human.place) {
    // Facing where it walks; seen first standing, where the source says it faces, or else where
    // it goes next (the samples up to the newest are known already).
    const Eigen::Vector2d next = human.track.at(human.track.newestTime()).position - target.position;
    const double heading = target_speed > settings_.moving_speed ? std::atan2(target.velocity.y(), target.velocity.x())
                           : target.yaw                          ? *target.yaw
                           : next.norm() > 0.1                   ? std::atan2(next.y(), next.x())
                                                                 : walker.heading();
    walker.place(target.position, heading, walker.phase(), std::min(target_speed, WalkerSettings::kMaxSpeed));
    human.moving = target_speed > settings_.moving_speed;
    human.place = false;
  }
  // The velocity that keeps the walker on the track: the track's own plus a pull toward where
  // the track is (the walker's travel comes from its planted feet, not from this command).
  const Eigen::Vector2d off = target.position - walker.position();
  const Eigen::Vector2d wanted = target.velocity + settings_.position_gain * off;
  // The heading follows where it must go only while the track walks (hysteresis) or is far off:
  // a standing or shuffling person does not spin with the tracker's jitter.
  const double steering_speed = std::max(target_speed, off.norm() >= settings_.catch_up ? wanted.norm() : 0.0);
  human.moving = steering_speed > (human.moving ? settings_.standing_speed : settings_.moving_speed);
  double heading_error = 0.0;
  if (human.moving) {
    const Eigen::Vector2d aim = target.velocity + 0.6 * settings_.position_gain * off;
    heading_error = angleBetween(std::atan2(aim.y(), aim.x()), walker.heading());
  } else if (target.yaw) {
    heading_error = angleBetween(*target.yaw, walker.heading());  // a standing person turns as the source says
  }
  // As fast as the wanted velocity goes along the heading: a person facing away from where it
  // must go turns before it walks, and never backs up.
  const Eigen::Vector2d facing(std::cos(walker.heading()), std::sin(walker.heading()));
  // Standing, it stays put for what is jitter.
  const double speed =
      human.moving || wanted.norm() > settings_.standing_speed ? std::max(0.0, wanted.dot(facing)) : 0.0;
  walker.drive(speed, settings_.heading_gain * heading_error);
}

}  // namespace dressed_human
