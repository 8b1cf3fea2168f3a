// Relief-map generation cost on one core.
//  * SkinMap/1024 with 3 levels: the production path, target <= 50 ms. With roundness 0 (as
//    here) render() rasterises each cell's boundary polygon sector by sector (s linear per
//    sector, reference gradients precomputed at construction); SkinMapRounded keeps the per-pixel
//    path (bucket grid for level 1, children lists below).
//  * SkinMapBruteForce: the same map with every pixel scanning all seeds (and their 9 periodic
//    images) of each level -- the reference, run at a smaller size because it is O(pixels x seeds).
//  * SkinHierarchyBuild: seeds, clipping and wobble, paid once per parameter set -- now including
//    the rasteriser's per-cell boundary polygons and sectors (most of its time).
//  * SkinMapWithMipsAndNormals, MipChain, NormalMapRgb: the map as uploaded (mips + RGB normals).
//  * WrinkleMap: one pose's worth of per-cell alphas, exact folds and 8-term Gaussians. Gaussian
//    fits are cached across maps (wrinkle_map.cpp), so after the first iteration this measures a
//    pose whose alphas were seen before; WrinkleMapNewAlphas clears nothing but uses alphas never
//    seen, i.e. pays the 5 fits every iteration.
#include "dressed_human/core/relief/skin_relief.h"
#include "dressed_human/core/relief/wrinkle_map.h"
#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/garments/garment_file.h"
#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"
#include "dressed_human/core/surfaces/tessellation.h"
#include "dressed_human/core/relief/vertex_compression.h"
#include "dressed_human/core/relief/wrinkle_placement.h"

#include <memory>
#include <string>

#include <benchmark/benchmark.h>

namespace {

using namespace dressed_human;

SkinReliefParameters benchmarkSkin() {
  SkinReliefParameters parameters;
  parameters.cell_size = 1.0 / 10.0;
  parameters.levels = 3;
  parameters.wobble = 0.15;
  parameters.seed = 3;
  return parameters;
}

void SkinHierarchyBuild(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(SkinRelief(benchmarkSkin()));
}
BENCHMARK(SkinHierarchyBuild)->Unit(benchmark::kMillisecond);

void SkinMap(benchmark::State& state) {
  const SkinRelief relief(benchmarkSkin());
  const int size = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(relief.render(size, size));
  state.counters["cells_l1"] = static_cast<double>(relief.cellCount(0));
  state.counters["cells_l3"] = static_cast<double>(relief.cellCount(2));
  state.counters["ns_per_pixel"] = benchmark::Counter(
      static_cast<double>(size) * size, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(SkinMap)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond);

// Resolution x levels, for the speed chart of docs/EVALUATION.md (scripts/make_evaluation.py).
void SkinMapLevels(benchmark::State& state) {
  SkinReliefParameters parameters = benchmarkSkin();
  parameters.levels = static_cast<int>(state.range(1));
  const SkinRelief relief(parameters);
  const int size = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(relief.render(size, size));
}
BENCHMARK(SkinMapLevels)->ArgsProduct({{256, 512, 1024}, {1, 2, 3}})->Unit(benchmark::kMillisecond);

// What a caller uploads: the map, its mip chain (down to 1x1) and the 8-bit normal map of every
// mip level. The two extra stages are also timed alone on a fixed map.
void SkinMapWithMipsAndNormals(benchmark::State& state) {
  const SkinRelief relief(benchmarkSkin());
  for (auto _ : state) {
    const std::vector<ReliefMap> chain = buildMipChain(relief.render(1024, 1024));
    for (const ReliefMap& level : chain) benchmark::DoNotOptimize(encodeNormalMapRgb(level));
  }
}
BENCHMARK(SkinMapWithMipsAndNormals)->Unit(benchmark::kMillisecond);

void MipChain(benchmark::State& state) {
  const ReliefMap map = SkinRelief(benchmarkSkin()).render(1024, 1024);
  for (auto _ : state) benchmark::DoNotOptimize(buildMipChain(map));
}
BENCHMARK(MipChain)->Unit(benchmark::kMillisecond);

void NormalMapRgb(benchmark::State& state) {
  const ReliefMap map = SkinRelief(benchmarkSkin()).render(1024, 1024);
  for (auto _ : state) benchmark::DoNotOptimize(encodeNormalMapRgb(map));
}
BENCHMARK(NormalMapRgb)->Unit(benchmark::kMillisecond);

void SkinMapRounded(benchmark::State& state) {
  SkinReliefParameters parameters = benchmarkSkin();
  parameters.roundness = 0.4;
  const SkinRelief relief(parameters);
  for (auto _ : state) benchmark::DoNotOptimize(relief.render(1024, 1024));
}
BENCHMARK(SkinMapRounded)->Unit(benchmark::kMillisecond);

void SkinMapBruteForce(benchmark::State& state) {
  const SkinRelief relief(benchmarkSkin());
  const int size = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(relief.renderBruteForce(size, size));
  state.counters["ns_per_pixel"] = benchmark::Counter(
      static_cast<double>(size) * size, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(SkinMapBruteForce)->Arg(256)->Unit(benchmark::kMillisecond)->Iterations(2);

void WrinkleMap(benchmark::State& state) {
  WrinkleMapSpec spec;
  spec.width_pixels = 1024;
  spec.height_pixels = 1024;
  spec.chain = "X";
  spec.cells_around = 8;
  spec.rows = 4;
  spec.alpha.clear();
  for (int cell = 0; cell < spec.rows * spec.cells_around; ++cell) spec.alpha.push_back(0.6 + 0.4 * (cell % 5) / 4.0);
  spec.surface = state.range(0) == 0 ? WrinkleSurface::exactFolds : WrinkleSurface::gaussianApproximation;
  for (auto _ : state) benchmark::DoNotOptimize(makeWrinkleMap(spec));
  state.SetLabel(state.range(0) == 0 ? "exact folds, 5 distinct alphas" : "8 Gaussians, 5 fits");
}
BENCHMARK(WrinkleMap)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void WrinkleMapNewAlphas(benchmark::State& state) {
  WrinkleMapSpec spec;
  spec.width_pixels = 1024;
  spec.height_pixels = 1024;
  spec.surface = WrinkleSurface::gaussianApproximation;
  static double shift = 0.0;  // static: repetitions must not meet their predecessors' alphas either
  for (auto _ : state) {
    shift += 1e-9;  // distinct alphas every iteration: no cache hits
    spec.alpha.clear();
    for (int cell = 0; cell < spec.rows * spec.cells_around; ++cell)
      spec.alpha.push_back(0.6 + 0.4 * (cell % 5) / 4.0 - shift);
    benchmark::DoNotOptimize(makeWrinkleMap(spec));
  }
  state.SetLabel("8 Gaussians, 5 new fits");
}
BENCHMARK(WrinkleMapNewAlphas)->Unit(benchmark::kMillisecond)->Iterations(3);

// Wrinkle placement (wrinkle_placement.h), jacket + pants in one walk pose (knee bent in swing).
//  * WrinkleVertexCompression/level: the per-frame path of a renderer, VertexCompression::evaluate
//    on both garments' meshes (alpha and strength per vertex); level 4 is LevelOfDetail's default
//    (Skin::kDefaultLevel), 8 the Tessellator's. Target: well under 50 us for the outfit.
//  * WrinklePoseMap: one pose's wrinkle atlas for the pants (128 px tiles) and the region summary.
struct WrinkleOutfit {
  Skeleton skeleton = Skeleton::fromUrdfFile(std::string(DRESSED_HUMAN_SOURCE_DIR) + "/urdf/human.urdf");
  BodyDescription body =
      loadBodyDescriptionFile(std::string(DRESSED_HUMAN_SOURCE_DIR) + "/config/bodies/default.yaml", skeleton);
  std::vector<Garment> garments;
  std::vector<std::unique_ptr<WrinklePlacement>> placements;
  SkeletonPose pose;
  WrinkleOutfit() {
    MotionEvaluator evaluator(loadMotionFile(std::string(DRESSED_HUMAN_SOURCE_DIR) + "/config/motions/walk.yaml"));
    JointAngles angles{};
    RigidTransform root;
    evaluator.evaluate(0.3 * evaluator.motion().period, angles, root);
    ForwardKinematics(skeleton, body.shape).compute(root, angles, pose);
    for (const char* name : {"pants", "jacket"}) {
      garments.emplace_back(
          loadGarmentFile(std::string(DRESSED_HUMAN_SOURCE_DIR) + "/config/garments/" + name + ".yaml", skeleton),
          skeleton, body.shape);
      placements.push_back(std::make_unique<WrinklePlacement>(garments.back(), skeleton, body.shape));
      garments.back().pose(pose);
    }
  }
};

void WrinkleVertexCompression(benchmark::State& state) {
  const WrinkleOutfit outfit;
  const int level = static_cast<int>(state.range(0));
  std::vector<std::unique_ptr<Tessellator>> tessellators;
  std::vector<VertexCompression> compressions(outfit.garments.size());
  std::vector<std::vector<float>> alpha(outfit.garments.size()), strength(outfit.garments.size());
  std::size_t vertices = 0;
  for (std::size_t g = 0; g < outfit.garments.size(); ++g) {
    tessellators.push_back(std::make_unique<Tessellator>());
    const TriangleMesh& mesh =
        tessellators[g]->tessellateUniform(outfit.garments[g].patches(), outfit.garments[g].topology(), level);
    compressions[g].prepare(mesh, outfit.placements[g]->restPatches());
    alpha[g].resize(mesh.vertexCount());
    strength[g].resize(mesh.vertexCount());
    vertices += mesh.vertexCount();
  }
  for (auto _ : state) {
    for (std::size_t g = 0; g < outfit.garments.size(); ++g) {
      compressions[g].evaluate(tessellators[g]->mesh(), alpha[g].data(), strength[g].data());
      benchmark::DoNotOptimize(strength[g].data());
    }
    benchmark::ClobberMemory();
  }
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["ns_per_vertex"] = benchmark::Counter(
      static_cast<double>(vertices), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(WrinkleVertexCompression)->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond);

// The layout change a renderer pays when the level of detail changes (per garment pair).
void WrinkleVertexCompressionPrepare(benchmark::State& state) {
  const WrinkleOutfit outfit;
  std::vector<std::unique_ptr<Tessellator>> tessellators;
  for (std::size_t g = 0; g < outfit.garments.size(); ++g) {
    tessellators.push_back(std::make_unique<Tessellator>());
    tessellators[g]->tessellateUniform(outfit.garments[g].patches(), outfit.garments[g].topology(),
                                       static_cast<int>(state.range(0)));
  }
  for (auto _ : state) {
    for (std::size_t g = 0; g < outfit.garments.size(); ++g) {
      VertexCompression compression;
      compression.prepare(tessellators[g]->mesh(), outfit.placements[g]->restPatches());
      benchmark::DoNotOptimize(compression.vertexPatches().data());
    }
  }
}
BENCHMARK(WrinkleVertexCompressionPrepare)->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond);

void WrinklePoseMap(benchmark::State& state) {
  const WrinkleOutfit outfit;
  for (auto _ : state)
    benchmark::DoNotOptimize(makePoseWrinkleMap(*outfit.placements[0], outfit.garments[0].patches(), outfit.pose, 128));
  state.SetLabel("pants, " + std::to_string(outfit.garments[0].patches().size()) + " tiles of 128 px");
}
BENCHMARK(WrinklePoseMap)->Unit(benchmark::kMillisecond);

void WrinkleRegions(benchmark::State& state) {
  const WrinkleOutfit outfit;
  for (auto _ : state) {
    for (std::size_t g = 0; g < outfit.garments.size(); ++g) {
      benchmark::DoNotOptimize(outfit.placements[g]->measureRegions(outfit.garments[g].patches(), outfit.pose));
    }
  }
  state.SetLabel("jacket + pants, all regions");
}
BENCHMARK(WrinkleRegions)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
