#include "dressed_human/core/model/relief_visibility.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dressed_human {
namespace {

// Length of the control polygon along row (u) or column (v) `k` of the net: its chord sum bounds
// the curve's length from above and is close to it for the mild curves of a body patch.
double polygonLength(const BezierPatch& patch, int k, bool along_u) {
  double length = 0.0;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d a = along_u ? patch.controlPoint(i, k) : patch.controlPoint(k, i);
    const Eigen::Vector3d b = along_u ? patch.controlPoint(i + 1, k) : patch.controlPoint(k, i + 1);
    length += (b - a).norm();
  }
  return length;
}

}  // namespace

double typicalPatchSize(const std::vector<BezierPatch>& patches) {
  if (patches.empty()) throw std::invalid_argument("typicalPatchSize: no patches");
  std::vector<double> sizes;
  sizes.reserve(patches.size());
  for (const BezierPatch& patch : patches) {
    double largest = 0.0;
    for (const int k : {0, 3}) {
      largest = std::max({largest, polygonLength(patch, k, true), polygonLength(patch, k, false)});
    }
    sizes.push_back(largest);
  }
  std::nth_element(sizes.begin(), sizes.begin() + static_cast<std::ptrdiff_t>(sizes.size() / 2), sizes.end());
  return sizes[sizes.size() / 2];
}

ReliefVisibility::ReliefVisibility(double feature_size) : feature_size_(feature_size) {
  if (!(feature_size > 0.0) || !std::isfinite(feature_size)) {
    throw std::invalid_argument("ReliefVisibility: feature size " + std::to_string(feature_size) +
                                " m must be finite and > 0");
  }
}

bool ReliefVisibility::update(double pixels_per_metre) {
  const double pixels = feature_size_ * pixels_per_metre;
  if (shown_ && pixels <= kHidePixels) shown_ = false;
  if (!shown_ && pixels > kShowPixels) shown_ = true;
  const double t = std::clamp((pixels - kHidePixels) / (kFullPixels - kHidePixels), 0.0, 1.0);
  fade_ = shown_ ? t * t * (3.0 - 2.0 * t) : 0.0;
  return shown_;
}

}  // namespace dressed_human
