#include "dressed_human/core/surfaces/patch_corner_split.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace dressed_human {

void splitPatchCorners(const TriangleMesh& mesh, const std::vector<Eigen::Vector2d>& corner_parameters,
                       PatchCornerSplit& out) {
  const std::size_t vertices = mesh.uv.size();
  if (corner_parameters.size() != mesh.indices.size() || mesh.triangle_patch.size() * 3 != mesh.indices.size()) {
    throw std::invalid_argument("splitPatchCorners: " + std::to_string(corner_parameters.size()) +
                                " corner parameters and " + std::to_string(mesh.triangle_patch.size()) +
                                " triangle patches for " + std::to_string(mesh.indices.size()) + " triangle corners");
  }
  out.source.resize(vertices);
  out.uv.assign(mesh.uv.begin(), mesh.uv.end());
  if (mesh.vertex_patch.size() != vertices) {
    throw std::invalid_argument("splitPatchCorners: " + std::to_string(mesh.vertex_patch.size()) +
                                " vertex patches for " + std::to_string(vertices) + " vertices");
  }
  out.patch.assign(mesh.vertex_patch.begin(), mesh.vertex_patch.end());
  for (std::size_t i = 0; i < vertices; ++i) out.source[i] = static_cast<std::uint32_t>(i);
  out.indices.resize(mesh.indices.size());
  // Corner parameters are exact grid fractions and the vertex's uv their float: a tolerance far
  // below a grid step (1/64 at the finest level) and far above float rounding.
  constexpr float kSameParameter = 1e-5f;
  // Each vertex's copies as a chain (most vertices have none, one on an edge one or two, a pole
  // a few): first_copy[vertex], then next_copy[copy - vertices]. Matched by patch and (u, v),
  // since at a welded pole one patch's triangles give the one vertex several (u, v).
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> first_copy(vertices, kNone), next_copy, copy_patch;
  for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
    const std::uint32_t vertex = mesh.indices[c];
    if (vertex >= vertices) {
      throw std::invalid_argument("splitPatchCorners: index " + std::to_string(vertex) + " beyond " +
                                  std::to_string(vertices) + " vertices");
    }
    const Eigen::Vector2f uv = corner_parameters[c].cast<float>();
    const auto same = [&](const Eigen::Vector2f& other) {
      return (uv - other).cwiseAbs().maxCoeff() <= kSameParameter;
    };
    const std::uint32_t patch = mesh.triangle_patch[c / 3];
    // Another patch's vertex is copied even where its (u, v) happens to be the same (a welded
    // pole): the patches' relief tiles may differ (SurfacePart::relief_tiles).
    if (same(mesh.uv[vertex]) && mesh.vertex_patch[vertex] == patch) {
      out.indices[c] = vertex;
      continue;
    }
    std::uint32_t* link = &first_copy[vertex];
    while (*link != kNone && !(copy_patch[*link - vertices] == patch && same(out.uv[*link]))) {
      link = &next_copy[*link - vertices];
    }
    std::uint32_t copy = *link;
    if (copy == kNone) {
      copy = static_cast<std::uint32_t>(out.source.size());
      *link = copy;  // before the push_backs, which may move next_copy
      out.source.push_back(vertex);
      out.uv.push_back(uv);
      out.patch.push_back(patch);
      next_copy.push_back(kNone);
      copy_patch.push_back(patch);
    }
    out.indices[c] = copy;
  }
}

}  // namespace dressed_human
