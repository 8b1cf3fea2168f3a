// Relief-map generation cost on one core.
//  * SkinMap/1024 with 3 levels: the production path (bucket grid for level 1, children lists
//    below); target <= 50 ms.
//  * SkinMapBruteForce: the same map with every pixel scanning all seeds (and their 9 periodic
//    images) of each level -- the reference, run at a smaller size because it is O(pixels x seeds).
//  * SkinHierarchyBuild: seeds, clipping and wobble, paid once per parameter set.
//  * WrinkleMap: one pose's worth of per-cell alphas, exact folds and 8-term Gaussians.
#include "dressed_human/core/skin_relief.h"
#include "dressed_human/core/wrinkle_map.h"

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
  state.counters["ns_per_pixel"] = benchmark::Counter(static_cast<double>(size) * size,
                                                      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(SkinMap)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond);

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
  state.counters["ns_per_pixel"] = benchmark::Counter(static_cast<double>(size) * size,
                                                      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
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

}  // namespace

BENCHMARK_MAIN();
