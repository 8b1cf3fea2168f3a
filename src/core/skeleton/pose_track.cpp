#include "dressed_human/core/skeleton/pose_track.h"

#include <algorithm>
#include <cmath>

namespace dressed_human {
namespace {

// Within a revolution of `from`, the short way: angles may be reported wrapped to (-pi, pi].
double shortestDifference(double from, double to) { return std::remainder(to - from, 2.0 * M_PI); }

}  // namespace

bool PoseTrack::add(const PoseSample& sample) {
  if (count_ > 0 && !(sample.time > newest().time)) return false;
  if (count_ == kCapacity) {
    samples_[start_] = sample;
    start_ = (start_ + 1) % kCapacity;
  } else {
    samples_[(start_ + count_) % kCapacity] = sample;
    ++count_;
  }
  return true;
}

void PoseTrack::at(double time, RigidTransform& root, JointAngles& angles) const {
  std::size_t after = 0;
  while (after < count_ && sample(after).time < time) ++after;
  if (after == 0 || after == count_) {
    const PoseSample& held = after == 0 ? sample(0) : newest();
    root = held.root;
    angles = held.angles;
    return;
  }
  const PoseSample& a = sample(after - 1);
  const PoseSample& b = sample(after);
  const double t = (time - a.time) / (b.time - a.time);
  root.translation = a.root.translation + t * (b.root.translation - a.root.translation);
  root.rotation = a.root.rotation.slerp(t, b.root.rotation);
  for (std::size_t i = 0; i < kDofCount; ++i) {
    angles[i] = a.angles[i] + t * shortestDifference(a.angles[i], b.angles[i]);
  }
}

double PoseTrack::typicalInterval() const {
  if (count_ < 2) return 0.0;
  std::array<double, kCapacity> intervals{};
  for (std::size_t i = 1; i < count_; ++i) intervals[i - 1] = sample(i).time - sample(i - 1).time;
  const std::size_t n = count_ - 1;
  std::nth_element(intervals.begin(), intervals.begin() + n / 2, intervals.begin() + n);
  return intervals[n / 2];
}

double PoseTrack::renderDelay(double limit) const { return std::min(1.5 * typicalInterval(), limit); }

std::string humanStateProblem(const RigidTransform& root, const std::vector<double>& angles, double stature) {
  if (!root.translation.allFinite()) return "its root position is not finite";
  const double norm = root.rotation.coeffs().norm();
  if (!root.rotation.coeffs().allFinite() || std::abs(norm - 1.0) > 0.01) {
    return "its root orientation is not a unit quaternion (norm " + std::to_string(norm) + ")";
  }
  if (angles.size() != kDofCount) {
    return std::to_string(angles.size()) + " joint angles, expected " + std::to_string(kDofCount);
  }
  for (std::size_t i = 0; i < angles.size(); ++i) {
    if (!std::isfinite(angles[i])) return "joint angle " + std::to_string(i) + " is not finite";
  }
  if (!(stature > 0.5 && stature < 2.0)) {
    return "stature " + std::to_string(stature) + " is outside (0.5, 2) times the skeleton's";
  }
  return "";
}

}  // namespace dressed_human
