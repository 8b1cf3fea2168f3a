// A generalized cylinder of bicubic Bezier patches around the z axis: elliptical cross-sections,
// 4 patches around, optional dome caps whose pole is a collapsed patch edge. The shape the skin
// gives a bone (SPEC §2); also the closed test surface of the tessellation tests and tools.
#pragma once

#include "dressed_human/core/surfaces/bezier_patch.h"
#include "dressed_human/core/surfaces/tessellation.h"

#include <vector>

namespace dressed_human {

// One ring of control points: an ellipse with semi-axes radius_x, radius_y at height z,
// drawn with the usual 4-arc Bezier circle.
struct CylinderRing {
  double z;
  double radius_x;
  double radius_y;
};

struct PatchSurface {
  std::vector<BezierPatch> patches;
  PatchTopology topology;
};

// rings.size() must be 3k + 1 (k >= 1): rings 3s..3s+3 are the v control rows of stack s, so
// rings 3s are on the surface and the others shape it. A cap height > 0 closes that end with 4
// dome patches whose pole lies that far beyond the end ring (v = 0 collapsed at the bottom pole,
// v = 1 at the top pole); 0 leaves the end open. Patch order: stacks bottom-up, 4 around each
// (angle increasing, u along the angle, v along z), then bottom cap, then top cap. Normals point
// outwards. Throws std::invalid_argument on a bad ring count, non-finite values, radii <= 0 or
// negative cap heights.
PatchSurface makeGeneralizedCylinder(const std::vector<CylinderRing>& rings, double bottom_cap_height,
                                     double top_cap_height);

// A closed capsule 0.6 m long, 2 stacks of 4 side patches and a dome at each end (16 patches),
// with bulges and a waist so that curvature varies from patch to patch: the surface the
// tessellator's error is measured on (its tests, the tessellation_accuracy tool).
PatchSurface makeBulgingCapsule();

}  // namespace dressed_human
