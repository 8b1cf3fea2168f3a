// Bicubic patch evaluation and tessellation throughput.
//   vertices/s of grid evaluation (target >= 20 M/s per core at the default density),
//   time to re-tessellate 100 patches per frame (layout reused) and to build a layout.
#include "dressed_human/core/surfaces/bezier_patch.h"
#include "dressed_human/core/surfaces/generalized_cylinder.h"
#include "dressed_human/core/surfaces/tessellation.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace dressed_human {
namespace {

// A limb-like tube of `stacks` x 4 patches (no caps): 100 patches for 25 stacks.
PatchSurface limb(int stacks) {
  std::vector<CylinderRing> rings;
  for (int r = 0; r <= 3 * stacks; ++r) {
    const double z = 0.02 * r;
    rings.push_back({z, 0.05 + 0.02 * std::sin(7.0 * z), 0.04 + 0.015 * std::cos(5.0 * z)});
  }
  return makeGeneralizedCylinder(rings, 0.0, 0.0);
}

// Grid evaluation: each patch on a (level+1)^2 grid, the default level being Tessellator's.
void BM_EvaluateGrid(benchmark::State& state) {
  const int level = static_cast<int>(state.range(0));
  const PatchSurface surface = limb(25);
  const BernsteinTable table = BernsteinTable::uniform(level);
  const std::size_t per_patch = table.size() * table.size();
  std::vector<Eigen::Vector3f> positions(per_patch), normals(per_patch), tangents_u(per_patch), tangents_v(per_patch);
  const SurfaceSampleArrays out{positions.data(), normals.data(), tangents_u.data(), tangents_v.data()};
  for (auto _ : state) {
    for (const BezierPatch& patch : surface.patches) {
      patch.evaluateGrid(table, table, out);
      benchmark::ClobberMemory();
    }
  }
  const double vertices = static_cast<double>(per_patch * surface.patches.size());
  state.counters["vertices/s"] = benchmark::Counter(vertices, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_EvaluateGrid)->Arg(Tessellator::kDefaultLevel)->Arg(4)->Arg(16)->Arg(32);

// The same with a collapsed edge in every patch (caps): the limit-normal path on one row in level+1.
void BM_EvaluateGridWithPoles(benchmark::State& state) {
  const int level = static_cast<int>(state.range(0));
  const PatchSurface surface =
      makeGeneralizedCylinder({{0.0, 0.05, 0.05}, {0.1, 0.05, 0.05}, {0.2, 0.05, 0.05}, {0.3, 0.05, 0.05}}, 0.05, 0.05);
  std::vector<BezierPatch> caps(surface.patches.begin() + 4, surface.patches.end());
  const BernsteinTable table = BernsteinTable::uniform(level);
  const std::size_t per_patch = table.size() * table.size();
  std::vector<Eigen::Vector3f> positions(per_patch), normals(per_patch), tangents_u(per_patch), tangents_v(per_patch);
  const SurfaceSampleArrays out{positions.data(), normals.data(), tangents_u.data(), tangents_v.data()};
  for (auto _ : state) {
    for (const BezierPatch& patch : caps) {
      patch.evaluateGrid(table, table, out);
      benchmark::ClobberMemory();
    }
  }
  state.counters["vertices/s"] =
      benchmark::Counter(static_cast<double>(per_patch * caps.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_EvaluateGridWithPoles)->Arg(Tessellator::kDefaultLevel);

void BM_PointSample(benchmark::State& state) {
  const PatchSurface surface = limb(1);
  const BezierPatch& patch = surface.patches[0];
  double u = 0.0;
  for (auto _ : state) {
    u = u < 0.99 ? u + 0.01 : 0.0;
    benchmark::DoNotOptimize(patch.sample(u, 0.37));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_PointSample);

// Per-frame cost: 100 patches, uniform default level, layout reused (only vertices evaluated).
void BM_Tessellate100PatchesPerFrame(benchmark::State& state) {
  const int level = static_cast<int>(state.range(0));
  const PatchSurface surface = limb(25);
  Tessellator tessellator;
  tessellator.tessellateUniform(surface.patches, surface.topology, level);
  for (auto _ : state) {
    benchmark::DoNotOptimize(tessellator.tessellateUniform(surface.patches, surface.topology, level).positions.data());
  }
  state.counters["vertices"] = static_cast<double>(tessellator.mesh().vertexCount());
  state.counters["triangles"] = static_cast<double>(tessellator.mesh().triangleCount());
  state.counters["vertices/s"] = benchmark::Counter(static_cast<double>(tessellator.mesh().vertexCount()),
                                                    benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Tessellate100PatchesPerFrame)->Arg(Tessellator::kDefaultLevel)->Arg(16)->Unit(benchmark::kMicrosecond);

// Per-frame cost with adaptive levels chosen every frame (levels stable, so no layout rebuild).
void BM_Tessellate100PatchesAdaptive(benchmark::State& state) {
  const PatchSurface surface = limb(25);
  Tessellator tessellator;
  for (auto _ : state) {
    benchmark::DoNotOptimize(tessellator.tessellateToError(surface.patches, surface.topology, 2e-4).positions.data());
  }
  state.counters["triangles"] = static_cast<double>(tessellator.mesh().triangleCount());
}
BENCHMARK(BM_Tessellate100PatchesAdaptive)->Unit(benchmark::kMicrosecond);

// First frame / level change: the vertex and triangle layout is built from scratch.
void BM_Tessellate100PatchesLayoutBuild(benchmark::State& state) {
  const PatchSurface surface = limb(25);
  for (auto _ : state) {
    Tessellator tessellator;
    benchmark::DoNotOptimize(tessellator.tessellateUniform(surface.patches, surface.topology).positions.data());
  }
}
BENCHMARK(BM_Tessellate100PatchesLayoutBuild)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace dressed_human

BENCHMARK_MAIN();
