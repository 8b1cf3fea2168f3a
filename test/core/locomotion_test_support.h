#pragma once
// The shipped skeleton, walk and gait table, and a Walker on them; what a walk does on the ground.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dressed_human/core/locomotion/stance_slide.h"
#include "dressed_human/core/locomotion/walker.h"
#include "dressed_human/core/motion/motion_file.h"
#include "dressed_human/core/skeleton/body_description.h"

namespace dressed_human {
namespace locomotion_test {

inline std::string sourcePath(const std::string& relative) {
  return std::string(DRESSED_HUMAN_SOURCE_DIR) + "/" + relative;
}

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
inline const BodyDescription& body() {
  static const BodyDescription b = loadBodyDescriptionFile(sourcePath("config/bodies/default.yaml"), skeleton());
  return b;
}
inline FootSoles soles() { return FootSoles(skeleton(), BodyShape(), body()); }
inline const SpeedGait& gait() {
  static const SpeedGait g(walk(), normative(), skeleton(), BodyShape(), soles());
  return g;
}
inline Walker walker() { return Walker(skeleton(), BodyShape(), gait()); }

// What a walk does on the ground, as the walker's feet carry it.
struct GroundRecord : StanceSlideMeter {
  void add(const Walker& walker, const SkeletonPose& pose) {
    StanceSlideMeter::add(walker.feet(), pose, static_cast<int>(walker.feet().carryingPoint()));
  }
};

}  // namespace locomotion_test
}  // namespace dressed_human
