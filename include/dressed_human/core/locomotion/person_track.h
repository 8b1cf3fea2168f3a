#pragma once
// One person's track as a tracker, a simulator or a recording reports it, kept for a few seconds
// so that where the person was at a recent time can be read from the samples on both sides of it:
// a walker following the track a declared delay behind its newest sample walks what was measured
// instead of guessing ahead. Reading a time fits a straight walk (position and velocity, least
// squares) to the samples within a window around it: the tracker's jitter and the head's sway
// from step to step (PeTrack tracks a head) average out, and a steady walk is followed without
// the lag a causal filter (a 1€ filter, a Kalman filter) has at walking speed.

#include <cstddef>
#include <deque>
#include <optional>

#include <Eigen/Core>

namespace dressed_human {

// One observation of a person: time (s), ground position (m), its heading where the source's
// orientation is valid, and whether the source only predicted it (an occluded track).
struct TrackObservation {
  double time = 0.0;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  std::optional<double> yaw;
  bool occluded = false;
};

struct PersonTrackSettings {
  double smoothing = 0.4;       // s: half the window a position is fitted over (0: interpolation only)
  double max_jump = 1.0;        // m from where the track was heading: further is a new place
  double max_speed = 3.0;       // m/s between samples (over more than kMinJumpDistance): faster is a new place
  double max_prediction = 1.0;  // s read past the newest sample (an occluded or late track)
  static constexpr double kMinJumpDistance = 0.3;  // m: jitter between close samples is no jump
  static constexpr double kKeptSeconds = 3.0;      // s of samples kept
};

class PersonTrack {
 public:
  explicit PersonTrack(PersonTrackSettings settings = {}) : settings_(settings) {}

  enum class Added { kFirst, kAppended, kJumped, kNotNewer };
  // Adds an observation. kJumped: further than a walker can go since the last (max_jump,
  // max_speed): the track starts again from it. kNotNewer: not after the newest, ignored.
  Added add(const TrackObservation& observation);

  struct Point {
    Eigen::Vector2d position = Eigen::Vector2d::Zero();
    Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
    std::optional<double> yaw;
  };
  // Where the person was at `time` (the fit around it); before the first sample the first
  // (standing); past the newest, moved on at its velocity for at most max_prediction seconds.
  // Requires a sample.
  Point at(double time) const;

  bool empty() const { return samples_.empty(); }
  double firstTime() const { return samples_.front().time; }
  double newestTime() const { return samples_.back().time; }
  // Seconds from the first of the current run of occluded samples to the newest; 0 if the newest
  // is not occluded.
  double occludedFor() const;
  // The median interval between the kept samples; 0 with fewer than two.
  double typicalInterval() const;

 private:
  // The straight walk fitted to the samples within the smoothing window around `time` (clamped
  // to the kept samples).
  Point fit(double time) const;

  struct Sample {
    double time;
    Eigen::Vector2d position;
    std::optional<double> yaw;
    bool occluded;
  };
  PersonTrackSettings settings_;
  std::deque<Sample> samples_;
  double occluded_since_ = -1.0;  // time of the first occluded sample of the current run; < 0: none
};

}  // namespace dressed_human
