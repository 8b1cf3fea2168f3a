#pragma once
// The shipped skeleton, walk and gait table, and a Walker on them; a recorder of what a walk
// does on the ground (sole points against z = 0), as the rostest measures it over TF.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dressed_human/core/locomotion/walker.h"
#include "dressed_human/core/motion/motion_file.h"

namespace dressed_human {
namespace locomotion_test {

inline std::string sourcePath(const std::string& relative) { return std::string(DRESSED_HUMAN_SOURCE_DIR) + "/" + relative; }

inline const Skeleton& skeleton() {
  static const Skeleton s = Skeleton::fromUrdfFile(sourcePath("urdf/human.urdf"));
  return s;
}
inline const Motion& walk() {
  static const Motion m = loadMotionFile(sourcePath("config/motions/walk.yaml"));
  return m;
}
inline const NormativeGait& normative() {
  static const NormativeGait g = loadNormativeGaitFile(sourcePath("config/gait/speed_gaits.yaml"));
  return g;
}
inline const SpeedGait& gait() {
  static const SpeedGait g(walk(), normative(), skeleton(), BodyShape());
  return g;
}
inline Walker walker() { return Walker(skeleton(), BodyShape(), gait()); }

// What a walk does on the ground, per foot: its lowest sole point while on the ground (stance)
// must stay put; when the foot rolls (heel to toe) the new lowest point starts a new spell. Also
// the lowest any sole point gets (never below the ground) and the carrying point's height.
struct GroundRecord {
  static constexpr double kBand = PlantedFeet::kContactBand;  // m: "on the ground"
  std::vector<double> slides;              // m, one per finished spell of a foot's lowest point
  double lowest = 1e9, highest_carrying = -1e9, lowest_carrying = 1e9;
  std::array<int, 2> point{-1, -1};        // per foot: the lowest point in the current spell, -1 in the air
  std::array<Eigen::Vector2d, 2> touched_at{};
  std::array<double, 2> slid{};

  void add(const Walker& walker, const SkeletonPose& pose) {
    for (std::size_t foot = 0; foot < 2; ++foot) {
      std::size_t low = foot * PlantedFeet::kPointsPerFoot;
      Eigen::Vector3d low_point = walker.feet().solePoint(pose, low);
      for (std::size_t p = low; p < (foot + 1) * PlantedFeet::kPointsPerFoot; ++p) {
        const Eigen::Vector3d point_now = walker.feet().solePoint(pose, p);
        lowest = std::min(lowest, point_now.z());
        if (p == walker.feet().carryingPoint()) {
          highest_carrying = std::max(highest_carrying, point_now.z());
          lowest_carrying = std::min(lowest_carrying, point_now.z());
        }
        if (point_now.z() < low_point.z()) {
          low = p;
          low_point = point_now;
        }
      }
      const int current = low_point.z() < kBand ? static_cast<int>(low) : -1;
      if (current != point[foot]) {
        if (point[foot] >= 0) slides.push_back(slid[foot]);
        touched_at[foot] = low_point.head<2>();
        slid[foot] = 0.0;
        point[foot] = current;
      }
      if (current >= 0) slid[foot] = std::max(slid[foot], (low_point.head<2>() - touched_at[foot]).norm());
    }
  }
  double worstSlide() const { return slides.empty() ? 0.0 : *std::max_element(slides.begin(), slides.end()); }
};

}  // namespace locomotion_test
}  // namespace dressed_human
