// One dressed human's whole frame in the core (HumanModel::update: pose, levels, tessellation or
// layout, corner split, wrinkle strength, bounds), as the rviz display calls it: every vertex
// evaluated here (CPU) or only the control points posed and the layout kept (the renderer's vertex
// shader evaluates them), at a fixed level and by screen error from 3 m and 12 m. Poses cycle
// through the walk, so automatic levels move as they do on screen.
#include "dressed_human/core/model/human_model.h"
#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace dressed_human {
namespace {

const std::string kSource = DRESSED_HUMAN_SOURCE_DIR;

struct Fixture {
  Skeleton skeleton = Skeleton::fromUrdfFile(kSource + "/urdf/human.urdf");
  BodyDescription body = loadBodyDescriptionFile(kSource + "/config/bodies/default.yaml", skeleton);
  std::vector<SkeletonPose> poses;
  Fixture() {
    const ForwardKinematics kinematics(skeleton, body.shape);
    MotionEvaluator walk(loadMotionFile(kSource + "/config/motions/walk.yaml"));
    JointAngles angles;
    RigidTransform root;
    poses.resize(64);
    for (std::size_t i = 0; i < poses.size(); ++i) {
      walk.evaluate(walk.motion().period * static_cast<double>(i) / poses.size(), angles, root);
      kinematics.compute(root, angles, poses[i]);
    }
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

// range(0): 0 CPU vertices, 1 the renderer's; range(1): 0 the fixed default level, else the
// camera's distance in metres (1000 px viewport, 0.8 rad, 1 px error, covered patches hidden).
void HumanModelUpdate(benchmark::State& state) {
  HumanModelSettings settings;
  settings.garment_directory = kSource + "/config/garments";
  HumanModel model(fixture().skeleton, fixture().body, settings);
  model.setVertexEvaluation(state.range(0) == 0 ? VertexEvaluation::kCpu : VertexEvaluation::kRenderer);
  LevelOfDetail lod;
  if (state.range(1) > 0) {
    lod.automatic = true;
    lod.hide_covered = state.range(1) >= 12;
    lod.camera = CameraView{Eigen::Vector3d(static_cast<double>(state.range(1)), 0.0, 1.0), 0.8, 1000.0};
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const SkeletonPose& pose = fixture().poses[i++ % fixture().poses.size()];
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
