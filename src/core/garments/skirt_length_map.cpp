#include "dressed_human/core/garments/skirt_length_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dressed_human {

double kneeLength(double upper_length, double lower_length) {
  if (!(std::isfinite(upper_length) && std::isfinite(lower_length) && upper_length > 0.0 && lower_length > 0.0)) {
    throw std::invalid_argument("skirt length map: bone lengths must be finite and > 0, got d_i = " +
                                std::to_string(upper_length) + ", d_j = " + std::to_string(lower_length));
  }
  return upper_length / (upper_length + lower_length);
}

SkirtLengthWeights skirtLengthWeights(double c, double upper_length, double lower_length) {
  const double knee = kneeLength(upper_length, lower_length);
  if (!(std::isfinite(c) && c >= 0.0 && c <= 1.0)) {
    throw std::invalid_argument("skirt length map: normalized length c must lie in [0, 1], got " + std::to_string(c));
  }
  SkirtLengthWeights w{};
  w.ai = c < knee ? c / knee : 1.0;
  w.a0 = 1.0 - w.ai;
  // ((d_i + d_j) c - d_i) / d_j: exactly 0 at c = c_k and 1 at c = 1.
  w.aj = c <= knee ? 0.0 : std::min(1.0, ((upper_length + lower_length) * c - upper_length) / lower_length);
  return w;
}

double printedLowerWeight(double c, double upper_length, double lower_length) {
  const double knee = kneeLength(upper_length, lower_length);
  if (c < knee) return 0.0;
  return (c * upper_length + (c - 1.0) * lower_length) / lower_length;
}

}  // namespace dressed_human
