#include "dressed_human/core/surfaces/patch_corner_split.h"

#include <stdexcept>
#include <string>
#include <cmath>
#include <map>
#include <tuple>

namespace dressed_human {

void splitPatchCorners(const TriangleMesh& mesh, const std::vector<Eigen::Vector2d>& corner_parameters,
                       PatchCornerSplit& out) {
  const std::size_t vertices = mesh.uv.size();
  if (corner_parameters.size() != mesh.indices.size() || mesh.triangle_patch.size() * 3 != mesh.indices.size()) {
    throw std::invalid_argument("splitPatchCorners: " + std::to_string(corner_parameters.size()) + " corner parameters and " +
                                std::to_string(mesh.triangle_patch.size()) + " triangle patches for " +
                                std::to_string(mesh.indices.size()) + " triangle corners");
  }
  out.source.resize(vertices);
  out.uv.assign(mesh.uv.begin(), mesh.uv.end());
  for (std::size_t i = 0; i < vertices; ++i) out.source[i] = static_cast<std::uint32_t>(i);
  out.indices.resize(mesh.indices.size());
  // Corner parameters are exact grid fractions and the vertex's uv their float: a tolerance far
  // below a grid step (1/64 at the finest level) and far above float rounding.
  constexpr float kSameParameter = 1e-5f;
  // (vertex, patch, uv in millionths) -> split vertex; uv too, since at a welded pole one
  // patch's triangles give the one vertex several (u, v).
  std::map<std::tuple<std::uint32_t, std::uint32_t, long, long>, std::uint32_t> copies;
  for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
    const std::uint32_t vertex = mesh.indices[c];
    if (vertex >= vertices) {
      throw std::invalid_argument("splitPatchCorners: index " + std::to_string(vertex) + " beyond " +
                                  std::to_string(vertices) + " vertices");
    }
    const Eigen::Vector2f uv = corner_parameters[c].cast<float>();
    if ((uv - mesh.uv[vertex]).cwiseAbs().maxCoeff() <= kSameParameter) {
      out.indices[c] = vertex;
      continue;
    }
    const auto key = std::make_tuple(vertex, mesh.triangle_patch[c / 3], std::lround(uv.x() * 1e6f), std::lround(uv.y() * 1e6f));
    const auto [copy, added] = copies.emplace(key, static_cast<std::uint32_t>(out.source.size()));
    if (added) {
      out.source.push_back(vertex);
      out.uv.push_back(uv);
    }
    out.indices[c] = copy->second;
  }
}

}  // namespace dressed_human
