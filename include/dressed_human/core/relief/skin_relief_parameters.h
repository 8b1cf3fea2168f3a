// The parameters of the skin relief (SkinRelief, skin_relief.h), in a header of their own so that
// the cell hierarchy, the lowest piece of the skin relief, is built from them without the rest.
#pragma once

#include "dressed_human/core/surfaces/bezier_profile.h"

#include <array>
#include <cstdint>

namespace dressed_human {

struct SkinReliefParameters {
  double cell_size = 1.0 / 12.0;  ///< level-1 seed spacing in tile units, (0, 1]
  int levels = 1;                 ///< hierarchy depth, 1..3
  double child_cell_ratio = 0.4;  ///< child spacing / parent spacing, [0.1, 0.8]
  double jitter = 0.35;           ///< uniform seed displacement, fraction of spacing, [0, 0.5]
  double wobble = 0.12;           ///< midpoint displacement amplitude / wall length, [0, 0.3]
  int wobble_subdivisions = 3;    ///< midpoint-displacement depth, 0..6
  double wobble_roughness = 0.5;  ///< amplitude factor per subdivision, [0, 1]
  BezierProfile profile = BezierProfile::fromEdgeSlope(3.0);  ///< cross-section ("slope")
  double roundness = 0.0;                                     ///< 0 = polygonal contours, 1 = round, [0, 1]
  double direction_angle = 0.0;                            ///< radians from +u, direction the cells are stretched along
  double direction_stretch = 1.0;                          ///< >= 1, 1 = no directionality
  int directional_levels = 3;                              ///< the stretch applies to levels 1..directional_levels
  std::array<double, 3> level_depth{{0.08, 0.05, 0.035}};  ///< relief depth / level spacing, >= 0
  std::uint32_t seed = 1;                                  ///< RNG seed (std::mt19937): same seed -> same map
};

}  // namespace dressed_human
