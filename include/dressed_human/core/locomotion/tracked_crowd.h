#pragma once
// The people a tracker, a pedestrian simulator or a recording reports, each walking as a human:
// per track a Walker (speed gait, planted feet) steered after the track read a declared delay
// behind its newest sample (PersonTrack), so that it walks between what was measured. Tracks come
// and go: a new one gets its human at once, an ended one leaves once its human has walked to its
// last sample, an occluded one walks on its prediction for a while, a jump no walker can make
// places the human anew.

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dressed_human/core/locomotion/person_track.h"
#include "dressed_human/core/locomotion/walker.h"

namespace dressed_human {

struct TrackedCrowdSettings {
  PersonTrackSettings track;
  // The render delay: 1.5 typical sample intervals (a frame then almost always falls between two
  // samples) and the smoothing window's half (PersonTrackSettings::smoothing), within these.
  double max_delay = 0.5;        // s: a new track's human appears within this
  double min_delay = 0.1;        // s
  double moving_speed = 0.25;    // m/s: a track this fast turns its walker where it goes...
  double standing_speed = 0.15;  // m/s: ... until it is slower than this (hysteresis); slower, the
                                 // heading stays (a tracker's jitter does not spin a standing person)...
  double catch_up = 0.2;         // m: ... unless the track is this far off
  double position_gain = 2.0;    // 1/s: speed added toward the track per metre behind or ahead
  double heading_pull = 1.0;     // 1/s: the same for the heading, gentler: a person veers back onto
                                 // a path over a second or so, not in a twitch
  double heading_gain = 4.0;     // 1/s: turn rate per radian off the wanted heading
  double occlusion_limit = 1.0;  // s an occluded track is walked on its prediction
  double silence_limit = 0.5;    // s past its newest sample (at the render time) before a silent track ends
  static constexpr double kMaxCoordinate = 1e5;  // m (RouteLimits): further is a broken source
};

// One person of one message.
struct PersonSighting {
  std::string id;
  TrackObservation observation;
};

class TrackedCrowd {
 public:
  using WalkerFactory = std::function<std::unique_ptr<Walker>(const std::string& id, const WalkerSettings& settings)>;
  // `make_walker` builds each new person's walker (its skeleton and gait) with `settings`
  // (walkerSettings()).
  explicit TrackedCrowd(WalkerFactory make_walker, TrackedCrowdSettings settings = {});

  // A person stops within about a step (Winter: 2.5-3 m/s^2 when stopping); a walker following
  // a track that does so must too, or it overshoots where the person stands.
  static WalkerSettings walkerSettings() {
    WalkerSettings settings;
    settings.acceleration = 2.5;
    return settings;
  }

  // One message holding every person the source tracks at `time`: people absent from it end. A
  // track seen only occluded (a tracker's prediction) gets no human.
  // Returns one warning per person left out (a duplicate id, a non-finite value) and one if the
  // time went back (a bag played again: every human starts over).
  std::vector<std::string> observe(double time, const std::vector<PersonSighting>& people);

  // Walks every human `dt` seconds on, to the tracks `delay()` before `now`; removes those whose
  // track has ended and been walked to its end.
  void advance(double now, double dt);

  // The render delay: 1.5 typical sample intervals of the tracks, within [min_delay, max_delay].
  double delay() const { return delay_; }

  struct Human {
    PersonTrack track;
    std::unique_ptr<Walker> walker;
    JointAngles angles{};
    SkeletonPose pose;
    bool posed = false;   // advanced at least once (pose valid)
    bool ended = false;   // absent from a message, or occluded too long
    bool moving = false;  // the heading follows the track (hysteresis)
    bool place = true;    // the walker is put where the track is (new, or jumped)
  };
  // By id; only humans posed at least once are drawn (Human::posed: the render time has reached
  // the track's first sample).
  const std::map<std::string, Human>& humans() const { return humans_; }

 private:
  void steer(Human& human, double render_time);

  WalkerFactory make_walker_;
  TrackedCrowdSettings settings_;
  std::map<std::string, Human> humans_;
  double delay_;
  std::optional<double> last_time_;
};

}  // namespace dressed_human
