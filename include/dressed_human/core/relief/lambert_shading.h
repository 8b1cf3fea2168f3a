// Lambert diffuse shading, seed paper 000 Eq. 12: I = I_i k_d (L . n) / (|L| |n|).
// The reference shading for tests and figures (the rviz plugin shades on the GPU).
#pragma once

#include "dressed_human/core/relief/relief_map.h"

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace dressed_human {

/// Eq. 12. Light facing away (L . n < 0) gives 0: Eq. 12 itself goes negative there, which no
/// renderer displays. Throws std::invalid_argument for a zero light or normal vector.
double lambertIntensity(const Eigen::Vector3d& light, const Eigen::Vector3d& normal, double incident_intensity = 1.0,
                        double diffuse_coefficient = 1.0);

/// Shade every pixel of a relief map with a directional light given in tangent space;
/// returns 8-bit grey levels (intensity * 255).
std::vector<std::uint8_t> shadeReliefMap(const ReliefMap& map, const Eigen::Vector3d& light,
                                         double incident_intensity = 1.0, double diffuse_coefficient = 1.0);

}  // namespace dressed_human
