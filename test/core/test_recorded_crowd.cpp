#include "dressed_human/core/model/recorded_crowd.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace dressed_human {
namespace {

// 10 frames per second. Person 1 walks along x at 1 m/s in frames 0-4; person 2 stands in frames
// 2-3; person 3 is seen once, in frame 4; person 4 is lost in frame 2 and found again in frame 3,
// 0.4 m further.
const char* const kRecording =
    "# framerate: 10 fps\n"
    "1 0 0.0 0 1.7\n1 1 0.1 0 1.7\n1 2 0.2 0 1.7\n1 3 0.3 0 1.7\n1 4 0.4 0 1.7\n"
    "2 2 5 5 1.6\n2 3 5 5 1.6\n"
    "3 4 -1 -1 1.8\n"
    "4 0 0 2 1.7\n4 1 0 2.1 1.7\n4 3 0 2.5 1.7\n";

RecordedCrowd crowd(const ScenePlacement& placement = {}) {
  return RecordedCrowd(parsePedestrianTrajectories(kRecording, "recording.txt"), placement);
}

std::vector<RecordedPerson> at(const RecordedCrowd& recorded, std::size_t sample) {
  return std::vector<RecordedPerson>(recorded.begin(sample), recorded.end(sample));
}

std::vector<std::uint64_t> idsAt(const RecordedCrowd& recorded, std::size_t sample) {
  std::vector<std::uint64_t> ids;
  for (const RecordedPerson& person : at(recorded, sample)) ids.push_back(person.id);
  return ids;
}

TEST(RecordedCrowd, EachSampleHoldsThePeoplePresentInItsFrameById) {
  const RecordedCrowd recorded = crowd();
  EXPECT_EQ(recorded.sampleCount(), 5u);
  EXPECT_EQ(recorded.personCount(), 4u);
  EXPECT_DOUBLE_EQ(recorded.sampleRate(), 10.0);
  EXPECT_DOUBLE_EQ(recorded.duration(), 0.4);
  EXPECT_EQ(idsAt(recorded, 0), (std::vector<std::uint64_t>{1, 4}));
  EXPECT_EQ(idsAt(recorded, 1), (std::vector<std::uint64_t>{1, 4}));
  EXPECT_EQ(idsAt(recorded, 2), (std::vector<std::uint64_t>{1, 2}));  // 4 is lost here: absent, not held
  EXPECT_EQ(idsAt(recorded, 3), (std::vector<std::uint64_t>{1, 2, 4}));
  EXPECT_EQ(idsAt(recorded, 4), (std::vector<std::uint64_t>{1, 3}));
  EXPECT_EQ(recorded.countAt(3), 3u);
  EXPECT_TRUE(at(recorded, 4)[1].position.isApprox(Eigen::Vector2d(-1, -1)));
}

TEST(RecordedCrowd, VelocitiesAreCentralDifferencesOneSidedAtTheEnds) {
  const RecordedCrowd recorded = crowd();
  for (std::size_t sample = 0; sample < 5; ++sample) {
    const RecordedPerson walker = at(recorded, sample)[0];
    EXPECT_NEAR((walker.velocity - Eigen::Vector2d(1.0, 0.0)).norm(), 0.0, 1e-12) << "sample " << sample;
    ASSERT_TRUE(walker.heading.has_value());
    EXPECT_NEAR(*walker.heading, 0.0, 1e-12);
  }
  const RecordedPerson standing = at(recorded, 2)[1];
  EXPECT_EQ(standing.velocity, Eigen::Vector2d::Zero());
  EXPECT_FALSE(standing.heading.has_value());
  EXPECT_EQ(at(recorded, 4)[1].velocity, Eigen::Vector2d::Zero());  // seen once: no motion known
  // Person 4 around its gap: from frame 0 to frame 3, 0.5 m in 0.3 s.
  EXPECT_NEAR(at(recorded, 1)[1].velocity.y(), 0.5 / 0.3, 1e-12);
  EXPECT_NEAR(at(recorded, 3)[2].velocity.y(), 0.4 / 0.2, 1e-12);  // one-sided: 0.4 m in the 0.2 s since frame 1
}

TEST(RecordedCrowd, AHeadingOnlyAbove0point3MetresPerSecond) {
  const RecordedCrowd slow(
      parsePedestrianTrajectories("# framerate: 10\n1 0 0 0\n1 1 0.029 0\n2 0 0 0\n2 1 0.031 0\n", "slow"), {});
  EXPECT_FALSE(at(slow, 0)[0].heading.has_value());
  EXPECT_TRUE(at(slow, 0)[1].heading.has_value());
}

TEST(RecordedCrowd, ThePlacementRotatesAboutTheOriginThenShifts) {
  ScenePlacement placement;
  placement.yaw = M_PI / 2;
  placement.offset = Eigen::Vector2d(10.0, -2.0);
  const RecordedCrowd recorded = crowd(placement);
  const RecordedPerson walker = at(recorded, 1)[0];  // at (0.1, 0) walking +x
  EXPECT_NEAR((walker.position - Eigen::Vector2d(10.0, -1.9)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((walker.velocity - Eigen::Vector2d(0.0, 1.0)).norm(), 0.0, 1e-12);  // turned, not shifted
  EXPECT_NEAR(*walker.heading, M_PI / 2, 1e-12);
  EXPECT_NEAR((at(recorded, 2)[1].position - Eigen::Vector2d(5.0, 3.0)).norm(), 0.0,
              1e-12);  // (5, 5) -> (-5, 5) -> (5, 3)
}

}  // namespace
}  // namespace dressed_human
