// Per-patch texture coordinates at shared vertices. The tessellator gives a vertex on an edge two
// patches share to one of them, with that patch's (u, v); a per-patch texture interpolated over
// the other patch's triangles then runs from the owner's u = 1 to this patch's u = 0.1, and the
// whole tile is squeezed into one strip of triangles along the edge. The split gives each patch
// its own copy of such a vertex, with the (u, v) it has in that patch (the tessellator's
// triangle corner parameters). A copy keeps its source's position, so the surface stays
// watertight to the bit; only the texture coordinate differs.
#pragma once

#include "dressed_human/core/surfaces/tessellation.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace dressed_human {

struct PatchCornerSplit {
  std::vector<std::uint32_t> source;   ///< per split vertex: the mesh vertex it copies
  std::vector<Eigen::Vector2f> uv;     ///< per split vertex: (u, v) in the patch of its triangles
  std::vector<std::uint32_t> patch;    ///< per split vertex: that patch
  std::vector<std::uint32_t> indices;  ///< 3 per triangle, into the split vertices
};

/// The mesh's vertices first (source i = i, their own uv and patch), then one copy per (vertex,
/// patch, (u, v)) where a patch other than the vertex's own, or another (u, v), meets it (at a
/// welded pole, one patch's triangles give it several). `corner_parameters`: 3 per triangle
/// (Tessellator::triangleCornerParameters). Throws std::invalid_argument when the counts do not
/// match the mesh.
void splitPatchCorners(const TriangleMesh& mesh, const std::vector<Eigen::Vector2d>& corner_parameters,
                       PatchCornerSplit& out);

}  // namespace dressed_human
