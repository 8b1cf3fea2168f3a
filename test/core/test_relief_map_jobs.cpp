// The relief-map builds a renderer polls: results arrive without waiting, a request made while a
// build runs is built next, and a bad parameter comes back as an error, not an exception.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

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
  jobs.startCloth();
  const std::vector<FinishedReliefMap> done = pollFor(jobs, 2);
  ASSERT_EQ(done.size(), 2u);
  for (const FinishedReliefMap& map : done) {
    ASSERT_TRUE(map.map) << map.error;
    EXPECT_EQ(map.normal_rgb, encodeNormalMapRgb(*map.map));
    EXPECT_EQ(jobs.map(map.kind), map.map);
  }
  EXPECT_EQ(jobs.map(ReliefKind::kSkin)->width, ReliefMapJobs::kSkinMapSize);
  const ReliefMap wrinkles = makeWrinkleMap(garmentWrinkleMapSpec());
  ASSERT_EQ(jobs.map(ReliefKind::kCloth)->width, wrinkles.height);
  EXPECT_EQ(jobs.map(ReliefKind::kCloth)->heights, transposed(wrinkles).heights);
  EXPECT_GT(ReliefMapJobs::clothHeightToTile(), 0.0f);
  EXPECT_TRUE(jobs.poll().empty());
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
