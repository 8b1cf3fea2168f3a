#pragma once
// How still the feet stand: per foot, its lowest sole point while on the ground (within
// PlantedFeet::kContactBand); when the foot rolls (heel to toe) the new lowest point starts a new
// spell. The slide of a spell is how far that point moved from where it touched. Used by the
// tests, the rostest (over TF, the same measure) and the walk chart.

#include <algorithm>
#include <array>
#include <vector>

#include "dressed_human/core/locomotion/planted_feet.h"

namespace dressed_human {

class StanceSlideMeter {
 public:
  // Adds one posed frame; `carrying`: the point carrying the body (PlantedFeet), or -1.
  void add(const PlantedFeet& feet, const SkeletonPose& pose, int carrying = -1) {
    for (std::size_t foot = 0; foot < 2; ++foot) {
      const std::size_t first = feet.soles().heel(foot), end = first + feet.soles().pointsPerFoot();
      std::size_t low = first;
      Eigen::Vector3d low_point = feet.solePoint(pose, low);
      for (std::size_t p = first; p < end; ++p) {
        const Eigen::Vector3d point = feet.solePoint(pose, p);
        lowest = std::min(lowest, point.z());
        if (static_cast<int>(p) == carrying) {
          highest_carrying = std::max(highest_carrying, point.z());
          lowest_carrying = std::min(lowest_carrying, point.z());
        }
        if (point.z() < low_point.z()) {
          low = p;
          low_point = point;
        }
      }
      const int current = low_point.z() < PlantedFeet::kContactBand ? static_cast<int>(low) : -1;
      if (current != point_[foot]) {
        if (point_[foot] >= 0) slides.push_back(slid_[foot]);
        touched_at_[foot] = low_point.head<2>();
        slid_[foot] = 0.0;
        point_[foot] = current;
      }
      if (current >= 0) slid_[foot] = std::max(slid_[foot], (low_point.head<2>() - touched_at_[foot]).norm());
    }
  }
  double worstSlide() const { return slides.empty() ? 0.0 : *std::max_element(slides.begin(), slides.end()); }

  std::vector<double> slides;  // m, one per finished spell
  double lowest = 1e9;         // m, the lowest any sole point got
  double highest_carrying = -1e9, lowest_carrying = 1e9;

 private:
  std::array<int, 2> point_{-1, -1};
  std::array<Eigen::Vector2d, 2> touched_at_{};
  std::array<double, 2> slid_{};
};

}  // namespace dressed_human
