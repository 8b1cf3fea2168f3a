#include "dressed_human/core/surfaces/bezier_profile.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dressed_human {
namespace {

double cubic(double p1, double p2, double p3, double t) {
  const double s = 1.0 - t;
  return 3.0 * s * s * t * p1 + 3.0 * s * t * t * p2 + t * t * t * p3;
}

double cubicDerivative(double p1, double p2, double p3, double t) {
  const double s = 1.0 - t;
  return 3.0 * s * s * p1 + 6.0 * s * t * (p2 - p1) + 3.0 * t * t * (p3 - p2);
}

void requireMonotone(const BezierProfile& profile) {
  const double x1 = profile.first_inner.x();
  const double x2 = profile.second_inner.x();
  if (!(x1 >= 0.0 && x1 <= x2 && x2 <= 1.0) || !profile.first_inner.allFinite() || !profile.second_inner.allFinite()) {
    std::ostringstream message;
    message << "BezierProfile: control points need 0 <= first_inner.x <= second_inner.x <= 1 "
               "(x must grow monotonically from edge to centre), got first_inner = ("
            << profile.first_inner.transpose() << "), second_inner = (" << profile.second_inner.transpose() << ")";
    throw std::invalid_argument(message.str());
  }
}

}  // namespace

BezierProfile BezierProfile::fromEdgeSlope(double edge_slope) {
  if (!(edge_slope > 0.0) || !std::isfinite(edge_slope)) {
    std::ostringstream message;
    message << "BezierProfile::fromEdgeSlope: edge_slope must be finite and > 0, got " << edge_slope;
    throw std::invalid_argument(message.str());
  }
  BezierProfile profile;
  const double x1 = std::min(1.0 / 3.0, 1.0 / edge_slope);
  profile.first_inner = {x1, edge_slope * x1};
  profile.second_inner = {2.0 / 3.0, 1.0};
  return profile;
}

void BezierProfileTable::evaluateExact(const BezierProfile& profile, double x, double& height, double& slope) {
  requireMonotone(profile);
  x = std::clamp(x, 0.0, 1.0);
  const double x1 = profile.first_inner.x(), x2 = profile.second_inner.x();
  const double z1 = profile.first_inner.y(), z2 = profile.second_inner.y();
  // x(t) is monotone: bisection is robust where x'(t) = 0 at an end; 60 halvings reach ulp level.
  double low = 0.0, high = 1.0;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double middle = 0.5 * (low + high);
    (cubic(x1, x2, 1.0, middle) < x ? low : high) = middle;
  }
  const double t = 0.5 * (low + high);
  height = cubic(z1, z2, 1.0, t);
  const double dx = cubicDerivative(x1, x2, 1.0, t);
  const double dz = cubicDerivative(z1, z2, 1.0, t);
  if (dx > 1e-9) {
    slope = dz / dx;
  } else {
    // Vertical tangent at an end point: use the chord to the nearby curve point instead.
    const double nearby = t < 0.5 ? t + 1e-4 : t - 1e-4;
    slope = (cubic(z1, z2, 1.0, nearby) - height) / (cubic(x1, x2, 1.0, nearby) - cubic(x1, x2, 1.0, t));
  }
}

BezierProfileTable::BezierProfileTable(const BezierProfile& profile, int entries) {
  requireMonotone(profile);
  if (entries < 16) {
    std::ostringstream message;
    message << "BezierProfileTable: entries must be >= 16, got " << entries;
    throw std::invalid_argument(message.str());
  }
  last_ = entries - 1;
  heights_.resize(static_cast<std::size_t>(entries));
  slopes_.resize(static_cast<std::size_t>(entries));
  for (int index = 0; index < entries; ++index) {
    evaluateExact(profile, index / last_, heights_[static_cast<std::size_t>(index)],
                  slopes_[static_cast<std::size_t>(index)]);
  }
}

}  // namespace dressed_human
