// The whole skin per frame: pose (bone frames -> world control points) and tessellate, at the
// default level and others; vertices/s of the whole frame. Poses cycle through the walk.
#include "dressed_human/core/surfaces/skin.h"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "walk_fixture.h"

namespace dressed_human {
namespace {

void BM_SkinPose(benchmark::State& state) {
  Skin skin(walkFixture().skeleton, walkFixture().body);
  std::size_t i = 0;
  for (auto _ : state) {
    skin.pose(walkFixture().poses[i++ % walkFixture().poses.size()]);
    benchmark::DoNotOptimize(skin.patches().data());
  }
  state.counters["patches"] = static_cast<double>(skin.patches().size());
}
BENCHMARK(BM_SkinPose);

// Pose + uniform tessellation (layout reused, as in a running renderer).
void BM_SkinPoseAndTessellate(benchmark::State& state) {
  const int level = static_cast<int>(state.range(0));
  Skin skin(walkFixture().skeleton, walkFixture().body);
  Tessellator tessellator;
  tessellator.tessellateUniform(skin.patches(), skin.topology(), level);
  std::size_t i = 0;
  for (auto _ : state) {
    skin.pose(walkFixture().poses[i++ % walkFixture().poses.size()]);
    const TriangleMesh& mesh = tessellator.tessellateUniform(skin.patches(), skin.topology(), level);
    benchmark::DoNotOptimize(mesh.positions.data());
  }
  const TriangleMesh& mesh = tessellator.mesh();
  state.counters["vertices"] = static_cast<double>(mesh.vertexCount());
  state.counters["triangles"] = static_cast<double>(mesh.triangleCount());
  state.counters["vertices/s"] =
      benchmark::Counter(static_cast<double>(mesh.vertexCount()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_SkinPoseAndTessellate)
    ->Arg(Skin::kDefaultLevel)
    ->Arg(2)
    ->Arg(3)
    ->Arg(6)
    ->Arg(8)
    ->Unit(benchmark::kMicrosecond);

// Pose + adaptive tessellation to a geometric error bound (levels recomputed every frame; the
// layout is rebuilt only when a level changes).
void BM_SkinPoseAndTessellateToError(benchmark::State& state) {
  const double max_error = 1e-6 * static_cast<double>(state.range(0));
  Skin skin(walkFixture().skeleton, walkFixture().body);
  Tessellator tessellator;
  std::size_t i = 0;
  for (auto _ : state) {
    skin.pose(walkFixture().poses[i++ % walkFixture().poses.size()]);
    const TriangleMesh& mesh = tessellator.tessellateToError(skin.patches(), skin.topology(), max_error);
    benchmark::DoNotOptimize(mesh.positions.data());
  }
  const TriangleMesh& mesh = tessellator.mesh();
  state.counters["vertices"] = static_cast<double>(mesh.vertexCount());
  state.counters["triangles"] = static_cast<double>(mesh.triangleCount());
  state.counters["layout_builds"] = static_cast<double>(tessellator.layoutBuildCount());
}
BENCHMARK(BM_SkinPoseAndTessellateToError)->Arg(2000)->Arg(1000)->Arg(500)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace dressed_human

BENCHMARK_MAIN();
