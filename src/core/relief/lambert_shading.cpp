#include "dressed_human/core/relief/lambert_shading.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dressed_human {

double lambertIntensity(const Eigen::Vector3d& light, const Eigen::Vector3d& normal, double incident_intensity,
                        double diffuse_coefficient) {
  const double light_norm = light.norm();
  const double normal_norm = normal.norm();
  if (!(light_norm > 0.0)) throw std::invalid_argument("lambertIntensity: light vector L must be non-zero");
  if (!(normal_norm > 0.0)) throw std::invalid_argument("lambertIntensity: normal vector n must be non-zero");
  const double cosine = light.dot(normal) / (light_norm * normal_norm);
  return incident_intensity * diffuse_coefficient * std::max(0.0, cosine);
}

std::vector<std::uint8_t> shadeReliefMap(const ReliefMap& map, const Eigen::Vector3d& light, double incident_intensity,
                                         double diffuse_coefficient) {
  if (!(light.norm() > 0.0)) throw std::invalid_argument("shadeReliefMap: light vector must be non-zero");
  const Eigen::Vector3d unit_light = light.normalized();
  std::vector<std::uint8_t> grey(map.heights.size());
  for (std::size_t at = 0; at < grey.size(); ++at) {
    const Eigen::Vector3d normal(-map.slope_u[at], -map.slope_v[at], 1.0);
    const double intensity = lambertIntensity(unit_light, normal, incident_intensity, diffuse_coefficient);
    grey[at] = static_cast<std::uint8_t>(std::clamp(std::round(intensity * 255.0), 0.0, 255.0));
  }
  return grey;
}

}  // namespace dressed_human
