#pragma once
// The body shape as a user scales it by limb group (bodyShapeGroups(): all, trunk, arms, ...):
// each group's (a, b, c) multiplies the shape of every bone it covers (Eq. 5).

#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace dressed_human {

struct ShapeGroupScale {
  std::string group;  // a bodyShapeGroups() name
  Eigen::Vector3d abc = Eigen::Vector3d::Ones();
};

// A factor outside [kMinShapeScale, kMaxShapeScale]; `entry` is its index in the list given.
class ShapeGroupScaleError : public std::invalid_argument {
 public:
  ShapeGroupScaleError(std::size_t entry, const std::string& what) : std::invalid_argument(what), entry(entry) {}
  std::size_t entry;
};

constexpr double kMinShapeScale = 0.2;
constexpr double kMaxShapeScale = 5.0;

// `base` with the bones of each listed group scaled by its (a, b, c), in list order. Unknown
// group names scale nothing. Throws ShapeGroupScaleError ("a = 0.100000 is outside [0.2, 5]")
// for the first factor out of range, before changing anything.
BodyShape scaleBodyShapeGroups(const BodyShape& base, const Skeleton& skeleton,
                               const std::vector<ShapeGroupScale>& groups);

}  // namespace dressed_human
