#pragma once
// Which patches of a surface lie under other surfaces: the skin under a jacket, a skirt's
// waistband under the jacket. Seen from far enough that the gap between cloth and body is under
// a pixel or two, they only cost rasterization (on a software renderer, most of a small human's
// cost), so a renderer may skip them there.
//
// A patch is covered when, from every point of a grid on it (edges included), rays along its
// outward normal and tilted kCoverTiltDegrees from it towards both ways of both tangents all
// meet a covering surface within kMaxCoverGap: no line of sight within that cone reaches it past
// a hem, cuff or collar. Judged on the surfaces as given (a renderer passes them at rest).

#include <vector>

#include "dressed_human/core/surfaces/bezier_patch.h"

namespace dressed_human {

constexpr double kCoverTiltDegrees = 45.0;
constexpr double kMaxCoverGap = 0.3;  // metres: a garment further off is not what covers a patch
constexpr int kCoverSamplesPerSide = 4;

// Per patch of `inner`, whether the patches of `covers` (taken together) cover it. The inner
// patches' normals must point outwards (d_du x d_dv, as the skin's and the garments' do).
std::vector<bool> patchesCoveredBy(const std::vector<BezierPatch>& inner,
                                   const std::vector<const std::vector<BezierPatch>*>& covers);

}  // namespace dressed_human
