// A garment built from its description (SPEC §3, seed paper 000 §3): bicubic Bezier patches
// whose control net follows the skeleton (garment_control_net.h: shape points fixed in bone
// frames, continuity points as midpoints, C1 across every internal boundary in every pose).
//
// Patch layout. The trunk part is a ring lattice of 4 patch columns around the body (front-left,
// back-left, back-right, front-right: 2 front + 2 back per patch row) and patch rows from top to
// bottom; u runs down the garment, v around it counter-clockwise seen from above, so normals
// (F_u x F_v) point outwards.
//   jacket     torso 2 rows x 4 = 8 patches + each sleeve 1 row x 2 around = 12
//   skirt      hips row + leg row, 2 x 4 = 8; the leg row's hem follows Eq. 8' (thigh/shank)
//   pants      hips row (4) + two leg tubes of 2 patches (front, back): the leg row's left and
//              right patches are not joined; each leg's front joins its own back at the inseam.
//              The eight patches meet at the crotch; C1 there forces the eight control points
//              next to it onto it (kCollapsed): the only non-midpoint continuity points.
//   one_piece  bodice 2 rows + skirt 2 rows (4 x 4 = 16) in one lattice, so the waist row is a
//              boundary like any other: C1 by the same midpoint rule; optional sleeves (+4)
// Lower (leg) rows sit at normalized lengths f1 c, f2 c and c (legs.rows, default 1/3, 2/3) on Eq. 8'.
//
// Body shape (Eq. 5, a, b, c per bone) is applied to every shape point in its bone frame, and
// the skirt's d_i, d_j (hence c_k) are the shaped bone lengths, so a changed body carries
// through to the garment.
#pragma once

#include "dressed_human/core/forward_kinematics.h"
#include "dressed_human/core/garment_control_net.h"
#include "dressed_human/core/garment_description.h"
#include "dressed_human/core/skeleton.h"

#include <vector>

namespace dressed_human {

class Garment {
 public:
  // Throws GarmentError if the description does not fit the skeleton.
  Garment(const GarmentDescription& description, const Skeleton& skeleton,
          const BodyShape& shape = BodyShape());

  void pose(const SkeletonPose& pose) { net_.pose(pose); }

  const GarmentDescription& description() const { return description_; }
  const GarmentControlNet& net() const { return net_; }
  GarmentControlNet& net() { return net_; }
  const std::vector<BezierPatch>& patches() const { return net_.patches(); }
  const PatchTopology& topology() const { return net_.topology(); }
  // The legs part's c_k and the c actually used (after `length: knee`); 0 for a jacket.
  double kneeLength() const { return knee_length_; }
  double length() const { return length_; }

 private:
  GarmentDescription description_;
  GarmentControlNet net_;
  double knee_length_ = 0.0;
  double length_ = 0.0;
};

}  // namespace dressed_human
