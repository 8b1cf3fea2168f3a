#include "dressed_human/core/relief/wrinkle_map.h"

#include <gtest/gtest.h>

#include <cmath>

namespace dressed_human {
namespace {

// Largest height step between horizontally / vertically adjacent pixels, interior and across the seam.
struct Steps {
  double interior_u = 0.0, seam_u = 0.0, interior_v = 0.0, seam_v = 0.0;
};

Steps measureSteps(const ReliefMap& map) {
  Steps steps;
  for (int row = 0; row < map.height; ++row) {
    for (int column = 0; column < map.width; ++column) {
      const double here = map.heights[map.index(column, row)];
      const double right = map.heights[map.index((column + 1) % map.width, row)];
      const double below = map.heights[map.index(column, (row + 1) % map.height)];
      double& u = column + 1 == map.width ? steps.seam_u : steps.interior_u;
      double& v = row + 1 == map.height ? steps.seam_v : steps.interior_v;
      u = std::max(u, std::abs(right - here));
      v = std::max(v, std::abs(below - here));
    }
  }
  return steps;
}

TEST(WrinkleMap, WrapsAroundTheLimbWithoutSeam) {
  for (const char* chain : {"X", "YY", "YXY", "I"}) {
    WrinkleMapSpec spec;
    spec.width_pixels = 240;
    spec.height_pixels = 160;
    spec.chain = chain;
    spec.cells_around = 6;
    spec.rows = 2;
    spec.alpha = {0.8, 0.6};
    const ReliefMap map = makeWrinkleMap(spec);
    const Steps steps = measureSteps(map);
    EXPECT_LE(steps.seam_u, steps.interior_u + 1e-6) << chain;
    EXPECT_LE(steps.seam_v, steps.interior_v + 1e-6) << chain;
    for (int row = 0; row < map.height; ++row)
      for (int column = 0; column < map.width; ++column) EXPECT_NEAR(map.normalAt(column, row).norm(), 1.0f, 1e-6f);
  }
}

TEST(WrinkleMap, ReliefGrowsWithCompression) {
  double previous = -1.0;
  for (double alpha : {1.0, 0.95, 0.9, 0.8, 0.7, 0.6}) {
    WrinkleMapSpec spec;
    spec.width_pixels = 64;
    spec.height_pixels = 64;
    spec.alpha = {alpha};
    const ReliefMap map = makeWrinkleMap(spec);
    const double relief = map.maximumHeight() - map.minimumHeight();
    EXPECT_GT(relief, previous) << alpha;
    previous = relief;
  }
}

TEST(WrinkleMap, PerCellAlphaAndGaussianSurface) {
  WrinkleMapSpec spec;
  spec.width_pixels = 64;
  spec.height_pixels = 64;
  spec.cells_around = 4;
  spec.rows = 2;
  spec.alpha = {1.0, 1.0, 1.0, 1.0, 0.7, 0.7, 0.7, 0.7};
  const ReliefMap exact = makeWrinkleMap(spec);
  EXPECT_FLOAT_EQ(exact.heights[exact.index(10, 5)], 0.0f);  // the uncompressed row is flat
  EXPECT_GT(exact.maximumHeight(), 0.5f);
  spec.surface = WrinkleSurface::gaussianApproximation;
  spec.gaussian_terms = 6;
  const ReliefMap smooth = makeWrinkleMap(spec);
  EXPECT_GT(smooth.maximumHeight(), 0.3f);
  // The second map reuses the cached fits: same map, bit for bit; another term count is another fit.
  const ReliefMap again = makeWrinkleMap(spec);
  EXPECT_EQ(again.heights, smooth.heights);
  EXPECT_EQ(again.slope_u, smooth.slope_u);
  spec.gaussian_terms = 3;
  EXPECT_NE(makeWrinkleMap(spec).heights, smooth.heights);
}

TEST(WrinkleMap, RejectsBadSpecs) {
  WrinkleMapSpec spec;
  spec.alpha = {0.5, 0.6, 0.7};
  EXPECT_THROW(makeWrinkleMap(spec), std::invalid_argument);
  spec.alpha = {1.2};
  EXPECT_THROW(makeWrinkleMap(spec), std::invalid_argument);
  spec.alpha = {0.7};
  spec.chain = "YX";  // cannot close around the limb
  spec.cells_around = 2;
  EXPECT_THROW(makeWrinkleMap(spec), std::invalid_argument);
  spec.chain = "X";
  spec.width_pixels = 0;
  EXPECT_THROW(makeWrinkleMap(spec), std::invalid_argument);
}

}  // namespace
}  // namespace dressed_human
