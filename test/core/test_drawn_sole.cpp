// Issue 39: the sole slide in stance measured on the skin as the display draws it, not only on
// the sole points the walker plants: every sampled point of the drawn feet that is on the ground
// (within PlantedFeet::kContactBand) stays within 5 mm of where it touched down until it lifts.
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "dressed_human/core/surfaces/skin.h"
#include "locomotion_test_support.h"

namespace dressed_human {
namespace {

using namespace locomotion_test;

struct DrawnSoleRecord {
  double worst_slide = 0.0;  // m
  double lowest = 1e9;       // m, the lowest point of the drawn feet
  std::size_t touches = 0;   // spells of a sampled point on the ground
};

// The patches of the drawn feet (their stacks and toe caps).
std::vector<std::uint32_t> footPatches(const Skin& skin) {
  std::vector<std::uint32_t> patches;
  for (const SkinSegment& segment : skin.segments()) {
    if (segment.name != "l_ankle" && segment.name != "r_ankle") continue;
    for (std::uint32_t p = 0; p < 4 * segment.stack_count; ++p) patches.push_back(segment.first_patch + p);
    for (std::uint32_t p = 0; segment.has_distal_cap && p < 4; ++p) patches.push_back(segment.distal_cap_first + p);
  }
  return patches;
}

DrawnSoleRecord walkOnTheDrawnSole(double speed) {
  constexpr int kSamples = 9;  // per patch edge
  Walker w = walker();
  w.place({0.0, 0.0}, 0.0);
  w.drive(speed, 0.0);
  Skin skin(skeleton(), body());
  const std::vector<std::uint32_t> patches = footPatches(skin);
  EXPECT_GE(patches.size(), 8u);
  std::map<std::size_t, Eigen::Vector2d> touched_at;  // sampled point -> where it touched down
  DrawnSoleRecord record;
  JointAngles angles;
  SkeletonPose pose;
  for (int step = 0; step < 1300; ++step) {
    w.step(0.01, angles, pose);
    if (step < 300) continue;
    skin.pose(pose);
    std::size_t sample = 0;
    for (const std::uint32_t patch : patches) {
      for (int i = 0; i < kSamples; ++i) {
        for (int j = 0; j < kSamples; ++j, ++sample) {
          const Eigen::Vector3d x = skin.patches()[patch].position(i / (kSamples - 1.0), j / (kSamples - 1.0));
          record.lowest = std::min(record.lowest, x.z());
          if (x.z() >= PlantedFeet::kContactBand) {
            touched_at.erase(sample);
            continue;
          }
          const auto [at, first] = touched_at.emplace(sample, x.head<2>());
          if (first) ++record.touches;
          record.worst_slide = std::max(record.worst_slide, (x.head<2>() - at->second).norm());
        }
      }
    }
  }
  return record;
}

class DrawnSole : public ::testing::TestWithParam<double> {};

TEST_P(DrawnSole, StandsStillOnTheGroundInStance) {
  const DrawnSoleRecord record = walkOnTheDrawnSole(GetParam());
  EXPECT_GT(record.touches, 100u);
  EXPECT_LE(record.worst_slide, 0.005);
  // Drawn feet reach no lower than the 3 mm a sole point lies off the skin (test_foot_soles).
  EXPECT_GE(record.lowest, -0.003);
  std::printf("%.1f m/s: worst slide of the drawn sole %.1f mm, lowest %.1f mm, %zu touches\n", GetParam(),
              1000.0 * record.worst_slide, 1000.0 * record.lowest, record.touches);
}
INSTANTIATE_TEST_SUITE_P(Speeds, DrawnSole, ::testing::Values(0.6, 1.2, 1.8));

}  // namespace
}  // namespace dressed_human
