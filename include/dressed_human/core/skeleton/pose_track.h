#pragma once
// One human's recent poses as a crowd message delivers them (root and joint angles at a stamp,
// 2.5 to 100 Hz), and the pose between them at the time a frame is drawn: drawing a few samples
// behind the newest one interpolates instead of snapping to each message or guessing ahead.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace dressed_human {

struct PoseSample {
  double time = 0.0;  // seconds, on the clock of the messages
  RigidTransform root;
  JointAngles angles{};
};

class PoseTrack {
 public:
  static constexpr std::size_t kCapacity = 8;

  // Adds `sample` after the newest one. A sample not newer than the newest is refused (false):
  // a repeated message; time going back (a bag loop) is the caller's to handle with clear().
  bool add(const PoseSample& sample);
  void clear() { count_ = 0; }
  bool empty() const { return count_ == 0; }
  const PoseSample& newest() const { return sample(count_ - 1); }

  // The pose at `time`: between the two samples around it, the root's position linearly, its
  // rotation by slerp and each angle the short way round; before the oldest sample the oldest,
  // after the newest the newest (no extrapolation). Requires !empty().
  void at(double time, RigidTransform& root, JointAngles& angles) const;

  // The median interval between the stored samples; 0 with fewer than two.
  double typicalInterval() const;
  // How far behind the newest sample to draw so that a frame almost always falls between two
  // samples although messages arrive unevenly: 1.5 typical intervals, at most `limit` seconds.
  double renderDelay(double limit = 0.5) const;

 private:
  const PoseSample& sample(std::size_t i) const { return samples_[(start_ + i) % kCapacity]; }

  std::array<PoseSample, kCapacity> samples_{};
  std::size_t start_ = 0;  // ring buffer: the oldest sample
  std::size_t count_ = 0;
};

// Why a crowd message's human cannot be drawn ("" if it can): a root or angle that is not
// finite, a root rotation that is no rotation, `angle_count` other than 48, a stature outside
// (0.5, 2) of the skeleton's.
std::string humanStateProblem(const RigidTransform& root, const std::vector<double>& angles, double stature);

}  // namespace dressed_human
