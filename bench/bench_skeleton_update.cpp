// One full skeleton update: Eq. 1 for the 48 DOFs and the root (order m), then FK to every frame.
// Target (issue 2): <= 2 us at m = 8.
#include <benchmark/benchmark.h>

#include <cmath>

#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/motion/motion_evaluator.h"

namespace dressed_human {
namespace {

Motion motionOfOrder(std::size_t order) {
  Motion motion;
  motion.period = 1.1;
  for (std::size_t i = 0; i < Motion::kSeriesCount; ++i) {
    FourierSeries& s = const_cast<FourierSeries&>(motion.series(i));
    s.period = motion.period;
    s.a0 = 0.1;
    for (std::size_t n = 1; n <= order; ++n) {
      s.a.push_back(0.2 / static_cast<double>(n) * std::cos(static_cast<double>(i + n)));
      s.b.push_back(0.2 / static_cast<double>(n) * std::sin(static_cast<double>(i * n)));
    }
  }
  motion.root.forward_speed = 1.2;
  return motion;
}

const Skeleton& humanSkeleton() {
  static const Skeleton skeleton = Skeleton::fromUrdfFile(std::string(DRESSED_HUMAN_SOURCE_DIR) + "/urdf/human.urdf");
  return skeleton;
}

void FullUpdate(benchmark::State& state) {
  MotionEvaluator evaluator(motionOfOrder(static_cast<std::size_t>(state.range(0))));
  ForwardKinematics kinematics(humanSkeleton());
  JointAngles angles{};
  RigidTransform root;
  SkeletonPose pose;
  double time = 0.0;
  for (auto _ : state) {
    evaluator.evaluate(time, angles, root);
    kinematics.compute(root, angles, pose);
    benchmark::DoNotOptimize(pose);
    time += 0.001;
  }
}
BENCHMARK(FullUpdate)->Arg(1)->Arg(4)->Arg(8)->Arg(12);

void MotionOnly(benchmark::State& state) {
  MotionEvaluator evaluator(motionOfOrder(static_cast<std::size_t>(state.range(0))));
  JointAngles angles{};
  RigidTransform root;
  double time = 0.0;
  for (auto _ : state) {
    evaluator.evaluate(time, angles, root);
    benchmark::DoNotOptimize(angles);
    time += 0.001;
  }
}
BENCHMARK(MotionOnly)->Arg(8);

void ForwardKinematicsOnly(benchmark::State& state) {
  ForwardKinematics kinematics(humanSkeleton());
  JointAngles angles{};
  for (std::size_t i = 0; i < kDofCount; ++i) angles[i] = 0.01 * static_cast<double>(i);
  RigidTransform root;
  SkeletonPose pose;
  for (auto _ : state) {
    kinematics.compute(root, angles, pose);
    benchmark::DoNotOptimize(pose);
    angles[0] += 1e-6;
  }
}
BENCHMARK(ForwardKinematicsOnly);

}  // namespace
}  // namespace dressed_human

BENCHMARK_MAIN();
