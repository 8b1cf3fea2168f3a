#include "dressed_human/core/skeleton/body_shape_groups.h"

#include "dressed_human/core/skeleton/body_description.h"

namespace dressed_human {

BodyShape scaleBodyShapeGroups(const BodyShape& base, const Skeleton& skeleton,
                               const std::vector<ShapeGroupScale>& groups) {
  for (std::size_t g = 0; g < groups.size(); ++g) {
    for (int k = 0; k < 3; ++k) {
      const double factor = groups[g].abc[k];
      if (!(factor >= kMinShapeScale && factor <= kMaxShapeScale)) {
        throw ShapeGroupScaleError(g,
                                   std::string(1, "abc"[k]) + " = " + std::to_string(factor) + " is outside [0.2, 5]");
      }
    }
  }
  BodyShape shape = base;
  for (const ShapeGroupScale& scale : groups) {
    for (const auto& group : bodyShapeGroups()) {
      if (group.first != scale.group) continue;
      for (const std::string& bone : group.second) {
        const int index = skeleton.findBone(bone);
        if (index >= 0) shape.scale[static_cast<std::size_t>(index)].array() *= scale.abc.array();
      }
    }
  }
  return shape;
}

}  // namespace dressed_human
