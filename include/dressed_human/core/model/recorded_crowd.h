#pragma once
// A recorded crowd (pedestrian_trajectories.h) as it is played back: per sample of the recording
// the people present in it, each with its velocity, placed in the scene.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "dressed_human/core/io/pedestrian_trajectories.h"

namespace dressed_human {

// Where the recording goes: rotated by `yaw` about the origin, then shifted.
struct ScenePlacement {
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();  // m
  double yaw = 0.0;                                  // rad, counter-clockwise
};

struct RecordedPerson {
  std::uint64_t id = 0;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // m, on the floor, placed
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  // m/s, placed
  std::optional<double> heading;  // rad: the velocity's direction, none when slower than kHeadingMinSpeed
};

class RecordedCrowd {
 public:
  // Below it the direction of the velocity is the sway of a head that stands or shuffles
  // (a few cm per step): not where the person faces.
  static constexpr double kHeadingMinSpeed = 0.3;  // m/s

  // Velocities are central differences of each person's positions over its neighbouring samples
  // (one-sided at a trajectory's ends, 0 for a person seen once).
  RecordedCrowd(const PedestrianTrajectories& trajectories, const ScenePlacement& placement);

  std::size_t sampleCount() const { return sample_begin_.size() - 1; }
  double sampleRate() const { return sample_rate_; }
  std::size_t personCount() const { return person_count_; }
  double duration() const { return static_cast<double>(sampleCount() - 1) / sample_rate_; }

  // The people present in sample `sample` (< sampleCount()), by id.
  const RecordedPerson* begin(std::size_t sample) const { return people_.data() + sample_begin_[sample]; }
  const RecordedPerson* end(std::size_t sample) const { return people_.data() + sample_begin_[sample + 1]; }
  std::size_t countAt(std::size_t sample) const { return sample_begin_[sample + 1] - sample_begin_[sample]; }

 private:
  double sample_rate_;
  std::size_t person_count_;
  std::vector<RecordedPerson> people_;     // by sample, then id
  std::vector<std::size_t> sample_begin_;  // sample s is people_[sample_begin_[s], sample_begin_[s + 1])
};

}  // namespace dressed_human
