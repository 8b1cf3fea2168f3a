#pragma once
// Whether a relief can be seen on screen, per human and relief kind, so that a renderer can draw
// it with a cheaper, flat material when it cannot. A relief's features (skin cells, cloth folds)
// that cover fewer than about two pixels are averaged away by the normal map's mip chain anyway:
// sampling it then buys a flat normal at the fragment shader's full price. The switch has
// hysteresis (off below kHidePixels, on again above kShowPixels), so a human walking at the
// threshold distance does not pop between the two looks every frame. Nor does the relief pop on
// or off at the switch: fade() brings it in from nothing at kShowPixels to full at kFullPixels
// (a renderer scales the relief's strength by it), so it is already flat where it is switched
// off and still flat where it is switched on, and it fades out as features near pixel size,
// where a normal map would shimmer.

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
  static constexpr double kHidePixels = 2.0;
  static constexpr double kShowPixels = 2.5;
  static constexpr double kFullPixels = 6.0;

  // `feature_size`: metres on the surface between neighbouring features of the relief (> 0).
  explicit ReliefVisibility(double feature_size);

  // With `pixels_per_metre` at the human (pixelsPerMetre, tessellation.h, at its nearest point);
  // returns shown().
  bool update(double pixels_per_metre);
  bool shown() const { return shown_; }
  // How much of the relief to draw: 0 up to kShowPixels, 1 from kFullPixels, a smoothstep
  // between (by the last update; 1 before any).
  double fade() const { return fade_; }
  double featureSize() const { return feature_size_; }

 private:
  double feature_size_;
  bool shown_ = true;
  double fade_ = 1.0;
};

}  // namespace dressed_human
