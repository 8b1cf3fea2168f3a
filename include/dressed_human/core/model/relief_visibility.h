#pragma once
// Whether a relief can be seen on screen, per human and relief kind, so that a renderer can draw
// it with a cheaper, flat material when it cannot. fade() brings a relief in from nothing at
// kHidePixels per feature to full at kFullPixels (a renderer scales the relief's strength by
// it): below a few pixels a normal map's features are averaged away by its mip chain or
// shimmer. Where the fade is 0 the relief material would draw a flat surface at its full price
// (on a software renderer the garments' fold shader is most of a small human's cost), so the
// switch turns the plain material on there. It has hysteresis (off at kHidePixels, on again
// above kShowPixels), so a human walking at the threshold distance does not switch materials
// every frame, and does not pop: the fade is 0 where it switches off and under 0.004 where it
// switches on.

#include <vector>

#include <Eigen/Core>

#include "dressed_human/core/surfaces/bezier_patch.h"
#include "dressed_human/core/surfaces/tessellation.h"

namespace dressed_human {

// The typical size (m) of one patch of `patches`: the median of each patch's larger side (the
// longer of its boundary polygons' u and v lengths). A relief tiled once per patch has its
// features at a fraction of it. Throws std::invalid_argument for no patches.
double typicalPatchSize(const std::vector<BezierPatch>& patches);

class ReliefVisibility {
 public:
  static constexpr double kHidePixels = 3.0;
  static constexpr double kShowPixels = 3.1;
  static constexpr double kFullPixels = 6.0;

  // `feature_size`: metres on the surface between neighbouring features of the relief (> 0).
  explicit ReliefVisibility(double feature_size);

  // With `pixels_per_metre` at the human (pixelsPerMetre, tessellation.h, at its nearest point);
  // returns shown().
  bool update(double pixels_per_metre);
  bool shown() const { return shown_; }
  // How much of the relief to draw: 0 while hidden (up to kHidePixels at least), 1 from
  // kFullPixels, a smoothstep from kHidePixels between (by the last update; 1 before any).
  double fade() const { return fade_; }
  double featureSize() const { return feature_size_; }

 private:
  double feature_size_;
  bool shown_ = true;
  double fade_ = 1.0;
};

}  // namespace dressed_human
