// One dressed human's whole frame in the core (HumanModel::update: pose, levels, tessellation or
// layout, corner split, wrinkle strength, bounds), as the rviz display calls it: every vertex
// evaluated here (CPU) or only the control points posed and the layout kept (the renderer's vertex
// shader evaluates them), at a fixed level and by screen error from 3 m and 12 m. Poses cycle
// through the walk, so automatic levels move as they do on screen.
#include "dressed_human/core/model/human_model.h"

#include "dressed_human/core/model/calibration_poses.h"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "walk_fixture.h"

namespace dressed_human {
namespace {

// range(0): 0 CPU vertices, 1 the renderer's; range(1): 0 the fixed default level, else the
// camera's distance in metres (1000 px viewport, 0.8 rad, 1 px error, covered patches hidden).
void HumanModelUpdate(benchmark::State& state) {
  HumanModelSettings settings;
  settings.garment_directory = benchmarkSourcePath("config/garments");
  settings.calibration_poses = calibrationPosesFromFile(benchmarkSourcePath("config/motions/walk.yaml"));  // as the display
  HumanModel model(walkFixture().skeleton, walkFixture().body, settings);
  model.setVertexEvaluation(state.range(0) == 0 ? VertexEvaluation::kCpu : VertexEvaluation::kGpu);
  LevelOfDetail lod;
  if (state.range(1) > 0) {
    lod.automatic = true;
    lod.hide_covered = state.range(1) >= 12;
    lod.camera = CameraView{Eigen::Vector3d(static_cast<double>(state.range(1)), 0.0, 1.0), 0.8, 1000.0};
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const SkeletonPose& pose = walkFixture().poses[i++ % walkFixture().poses.size()];
    model.update(pose.root, pose.bone_in_world, lod);
    benchmark::DoNotOptimize(model.parts().data());
  }
  state.counters["triangles"] = static_cast<double>(model.drawnTriangleCount());
}
BENCHMARK(HumanModelUpdate)
    ->ArgNames({"renderer", "metres"})
    ->ArgsProduct({{0, 1}, {0, 3, 12}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace dressed_human

BENCHMARK_MAIN();
