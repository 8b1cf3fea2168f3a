// Continuity across the linked edges of a patch set, measured on the patches themselves:
// positions (C0) and the cross-boundary first derivatives (C1: the derivative leaving patch a
// across the edge equals the derivative entering patch b), sampled along each edge.
#pragma once

#include "dressed_human/core/surfaces/bezier_patch.h"
#include "dressed_human/core/surfaces/tessellation.h"

#include <cstddef>
#include <vector>

namespace dressed_human {

struct EdgeContinuity {
  std::size_t link = 0;           // index into topology.links()
  double position_gap = 0.0;      // max |F_a - F_b| along the edge (metres)
  double tangent_mismatch = 0.0;  // max |dF_a/dn_out - dF_b/dn_in| (metres per unit parameter)
};

// One entry per link, `samples` >= 2 points per edge (ends included).
std::vector<EdgeContinuity> measureContinuity(const std::vector<BezierPatch>& patches, const PatchTopology& topology,
                                              int samples = 9);

// Largest tangent mismatch over all links (0 for none).
double maxTangentMismatch(const std::vector<EdgeContinuity>& edges);

}  // namespace dressed_human
