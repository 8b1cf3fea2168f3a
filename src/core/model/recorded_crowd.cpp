#include "dressed_human/core/model/recorded_crowd.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace dressed_human {
namespace {

// The velocity at sample i of one trajectory, from its neighbours in time (which may be several
// frames apart when the tracker lost the person in between).
Eigen::Vector2d velocityAt(const std::vector<TrajectorySample>& samples, std::size_t i) {
  if (samples.size() < 2) return Eigen::Vector2d::Zero();
  const std::size_t before = i == 0 ? 0 : i - 1;
  const std::size_t after = i + 1 == samples.size() ? i : i + 1;
  const double seconds = samples[after].time - samples[before].time;
  return (samples[after].position - samples[before].position).head<2>() / seconds;
}

}  // namespace

RecordedCrowd::RecordedCrowd(const PedestrianTrajectories& trajectories, const ScenePlacement& placement)
    : sample_rate_(trajectories.sample_rate), person_count_(trajectories.people.size()) {
  const Eigen::Rotation2Dd rotation(placement.yaw);
  std::vector<std::size_t> per_sample(trajectories.sampleCount(), 0);
  for (const PersonTrajectory& person : trajectories.people) {
    for (const TrajectorySample& sample : person.samples) ++per_sample[sample.step];
  }
  sample_begin_.assign(per_sample.size() + 1, 0);
  for (std::size_t s = 0; s < per_sample.size(); ++s) sample_begin_[s + 1] = sample_begin_[s] + per_sample[s];
  people_.resize(sample_begin_.back());
  // Filled person by person in ascending id, each sample's slots in turn: every sample ends up by id.
  std::vector<std::size_t> next = sample_begin_;
  for (const PersonTrajectory& person : trajectories.people) {
    for (std::size_t i = 0; i < person.samples.size(); ++i) {
      RecordedPerson& placed = people_[next[person.samples[i].step]++];
      placed.id = person.id;
      placed.position = rotation * person.samples[i].position.head<2>() + placement.offset;
      placed.velocity = rotation * velocityAt(person.samples, i);
      if (placed.velocity.norm() > kHeadingMinSpeed)
        placed.heading = std::atan2(placed.velocity.y(), placed.velocity.x());
    }
  }
}

}  // namespace dressed_human
