// Shared vertices split per patch: every triangle sees its own patch's (u, v), so a per-patch
// relief tile is not squeezed into the strip of triangles along a patch edge; positions stay the
// source vertex's.
#include "dressed_human/core/surfaces/patch_corner_split.h"

#include "dressed_human/core/surfaces/generalized_cylinder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <stdexcept>

namespace dressed_human {
namespace {

PatchSurface tube() {
  return makeGeneralizedCylinder({{0.0, 0.10, 0.08}, {0.20, 0.05, 0.05}, {0.40, 0.07, 0.06}, {0.60, 0.04, 0.04}}, 0.08,
                                 0.03);
}

// The largest (u, v) span of any triangle: at most the grid step within one patch.
float largestTriangleSpan(const std::vector<std::uint32_t>& indices, const std::vector<Eigen::Vector2f>& uv) {
  float largest = 0.0f;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    for (int a = 0; a < 3; ++a) {
      const Eigen::Vector2f d = uv[indices[t + a]] - uv[indices[t + (a + 1) % 3]];
      largest = std::max(largest, d.cwiseAbs().maxCoeff());
    }
  }
  return largest;
}

TEST(PatchCornerSplit, EveryTriangleSeesItsOwnPatchParameters) {
  const PatchSurface surface = tube();
  Tessellator tessellator;
  std::mt19937 random(3);
  std::uniform_int_distribution<int> level(1, 9);
  PatchCornerSplit split;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<int> levels(surface.patches.size());
    for (int& l : levels) l = level(random);
    const TriangleMesh& mesh = tessellator.tessellate(surface.patches, surface.topology, levels);
    splitPatchCorners(mesh, tessellator.triangleCornerParameters(), split);
    ASSERT_EQ(split.indices.size(), mesh.indices.size());
    ASSERT_EQ(split.source.size(), split.uv.size());
    const auto& corners = tessellator.triangleCornerParameters();
    std::set<std::uint32_t> copied;
    for (std::size_t c = 0; c < split.indices.size(); ++c) {
      const std::uint32_t v = split.indices[c];
      EXPECT_EQ(split.source[v], mesh.indices[c]) << "same position";
      EXPECT_LT((split.uv[v] - corners[c].cast<float>()).norm(), 1e-5f) << "corner " << c;
      EXPECT_EQ(split.patch[v], mesh.triangle_patch[c / 3]) << "corner " << c;
      if (v >= mesh.vertexCount()) copied.insert(mesh.indices[c]);
    }
    for (std::size_t i = 0; i < mesh.vertexCount(); ++i) EXPECT_EQ(split.source[i], i);
    // Only vertices on shared edges and poles are copied, for the patches that do not own them.
    EXPECT_GT(copied.size(), 0u);
    EXPECT_LT(split.source.size(), 2 * mesh.vertexCount());
    // Without the split some triangles run across a whole patch; with it none spans more than
    // a grid step (at level 1 a whole patch).
    EXPECT_GT(largestTriangleSpan(mesh.indices, mesh.uv), 0.5f);
    EXPECT_LE(largestTriangleSpan(split.indices, split.uv),
              1.0f / *std::min_element(levels.begin(), levels.end()) + 1e-5f);
  }
}

TEST(PatchCornerSplit, MismatchedCornerCountsAreRefused) {
  const PatchSurface surface = tube();
  Tessellator tessellator;
  const TriangleMesh& mesh = tessellator.tessellateUniform(surface.patches, surface.topology, 3);
  PatchCornerSplit split;
  std::vector<Eigen::Vector2d> corners = tessellator.triangleCornerParameters();
  corners.pop_back();
  EXPECT_THROW(splitPatchCorners(mesh, corners, split), std::invalid_argument);
  TriangleMesh broken = mesh;
  broken.indices[0] = static_cast<std::uint32_t>(mesh.vertexCount());
  EXPECT_THROW(splitPatchCorners(broken, tessellator.triangleCornerParameters(), split), std::invalid_argument);
}

}  // namespace
}  // namespace dressed_human
