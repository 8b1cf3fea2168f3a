#include "dressed_human/core/surfaces/tessellation.h"

#include "dressed_human/core/surfaces/generalized_cylinder.h"
#include "dressed_human/core/surfaces/triangle_samples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <map>
#include <new>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "allocation_counter.h"

namespace dressed_human {
namespace {

struct EdgeUse {
  int forward = 0;   // as (a, b) with a < b
  int backward = 0;  // as (b, a)
};

std::map<std::pair<std::uint32_t, std::uint32_t>, EdgeUse> edgeUses(const TriangleMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, EdgeUse> uses;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t a = mesh.indices[3 * t + c];
      const std::uint32_t b = mesh.indices[3 * t + (c + 1) % 3];
      if (a < b)
        ++uses[{a, b}].forward;
      else
        ++uses[{b, a}].backward;
    }
  }
  return uses;
}

// Every edge in exactly two triangles, once in each direction (consistent orientation), every
// vertex used, no degenerate triangle, and Euler characteristic 2 (a sphere: nothing welded wrong).
void expectClosedOrientedSphere(const TriangleMesh& mesh) {
  ASSERT_GT(mesh.triangleCount(), 0u);
  std::vector<bool> used(mesh.vertexCount(), false);
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::uint32_t* tri = &mesh.indices[3 * t];
    ASSERT_TRUE(tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2]);
    for (int c = 0; c < 3; ++c) {
      ASSERT_LT(tri[c], mesh.vertexCount());
      used[tri[c]] = true;
    }
  }
  EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
  const auto uses = edgeUses(mesh);
  for (const auto& [edge, use] : uses) {
    ASSERT_EQ(use.forward, 1) << "edge " << edge.first << "-" << edge.second;
    ASSERT_EQ(use.backward, 1) << "edge " << edge.first << "-" << edge.second;
  }
  const long euler =
      static_cast<long>(mesh.vertexCount()) - static_cast<long>(uses.size()) + static_cast<long>(mesh.triangleCount());
  EXPECT_EQ(euler, 2);
}

void expectValidAttributes(const TriangleMesh& mesh) {
  ASSERT_EQ(mesh.normals.size(), mesh.vertexCount());
  ASSERT_EQ(mesh.uv.size(), mesh.vertexCount());
  ASSERT_EQ(mesh.triangle_patch.size(), mesh.triangleCount());
  for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
    ASSERT_TRUE(mesh.positions[v].allFinite());
    ASSERT_TRUE(mesh.normals[v].allFinite());
    EXPECT_NEAR(mesh.normals[v].norm(), 1.0f, 1e-5f);
    ASSERT_TRUE(mesh.tangents_u[v].allFinite() && mesh.tangents_v[v].allFinite());
  }
}

// Every triangle corner lies on its own patch at the recorded parameters: shared vertices are on
// both patches, so the mesh has no geometric crack either.
void expectCornersOnTheirPatches(const TriangleMesh& mesh, const Tessellator& tessellator,
                                 const std::vector<BezierPatch>& patches) {
  const auto& corners = tessellator.triangleCornerParameters();
  ASSERT_EQ(corners.size(), mesh.indices.size());
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const BezierPatch& patch = patches[mesh.triangle_patch[c / 3]];
    const Eigen::Vector3d expected = patch.position(corners[c].x(), corners[c].y());
    ASSERT_LT((mesh.positions[mesh.indices[c]].cast<double>() - expected).norm(), 1e-6) << c;
  }
}

// Largest |F(x) - L(x)| over samples of every triangle: an upper bound of the distance between
// mesh and surface (each is within it of the other). Also per patch.
double maxParametricError(const TriangleMesh& mesh, const Tessellator& tessellator,
                          const std::vector<BezierPatch>& patches, std::vector<double>* per_patch = nullptr) {
  constexpr int kSteps = 5;
  if (per_patch) per_patch->assign(patches.size(), 0.0);
  double worst = 0.0;
  forEachTriangleSample(mesh, tessellator.triangleCornerParameters(), kSteps, [&](const TriangleSample& sample) {
    const std::uint32_t patch = mesh.triangle_patch[sample.triangle];
    const double error = (sample.on_mesh - patches[patch].position(sample.uv.x(), sample.uv.y())).norm();
    worst = std::max(worst, error);
    if (per_patch) (*per_patch)[patch] = std::max((*per_patch)[patch], error);
  });
  return worst;
}

TEST(GeneralizedCylinder, TopologyMatchesCoincidentEdges) {
  const PatchSurface surface = makeBulgingCapsule();
  ASSERT_EQ(surface.patches.size(), 16u);
  const PatchTopology found = PatchTopology::fromCoincidentEdges(surface.patches, 1e-12);
  ASSERT_EQ(found.links().size(), surface.topology.links().size());
  ASSERT_EQ(found.links().size(), 28u);  // 4*2 around + 4 between stacks + 2*(4 + 4) for the caps
  for (std::uint32_t p = 0; p < surface.patches.size(); ++p) {
    for (int e = 0; e < 4; ++e) {
      EXPECT_EQ(found.isLinked(p, PatchEdge(e)), surface.topology.isLinked(p, PatchEdge(e)));
    }
  }
}

TEST(Tessellation, UniformClosedSurfaceIsWatertight) {
  const PatchSurface surface = makeBulgingCapsule();
  Tessellator tessellator;
  for (int level : {1, 2, 3, 5, 8, 16}) {
    SCOPED_TRACE(level);
    const TriangleMesh& mesh = tessellator.tessellateUniform(surface.patches, surface.topology, level);
    expectClosedOrientedSphere(mesh);
    expectValidAttributes(mesh);
    expectCornersOnTheirPatches(mesh, tessellator, surface.patches);
    // Poles are one vertex each: exactly two vertices sit on the axis.
    int on_axis = 0;
    for (const Eigen::Vector3f& p : mesh.positions) on_axis += p.head<2>().norm() < 1e-9f;
    EXPECT_EQ(on_axis, 2);
  }
}

TEST(Tessellation, MixedLevelsStayWatertight) {
  const PatchSurface surface = makeBulgingCapsule();
  Tessellator tessellator;
  std::mt19937 random(11);
  std::uniform_int_distribution<int> level(1, 13);
  for (int trial = 0; trial < 25; ++trial) {
    std::vector<int> levels(surface.patches.size());
    for (int& l : levels) l = level(random);
    const TriangleMesh& mesh = tessellator.tessellate(surface.patches, surface.topology, levels);
    expectClosedOrientedSphere(mesh);
    expectValidAttributes(mesh);
    expectCornersOnTheirPatches(mesh, tessellator, surface.patches);
  }
}

TEST(Tessellation, OpenTubeHasBoundaryOnlyAtItsRims) {
  const PatchSurface tube =
      makeGeneralizedCylinder({{0.0, 0.1, 0.1}, {0.1, 0.1, 0.1}, {0.2, 0.1, 0.1}, {0.3, 0.1, 0.1}}, 0.0, 0.0);
  Tessellator tessellator;
  const std::vector<int> levels = {2, 7, 3, 4};
  const TriangleMesh& mesh = tessellator.tessellate(tube.patches, tube.topology, levels);
  int boundary_edges = 0;
  for (const auto& [edge, use] : edgeUses(mesh)) {
    const int total = use.forward + use.backward;
    ASSERT_TRUE(total == 2 ? use.forward == 1 : total == 1);
    if (total == 1) {
      ++boundary_edges;
      const float z0 = mesh.positions[edge.first].z(), z1 = mesh.positions[edge.second].z();
      EXPECT_TRUE((std::abs(z0) < 1e-6f && std::abs(z1) < 1e-6f) ||
                  (std::abs(z0 - 0.3f) < 1e-6f && std::abs(z1 - 0.3f) < 1e-6f));
    }
  }
  EXPECT_EQ(boundary_edges, 2 * (2 + 7 + 3 + 4));  // open rims keep each patch's own level
}

TEST(Tessellation, AdaptiveToleranceIsHonoured) {
  const PatchSurface surface = makeBulgingCapsule();
  Tessellator tessellator;
  for (double tolerance : {2e-3, 3e-4, 1e-4}) {
    SCOPED_TRACE(tolerance);
    const TriangleMesh& mesh = tessellator.tessellateToError(surface.patches, surface.topology, tolerance);
    expectClosedOrientedSphere(mesh);
    std::vector<double> per_patch;
    const double measured = maxParametricError(mesh, tessellator, surface.patches, &per_patch);
    for (int level : tessellator.levels()) ASSERT_LT(level, Tessellator::kMaxLevel);
    EXPECT_LE(measured, tolerance);
    for (std::size_t p = 0; p < surface.patches.size(); ++p) {
      EXPECT_LE(per_patch[p], geometricErrorBound(surface.patches[p], tessellator.levels()[p]) + 1e-7);
    }
    // Not absurdly conservative either: the bound should be within ~30x of what is measured.
    EXPECT_GT(measured, tolerance / 30.0);
  }
}

TEST(Tessellation, ScreenSpaceLevelsFollowDistance) {
  const PatchSurface surface = makeBulgingCapsule();
  const BezierPatch& patch = surface.patches[0];
  CameraView camera{Eigen::Vector3d(0.0, -2.0, 0.3), 0.8, 1080.0};
  const int far_level = levelForScreenError(patch, camera, 0.5, Tessellator::kMaxLevel);
  camera.position.y() = -0.5;
  const int near_level = levelForScreenError(patch, camera, 0.5, Tessellator::kMaxLevel);
  EXPECT_LT(far_level, near_level);
  camera.position = Eigen::Vector3d(0.05, 0.05, 0.05);  // inside the control net's box
  EXPECT_EQ(levelForScreenError(patch, camera, 0.5, 20), 20);

  // The error, projected at the patch's nearest distance, stays within the pixel budget.
  camera.position = Eigen::Vector3d(0.0, -1.0, 0.3);
  Tessellator tessellator;
  const double budget = 0.5;
  const TriangleMesh& mesh = tessellator.tessellateForCamera(surface.patches, surface.topology, camera, budget);
  expectClosedOrientedSphere(mesh);
  std::vector<double> per_patch;
  maxParametricError(mesh, tessellator, surface.patches, &per_patch);
  const double focal = camera.viewport_height_pixels / (2.0 * std::tan(0.5 * camera.vertical_fov_radians));
  for (std::size_t p = 0; p < surface.patches.size(); ++p) {
    const BezierPatch& each = surface.patches[p];
    const Eigen::Vector3d nearest = camera.position.cwiseMax(each.boundingBoxMin()).cwiseMin(each.boundingBoxMax());
    EXPECT_LE(per_patch[p] * focal / (nearest - camera.position).norm(), budget) << p;
  }
  EXPECT_THROW(levelForScreenError(patch, CameraView{Eigen::Vector3d::Zero(), 0.0, 100.0}, 1.0, 8),
               std::invalid_argument);
}

TEST(Tessellation, RepeatedFramesReuseTheLayoutAndAllocateNothing) {
  PatchSurface surface = makeBulgingCapsule();
  Tessellator tessellator;
  tessellator.tessellateToError(surface.patches, surface.topology, 1e-4);
  EXPECT_EQ(tessellator.layoutBuildCount(), 1u);
  const std::vector<std::uint32_t> first_indices = tessellator.mesh().indices;

  // Move the whole surface (a new pose): same layout, new positions.
  std::vector<BezierPatch> moved;
  for (const BezierPatch& patch : surface.patches) {
    BezierPatch::ControlPoints points = patch.controlPoints();
    for (Eigen::Vector3d& p : points) p += Eigen::Vector3d(0.5, 0.0, 0.0);
    moved.emplace_back(points);
  }
  allocation_count = 0;
  counting_allocations = true;
  for (int frame = 0; frame < 5; ++frame) {
    tessellator.tessellateToError(frame % 2 ? moved : surface.patches, surface.topology, 1e-4);
    tessellator.tessellateUniform(moved, surface.topology, 6);  // alternating layouts rebuilds
  }
  counting_allocations = false;
  EXPECT_GT(tessellator.layoutBuildCount(), 1u);

  // Now the same levels every frame: no rebuild, no allocation.
  tessellator.tessellateToError(surface.patches, surface.topology, 1e-4);
  const std::size_t builds = tessellator.layoutBuildCount();
  allocation_count = 0;
  counting_allocations = true;
  for (int frame = 0; frame < 10; ++frame) {
    tessellator.tessellateToError(frame % 2 ? moved : surface.patches, surface.topology, 1e-4);
  }
  counting_allocations = false;
  EXPECT_EQ(allocation_count.load(), 0);
  EXPECT_EQ(tessellator.layoutBuildCount(), builds);
  EXPECT_EQ(tessellator.mesh().indices, first_indices);
  const TriangleMesh& mesh = tessellator.tessellateToError(moved, surface.topology, 1e-4);
  expectCornersOnTheirPatches(mesh, tessellator, moved);
}

TEST(Tessellation, RejectsInconsistentInput) {
  const PatchSurface surface = makeBulgingCapsule();
  Tessellator tessellator;
  EXPECT_THROW(tessellator.tessellate(surface.patches, surface.topology, std::vector<int>(3, 4)),
               std::invalid_argument);
  EXPECT_THROW(tessellator.tessellate(surface.patches, surface.topology, std::vector<int>(surface.patches.size(), 0)),
               std::invalid_argument);
  // Linking edges that are not the same curve is caught, not silently welded.
  PatchTopology wrong(surface.patches.size());
  wrong.link(0, PatchEdge::kU1, 2, PatchEdge::kU0, false);
  EXPECT_THROW(tessellator.tessellateUniform(surface.patches, wrong, 4), std::invalid_argument);
  PatchTopology topology(2);
  topology.link(0, PatchEdge::kV0, 1, PatchEdge::kV1, false);
  EXPECT_THROW(topology.link(0, PatchEdge::kV0, 1, PatchEdge::kU1, false), std::invalid_argument);
  EXPECT_THROW(topology.link(0, PatchEdge::kU0, 0, PatchEdge::kU0, false), std::invalid_argument);
  EXPECT_THROW(topology.link(0, PatchEdge::kU0, 5, PatchEdge::kU0, false), std::invalid_argument);
  EXPECT_THROW(levelForGeometricError(surface.patches[0], 0.0, 8), std::invalid_argument);
}

TEST(Tessellation, ReversedLinkBetweenOppositelyParametrisedPatches) {
  // Two flat patches side by side; the second one's v runs the other way along the shared edge.
  BezierPatch::ControlPoints left, right;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      left[BezierPatch::index(i, j)] = {i / 3.0, j / 3.0, 0.05 * std::sin(i + j)};
      // Right runs u towards -x and v towards -y: both mirrored, so the normals still agree.
      right[BezierPatch::index(i, j)] = {1.0 + (3 - i) / 3.0, (3 - j) / 3.0, 0.0};
    }
  }
  // The shared curve: left's u=1 edge equals right's u=1 edge reversed.
  for (int j = 0; j < 4; ++j) right[BezierPatch::index(3, 3 - j)] = left[BezierPatch::index(3, j)];
  const std::vector<BezierPatch> patches = {BezierPatch(left), BezierPatch(right)};
  const PatchTopology found = PatchTopology::fromCoincidentEdges(patches, 1e-12);
  ASSERT_EQ(found.links().size(), 1u);
  EXPECT_TRUE(found.links()[0].reversed);
  Tessellator tessellator;
  const std::vector<int> levels = {3, 5};
  const TriangleMesh& mesh = tessellator.tessellate(patches, found, levels);
  int boundary = 0, interior = 0;
  for (const auto& [edge, use] : edgeUses(mesh)) {
    const int total = use.forward + use.backward;
    ASSERT_LE(total, 2);
    (total == 2 ? interior : boundary) += 1;
  }
  // Open boundary: left 3 + 3 + 3 and right 5 + 5 + 5 segments; the shared edge is interior.
  EXPECT_EQ(boundary, 9 + 15);
  expectCornersOnTheirPatches(mesh, tessellator, patches);
}

}  // namespace
}  // namespace dressed_human
