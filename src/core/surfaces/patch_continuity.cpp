#include "dressed_human/core/surfaces/patch_continuity.h"

#include <algorithm>
#include <stdexcept>

namespace dressed_human {
namespace {

// (u, v) of edge parameter t, and the sign/axis of the derivative pointing out of the patch.
void edgePoint(PatchEdge edge, double t, double& u, double& v, bool& along_u, double& outward) {
  u = t;
  v = 0.0;
  along_u = false;
  outward = -1.0;
  switch (edge) {
    case PatchEdge::kV0:
      u = t;
      v = 0.0;
      along_u = false;
      outward = -1.0;
      break;
    case PatchEdge::kV1:
      u = t;
      v = 1.0;
      along_u = false;
      outward = 1.0;
      break;
    case PatchEdge::kU0:
      u = 0.0;
      v = t;
      along_u = true;
      outward = -1.0;
      break;
    case PatchEdge::kU1:
      u = 1.0;
      v = t;
      along_u = true;
      outward = 1.0;
      break;
  }
}

}  // namespace

std::vector<EdgeContinuity> measureContinuity(const std::vector<BezierPatch>& patches, const PatchTopology& topology,
                                              int samples) {
  if (samples < 2) throw std::invalid_argument("measureContinuity: samples must be >= 2");
  if (topology.patchCount() != patches.size())
    throw std::invalid_argument("measureContinuity: topology does not fit the patches");
  std::vector<EdgeContinuity> out;
  const std::vector<EdgeLink>& links = topology.links();
  for (std::size_t l = 0; l < links.size(); ++l) {
    const EdgeLink& link = links[l];
    EdgeContinuity e;
    e.link = l;
    for (int s = 0; s < samples; ++s) {
      const double t = static_cast<double>(s) / (samples - 1);
      double ua = 0.0, va = 0.0, ub = 0.0, vb = 0.0, out_a = 1.0, out_b = 1.0;
      bool axis_a = true, axis_b = true;
      edgePoint(link.edge_a, t, ua, va, axis_a, out_a);
      edgePoint(link.edge_b, link.reversed ? 1.0 - t : t, ub, vb, axis_b, out_b);
      const PatchDerivatives da = patches[link.patch_a].derivatives(ua, va);
      const PatchDerivatives db = patches[link.patch_b].derivatives(ub, vb);
      const Eigen::Vector3d leaving = out_a * (axis_a ? da.d_du : da.d_dv);
      const Eigen::Vector3d entering = -out_b * (axis_b ? db.d_du : db.d_dv);
      e.position_gap = std::max(e.position_gap, (da.position - db.position).norm());
      e.tangent_mismatch = std::max(e.tangent_mismatch, (leaving - entering).norm());
    }
    out.push_back(e);
  }
  return out;
}

double maxTangentMismatch(const std::vector<EdgeContinuity>& edges) {
  double worst = 0.0;
  for (const EdgeContinuity& e : edges) worst = std::max(worst, e.tangent_mismatch);
  return worst;
}

}  // namespace dressed_human
