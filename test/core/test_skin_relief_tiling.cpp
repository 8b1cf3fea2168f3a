// The skin relief at its true size (issue 40): cells as large in metres as the region's measured
// ones on every patch, whatever the patch's size, and the tile running on across the seams inside
// a segment.
#include "dressed_human/core/model/skin_relief_tiling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "garment_test_support.h"

namespace dressed_human {
namespace {

using garment_test::body;
using garment_test::skeleton;

// The relief texture coordinate of (u, v) on `patch`, in tiles.
Eigen::Vector2d texture(const SkinReliefTiling& tiling, std::size_t patch, double u, double v) {
  return Eigen::Vector2d(u, v).cwiseProduct(tiling.tilesPerPatch()[patch].cast<double>());
}

// Equal modulo whole tiles: the same point of the periodic tile.
bool sameTilePoint(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = a - b;
  return std::abs(d.x() - std::round(d.x())) < 1e-6 && std::abs(d.y() - std::round(d.y())) < 1e-6;
}

TEST(SkinReliefTiling, CellsAreTheirRegionsMeasuredSizeOnEveryPatch) {
  const Skin skin(skeleton(), body());
  const SkinReliefTiling tiling(skin);
  const std::vector<SkinRegion>& regions = skinRegions();
  ASSERT_EQ(regions.front().name, "forearm");
  ASSERT_EQ(tiling.tilesPerPatch().size(), skin.patches().size());
  std::vector<int> patches_per_region(regions.size(), 0);
  for (std::size_t p = 0; p < skin.patches().size(); ++p) {
    const Eigen::Vector2f tiles = tiling.tilesPerPatch()[p];
    EXPECT_GE(tiles.minCoeff(), 1.0f);
    EXPECT_EQ(tiles.x(), std::round(tiles.x()));
    EXPECT_EQ(tiles.y(), std::round(tiles.y()));
    const int region = tiling.segmentRegion(static_cast<std::size_t>(skin.patchSegment(p)));
    ++patches_per_region[static_cast<std::size_t>(region)];
    const double wanted = cellSpacingForArea(regions[static_cast<std::size_t>(region)].cell_area_mm2);
    const Eigen::Vector2d spacing = tiling.cellSpacing(p);
    // Along a limb (v) a stack's count is its own; around (u) one count serves a segment whose
    // girth changes along it, and a cap narrows to its pole: within a factor 2 there.
    const std::string where = "patch " + std::to_string(p) + " of " + skin.segments()[skin.patchSegment(p)].name;
    const SkinSegment& segment = skin.segments()[static_cast<std::size_t>(skin.patchSegment(p))];
    const bool cap = p < segment.first_patch || p >= segment.first_patch + 4 * segment.stack_count;
    if (!cap) {
      EXPECT_GT(spacing.x(), 0.5 * wanted) << where;
      EXPECT_LT(spacing.x(), 2.0 * wanted) << where;
    }
    if (tiles.y() > 1.0f) {  // a stack shorter than a tile keeps one, with smaller cells
      EXPECT_GT(spacing.y(), wanted / 1.5) << where;
      EXPECT_LT(spacing.y(), wanted * 1.5) << where;
    }
  }
  for (std::size_t r = 0; r < regions.size(); ++r) EXPECT_GT(patches_per_region[r], 0) << regions[r].name;
  // About a millimetre: a cell per mm^2 of forearm (Trojahn et al. 2014).
  EXPECT_NEAR(SkinReliefTiling::measuredForearmSpacing(), 1.07e-3, 0.01e-3);
  EXPECT_NEAR(tiling.largestCellSpacing(), cellSpacingForArea(regions[3].cell_area_mm2), 1e-12);
}

TEST(SkinReliefTiling, TheTileRunsOnAcrossTheSeamsInsideASegment) {
  const Skin skin(skeleton(), body());
  const SkinReliefTiling tiling(skin);
  const std::vector<BezierPatch>& patches = skin.patches();
  int seams = 0;
  for (const SkinSegment& segment : skin.segments()) {
    for (std::uint32_t stack = 0; stack < segment.stack_count; ++stack) {
      for (std::uint32_t q = 0; q < 4; ++q) {
        const std::uint32_t patch = segment.first_patch + 4 * stack + q;
        const std::uint32_t beside = segment.first_patch + 4 * stack + (q + 1) % 4;
        for (const double t : {0.0, 0.3, 0.77, 1.0}) {
          // Around: this patch's u = 1 edge is the next quarter's u = 0 edge.
          ASSERT_LT((patches[patch].position(1.0, t) - patches[beside].position(0.0, t)).norm(), 1e-9);
          EXPECT_TRUE(sameTilePoint(texture(tiling, patch, 1.0, t), texture(tiling, beside, 0.0, t)))
              << segment.name << " stack " << stack << " quarter " << q;
          if (stack + 1 < segment.stack_count) {  // along: the next stack's v = 0 edge
            const std::uint32_t above = patch + 4;
            ASSERT_LT((patches[patch].position(t, 1.0) - patches[above].position(t, 0.0)).norm(), 1e-9);
            EXPECT_TRUE(sameTilePoint(texture(tiling, patch, t, 1.0), texture(tiling, above, t, 0.0)))
                << segment.name << " stack " << stack << " quarter " << q;
          }
        }
        ++seams;
      }
    }
  }
  EXPECT_GT(seams, 100);
}

TEST(SkinReliefTiling, ACellSizeScalesEveryRegionAndABadOneIsRefused) {
  const Skin skin(skeleton(), body());
  SkinReliefTiling tiling(skin);
  const std::vector<Eigen::Vector2f> measured = tiling.tilesPerPatch();
  tiling.setForearmCellSpacing(2.0 * SkinReliefTiling::measuredForearmSpacing());
  float tiles_before = 0.0f, tiles_after = 0.0f;
  for (std::size_t p = 0; p < measured.size(); ++p) {
    tiles_before += measured[p].prod();
    tiles_after += tiling.tilesPerPatch()[p].prod();
  }
  EXPECT_LT(tiles_after, 0.4f * tiles_before);  // cells twice as large: about a quarter the tiles
  for (const double bad : {0.0, -1e-3, std::nan(""), static_cast<double>(INFINITY)}) {
    EXPECT_THROW(tiling.setForearmCellSpacing(bad), std::invalid_argument) << bad;
  }
}

}  // namespace
}  // namespace dressed_human
