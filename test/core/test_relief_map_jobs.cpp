// The relief-map builds a renderer polls: results arrive without waiting, a request made while a
// build runs is built next, and a bad parameter comes back as an error, not an exception.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "dressed_human/core/model/relief_map_jobs.h"

namespace dressed_human {
namespace {

// Polls until `count` builds have finished (at most `seconds`).
std::vector<FinishedReliefMap> pollFor(ReliefMapJobs& jobs, std::size_t count, int seconds = 60) {
  std::vector<FinishedReliefMap> all;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  while (all.size() < count && std::chrono::steady_clock::now() < deadline) {
    for (FinishedReliefMap& done : jobs.poll()) all.push_back(std::move(done));
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return all;
}

TEST(ReliefMapJobs, BuildsBothMapsOffThisThread) {
  ReliefMapJobs jobs;
  EXPECT_TRUE(jobs.poll().empty());
  jobs.requestSkin(SkinReliefParameters());
  jobs.requestCloth();
  const std::vector<FinishedReliefMap> done = pollFor(jobs, 2);
  ASSERT_EQ(done.size(), 2u);
  for (const FinishedReliefMap& map : done) {
    ASSERT_TRUE(map.map) << map.error;
    ASSERT_TRUE(map.normal_map);
    ASSERT_FALSE(map.normal_map->levels.empty());
    EXPECT_EQ(map.normal_map->width, map.map->width);
    if (map.kind == ReliefKind::kSkin) {
      EXPECT_EQ(map.normal_map->channels, 3);
      EXPECT_EQ(map.normal_map->levels, encodeNormalMapMips(*map.map).levels);
      EXPECT_FALSE(map.fold_tiles);
    } else {
      ASSERT_TRUE(map.fold_tiles);
      EXPECT_EQ(map.normal_map->channels, 4);
      EXPECT_EQ(map.normal_map->levels, encodeFoldTilesMips(*map.fold_tiles).levels);
      EXPECT_EQ(map.map.get(), &map.fold_tiles->strong);
    }
    EXPECT_EQ(jobs.map(map.kind), map.map);
  }
  EXPECT_EQ(jobs.map(ReliefKind::kSkin)->width, ReliefMapJobs::kSkinMapSize);
  const ReliefMap wrinkles = makeWrinkleMap(garmentWrinkleMapSpec());
  ASSERT_EQ(jobs.map(ReliefKind::kCloth)->width, wrinkles.height);
  EXPECT_EQ(jobs.map(ReliefKind::kCloth)->heights, transposed(wrinkles).heights);
  // Square pixels are square in space (oriented_folds.h turns the slopes with the lookups).
  const WrinkleMapSpec spec = garmentWrinkleMapSpec();
  EXPECT_NEAR(2.0 * spec.cell.half_width_x * spec.cells_around,
              2.0 * spec.alpha[0] * spec.cell.half_length_y * spec.rows, 1e-12);
  EXPECT_EQ(spec.width_pixels, spec.height_pixels);
  EXPECT_GT(ReliefMapJobs::clothHeightToTile(), 0.0f);
  EXPECT_TRUE(jobs.poll().empty());
}

// Ten displays of ten humans: the maps are built once, running or done, and shared.
TEST(ReliefMapJobs, JobsAskingForTheSameMapShareOneBuild) {
  const std::size_t before = ReliefMapJobs::buildCount();
  std::vector<std::unique_ptr<ReliefMapJobs>> humans;
  for (int h = 0; h < 10; ++h) {
    humans.push_back(std::make_unique<ReliefMapJobs>());
    humans.back()->requestSkin(SkinReliefParameters());
    humans.back()->requestCloth();
  }
  EXPECT_EQ(ReliefMapJobs::buildCount() - before, 2u) << "one skin and one cloth build for ten humans";
  std::vector<std::vector<FinishedReliefMap>> done;
  for (auto& jobs : humans) done.push_back(pollFor(*jobs, 2));
  // Each human's maps in the order they finished: compared by kind.
  const auto ofKind = [](const std::vector<FinishedReliefMap>& maps, ReliefKind kind) -> const FinishedReliefMap& {
    return maps[0].kind == kind ? maps[0] : maps[1];
  };
  for (const auto& maps : done) {
    ASSERT_EQ(maps.size(), 2u);
    ASSERT_NE(maps[0].kind, maps[1].kind);
    for (const ReliefKind kind : {ReliefKind::kSkin, ReliefKind::kCloth}) {
      EXPECT_EQ(ofKind(maps, kind).map, ofKind(done[0], kind).map);  // the same map, not a copy
      EXPECT_EQ(ofKind(maps, kind).normal_map, ofKind(done[0], kind).normal_map);
    }
  }
  const std::shared_ptr<const ReliefMap> skin = ofKind(done[0], ReliefKind::kSkin).map;
  // An eleventh human, after the builds ended, gets them at once without a new build.
  ReliefMapJobs late;
  late.requestSkin(SkinReliefParameters());
  late.requestCloth();
  EXPECT_EQ(late.poll().size(), 2u);
  EXPECT_EQ(late.map(ReliefKind::kSkin), skin);
  EXPECT_EQ(ReliefMapJobs::buildCount() - before, 2u);
  // Other parameters are another map; once nobody holds a map, asking again builds it again.
  SkinReliefParameters other;
  other.seed = 7;
  late.requestSkin(other);
  ASSERT_EQ(pollFor(late, 1).size(), 1u);
  EXPECT_NE(late.map(ReliefKind::kSkin), skin);
  EXPECT_EQ(ReliefMapJobs::buildCount() - before, 3u);
}

TEST(ReliefMapJobs, ARequestDuringABuildIsBuiltNextAndOnlyTheLastOne) {
  ReliefMapJobs jobs;
  SkinReliefParameters first, second, third;
  second.seed = 2;
  third.seed = 3;
  jobs.requestSkin(first);
  jobs.requestSkin(second);  // almost surely while the first builds; superseded by the third
  jobs.requestSkin(third);
  // Two builds (the first, then the third), or three if the first ended before the second request.
  const std::vector<FinishedReliefMap> done = pollFor(jobs, 3, 10);
  ASSERT_GE(done.size(), 2u);
  ASSERT_TRUE(done.back().map) << done.back().error;
  const ReliefMap expected = SkinRelief(third).render(ReliefMapJobs::kSkinMapSize, ReliefMapJobs::kSkinMapSize);
  EXPECT_EQ(done.back().map->heights, expected.heights);
  EXPECT_TRUE(jobs.poll().empty());
}

TEST(ReliefMapJobs, ABadParameterComesBackAsAnErrorAndKeepsTheLastMap) {
  ReliefMapJobs jobs;
  jobs.requestSkin(SkinReliefParameters());
  ASSERT_EQ(pollFor(jobs, 1).size(), 1u);
  const std::shared_ptr<const ReliefMap> good = jobs.map(ReliefKind::kSkin);
  ASSERT_TRUE(good);
  SkinReliefParameters bad;
  bad.levels = 9;
  jobs.requestSkin(bad);
  const std::vector<FinishedReliefMap> done = pollFor(jobs, 1);
  ASSERT_EQ(done.size(), 1u);
  EXPECT_FALSE(done[0].map);
  EXPECT_NE(done[0].error.find("levels"), std::string::npos) << done[0].error;
  EXPECT_EQ(jobs.map(ReliefKind::kSkin), good);
}

// Fold softness (issue 40): another softness is another cloth map, built as asked; 0 is the exact
// folds; one outside [0, kMaxFoldSoftness] comes back as an error naming it, the last map kept.
TEST(ReliefMapJobs, FoldSoftnessBuildsItsOwnClothMap) {
  ReliefMapJobs jobs;
  jobs.requestCloth(0.0);
  ASSERT_EQ(pollFor(jobs, 1).size(), 1u);
  const std::shared_ptr<const ReliefMap> exact = jobs.map(ReliefKind::kCloth);
  ASSERT_TRUE(exact);
  EXPECT_EQ(exact->heights, garmentFoldTiles(512, 0.0).strong.heights);
  EXPECT_EQ(garmentWrinkleMapSpec(0.0).surface, WrinkleSurface::exactFolds);
  jobs.requestCloth(0.1);
  ASSERT_EQ(pollFor(jobs, 1).size(), 1u);
  const std::shared_ptr<const ReliefMap> soft = jobs.map(ReliefKind::kCloth);
  ASSERT_TRUE(soft);
  EXPECT_NE(soft->heights, exact->heights);
  EXPECT_EQ(soft->heights, garmentFoldTiles(512, 0.1).strong.heights);
  jobs.requestCloth(kMaxFoldSoftness + 0.1);
  const std::vector<FinishedReliefMap> done = pollFor(jobs, 1);
  ASSERT_EQ(done.size(), 1u);
  EXPECT_FALSE(done[0].map);
  EXPECT_NE(done[0].error.find("fold softness"), std::string::npos) << done[0].error;
  EXPECT_EQ(jobs.map(ReliefKind::kCloth), soft);
}

// The blur a softness asks for is what the harmonics give, never more (and within one harmonic).
TEST(ReliefMapJobs, FoldBlurComesFromWholeHarmonics) {
  for (const double blur : {0.01, 0.03, 0.0296, 0.1, 0.12, 0.2, 0.3}) {
    const int harmonics = smoothHarmonicsForBlur(blur);
    EXPECT_LE(smoothFoldBlur(harmonics), blur + 1e-12) << blur;
    if (harmonics > 1) {
      EXPECT_GT(smoothFoldBlur(harmonics - 1), blur) << blur;
    }
  }
  EXPECT_EQ(smoothHarmonicsForBlur(smoothFoldBlur(20)), 20);  // the earlier fixed 20 harmonics
  EXPECT_THROW(smoothHarmonicsForBlur(0.0), std::invalid_argument);
  EXPECT_THROW(smoothHarmonicsForBlur(-1.0), std::invalid_argument);
}

TEST(ReliefMapJobs, SameSkinParametersComparesTheUserFields) {
  SkinReliefParameters a, b;
  EXPECT_TRUE(sameSkinParameters(a, b));
  b.roundness = 0.5;
  EXPECT_FALSE(sameSkinParameters(a, b));
  b = a;
  b.profile = BezierProfile::fromEdgeSlope(5.0);
  EXPECT_FALSE(sameSkinParameters(a, b));
}

}  // namespace
}  // namespace dressed_human
