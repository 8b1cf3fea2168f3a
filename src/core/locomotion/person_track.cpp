#include "dressed_human/core/locomotion/person_track.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace dressed_human {

PersonTrack::Added PersonTrack::add(const TrackObservation& observation) {
  Added added = samples_.empty() ? Added::kFirst : Added::kAppended;
  if (!samples_.empty()) {
    const Sample& last = samples_.back();
    const double dt = observation.time - last.time;
    if (!(dt > 0.0)) return Added::kNotNewer;
    const Point heading = at(last.time);
    const Eigen::Vector2d expected = last.position + dt * heading.velocity;
    const double moved = (observation.position - last.position).norm();
    // From a single sample there is no heading to expect it along: only the speed tells.
    if ((samples_.size() > 1 && (observation.position - expected).norm() > settings_.max_jump) ||
        (moved > PersonTrackSettings::kMinJumpDistance && moved / dt > settings_.max_speed)) {
      samples_.clear();
      occluded_since_ = -1.0;
      added = Added::kJumped;
    }
  }
  samples_.push_back(Sample{observation.time, observation.position, observation.yaw, observation.occluded});
  if (!observation.occluded) {
    occluded_since_ = -1.0;
  } else if (occluded_since_ < 0.0) {
    occluded_since_ = observation.time;
  }
  while (samples_.size() > 2 && samples_.back().time - samples_[1].time > PersonTrackSettings::kKeptSeconds) {
    samples_.pop_front();
  }
  return added;
}

PersonTrack::Point PersonTrack::fit(double time) const {
  // Weighted least squares of p(t) = p0 + v (t - time), triangular weights over the window: the
  // nearest samples count most, and a sample entering or leaving the window moves nothing.
  const double half = std::max(settings_.smoothing, 1e-6);
  double w_sum = 0.0, wt = 0.0, wtt = 0.0;
  Eigen::Vector2d wp = Eigen::Vector2d::Zero(), wtp = Eigen::Vector2d::Zero();
  const auto first = std::lower_bound(samples_.begin(), samples_.end(), time - half,
                                      [](const Sample& sample, double t) { return sample.time < t; });
  for (auto sample = first; sample != samples_.end() && sample->time <= time + half; ++sample) {
    const double t = sample->time - time;
    const double w = 1.0 - std::abs(t) / (half * 1.000001);
    w_sum += w;
    wt += w * t;
    wtt += w * t * t;
    wp += w * sample->position;
    wtp += w * t * sample->position;
  }
  const double determinant = w_sum * wtt - wt * wt;
  // Fewer than two samples in the window (a sparse track, or no smoothing): between the two
  // samples around the time.
  if (w_sum <= 0.0 || determinant <= 1e-12 * std::max(1.0, w_sum * wtt)) {
    const auto after = std::upper_bound(samples_.begin(), samples_.end(), time,
                                        [](double t, const Sample& sample) { return t < sample.time; });
    const Sample& b = after == samples_.end() ? samples_.back() : *after;
    const Sample& a = after == samples_.begin() ? samples_.front() : *(after - 1);
    if (b.time <= a.time) return Point{a.position, Eigen::Vector2d::Zero(), a.yaw};
    const double s = std::clamp((time - a.time) / (b.time - a.time), 0.0, 1.0);
    return Point{a.position + s * (b.position - a.position), (b.position - a.position) / (b.time - a.time),
                 s < 0.5 ? a.yaw : b.yaw};
  }
  const Eigen::Vector2d velocity = (w_sum * wtp - wt * wp) / determinant;
  const Eigen::Vector2d position = (wp - wt * velocity) / w_sum;
  const auto nearest = std::min_element(first, samples_.end(), [time](const Sample& a, const Sample& b) {
    return std::abs(a.time - time) < std::abs(b.time - time);
  });
  return Point{position, velocity, nearest->yaw};
}

PersonTrack::Point PersonTrack::at(double time) const {
  const Sample& first = samples_.front();
  if (samples_.size() == 1 || time <= first.time) return Point{first.position, Eigen::Vector2d::Zero(), first.yaw};
  const double newest = samples_.back().time;
  if (time <= newest) return fit(time);
  Point point = fit(newest);
  point.position += std::min(time - newest, settings_.max_prediction) * point.velocity;
  return point;
}

double PersonTrack::occludedFor() const {
  return occluded_since_ < 0.0 || samples_.empty() ? 0.0 : samples_.back().time - occluded_since_;
}

double PersonTrack::typicalInterval() const {
  if (samples_.size() < 2) return 0.0;
  std::vector<double> intervals;
  intervals.reserve(samples_.size() - 1);
  for (std::size_t i = 1; i < samples_.size(); ++i) intervals.push_back(samples_[i].time - samples_[i - 1].time);
  std::nth_element(intervals.begin(), intervals.begin() + intervals.size() / 2, intervals.end());
  return intervals[intervals.size() / 2];
}

}  // namespace dressed_human
