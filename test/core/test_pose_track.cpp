#include "dressed_human/core/skeleton/pose_track.h"

#include "locomotion_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace dressed_human {
namespace {

PoseSample sampleAt(double time, double x, double yaw, double angle) {
  PoseSample sample;
  sample.time = time;
  sample.root.translation = {x, 2.0 * x, 1.0};
  sample.root.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  sample.angles.fill(angle);
  return sample;
}

double yawOf(const RigidTransform& root) {
  const Eigen::Vector3d forward = root.rotation * Eigen::Vector3d::UnitX();
  return std::atan2(forward.y(), forward.x());
}

TEST(PoseTrack, BetweenTwoSamplesEverythingMovesInProportion) {
  PoseTrack track;
  ASSERT_TRUE(track.add(sampleAt(10.0, 0.0, 0.0, 0.2)));
  ASSERT_TRUE(track.add(sampleAt(10.1, 1.0, 1.0, 0.6)));
  RigidTransform root;
  JointAngles angles{};
  track.at(10.025, root, angles);
  EXPECT_NEAR(root.translation.x(), 0.25, 1e-9);
  EXPECT_NEAR(root.translation.y(), 0.5, 1e-9);
  EXPECT_NEAR(yawOf(root), 0.25, 1e-9);  // slerp about one axis: in proportion to the angle
  for (double angle : angles) EXPECT_NEAR(angle, 0.3, 1e-9);
}

TEST(PoseTrack, AnAngleCrossingTheWrapGoesTheShortWay) {
  PoseTrack track;
  track.add(sampleAt(0.0, 0.0, 0.0, M_PI - 0.1));
  track.add(sampleAt(1.0, 0.0, 0.0, -M_PI + 0.1));  // 0.2 rad further on, reported wrapped
  RigidTransform root;
  JointAngles angles{};
  track.at(0.5, root, angles);
  EXPECT_NEAR(std::cos(angles[7]), -1.0, 1e-9) << angles[7] << ": through pi, not through 0";
}

TEST(PoseTrack, HoldsTheEndsInsteadOfGuessing) {
  PoseTrack track;
  track.add(sampleAt(1.0, 1.0, 0.0, 0.1));
  track.add(sampleAt(2.0, 3.0, 0.0, 0.5));
  RigidTransform root;
  JointAngles angles{};
  track.at(0.0, root, angles);
  EXPECT_DOUBLE_EQ(root.translation.x(), 1.0);
  track.at(5.0, root, angles);
  EXPECT_DOUBLE_EQ(root.translation.x(), 3.0);
  EXPECT_DOUBLE_EQ(angles[0], 0.5);
}

TEST(PoseTrack, RefusesARepeatedOrOlderSampleAndKeepsTheNewestWhenFull) {
  PoseTrack track;
  EXPECT_TRUE(track.empty());
  EXPECT_TRUE(track.add(sampleAt(1.0, 0.0, 0.0, 0.0)));
  EXPECT_FALSE(track.add(sampleAt(1.0, 9.0, 0.0, 0.0)));
  EXPECT_FALSE(track.add(sampleAt(0.5, 9.0, 0.0, 0.0)));
  for (int i = 1; i <= 20; ++i) ASSERT_TRUE(track.add(sampleAt(1.0 + 0.1 * i, i, 0.0, 0.0)));
  EXPECT_DOUBLE_EQ(track.newest().time, 3.0);
  RigidTransform root;
  JointAngles angles{};
  track.at(2.95, root, angles);  // between the two newest of 21 samples, eight kept
  EXPECT_NEAR(root.translation.x(), 19.5, 1e-9);
  track.at(0.0, root, angles);  // the oldest kept: sample 13
  EXPECT_NEAR(root.translation.x(), 20.0 - PoseTrack::kCapacity + 1, 1e-9);
  track.clear();
  EXPECT_TRUE(track.empty());
}

TEST(PoseTrack, RenderDelayFollowsTheTypicalIntervalNotAnOutlier) {
  PoseTrack track;
  EXPECT_EQ(track.renderDelay(), 0.0);
  const double times[] = {0.0, 0.1, 0.2, 0.3, 0.9, 1.0};  // one late message among 10 Hz ones
  for (double t : times) track.add(sampleAt(t, 0.0, 0.0, 0.0));
  EXPECT_NEAR(track.typicalInterval(), 0.1, 1e-9);
  EXPECT_NEAR(track.renderDelay(), 0.15, 1e-9);
  PoseTrack slow;  // 1 Hz input: drawn at most half a second behind
  slow.add(sampleAt(0.0, 0.0, 0.0, 0.0));
  slow.add(sampleAt(1.0, 0.0, 0.0, 0.0));
  EXPECT_DOUBLE_EQ(slow.renderDelay(), 0.5);
}

TEST(PoseTrack, AHumanThatCannotBeDrawnIsNamedWithItsReason) {
  const PoseSample good = sampleAt(0.0, 1.0, 0.3, 0.1);
  const std::vector<double> angles(good.angles.begin(), good.angles.end());
  EXPECT_EQ(humanStateProblem(good.root, angles, 1.0), "");
  RigidTransform far = good.root;
  far.translation.x() = std::nan("");
  EXPECT_EQ(humanStateProblem(far, angles, 1.0), "its root position is not finite");
  RigidTransform unnormalised = good.root;
  unnormalised.rotation.coeffs() *= 2.0;
  EXPECT_NE(humanStateProblem(unnormalised, angles, 1.0).find("not a unit quaternion"), std::string::npos);
  RigidTransform zero = good.root;
  zero.rotation.coeffs().setZero();
  EXPECT_NE(humanStateProblem(zero, angles, 1.0).find("not a unit quaternion"), std::string::npos);
  EXPECT_EQ(humanStateProblem(good.root, std::vector<double>(47, 0.0), 1.0), "47 joint angles, expected 48");
  std::vector<double> infinite = angles;
  infinite[12] = INFINITY;
  EXPECT_EQ(humanStateProblem(good.root, infinite, 1.0), "joint angle 12 is not finite");
  EXPECT_NE(humanStateProblem(good.root, angles, 0.0).find("stature"), std::string::npos);
  EXPECT_NE(humanStateProblem(good.root, angles, std::nan("")).find("stature"), std::string::npos);
  EXPECT_EQ(humanStateProblem(good.root, angles, 1.9), "");
}

}  // namespace
}  // namespace dressed_human

namespace dressed_human {
namespace {

// A walk sent at 30 Hz and drawn at 100 Hz: every bone within twice what linear interpolation
// of its own path between two samples could miss, h^2 / 8 times its largest acceleration there
// (from the walk's own 100 Hz samples), plus half a millimetre (0.07 px at 12 m): the angles are
// interpolated, not the positions, so a turning limb's chord adds to it. Snapping to the nearest
// sample instead is 19 times that bound at its worst, over 3,500 of the 3,920 bone positions judged.
TEST(PoseTrack, AWalkSentAt30HzIsDrawnBetweenItsSamplesWithinTheInterpolationBound) {
  Walker walker = locomotion_test::walker();
  walker.place(Eigen::Vector2d::Zero(), 0.0, 0.3);
  walker.followRoute(Route{{{0.0, 0.0}, {40.0, 0.0}}, false});
  walker.setCruiseSpeed(1.3);
  const ForwardKinematics kinematics(locomotion_test::skeleton());
  constexpr double kStep = 0.01;
  constexpr int kEvery = 3;  // 30 Hz of 100 Hz
  constexpr double kFloorMetres = 5e-4;
  std::vector<PoseSample> truth;
  std::vector<std::array<RigidTransform, kBoneCount>> bones;
  SkeletonPose pose;
  for (int i = 0; i < 400; ++i) {
    PoseSample sample;
    sample.time = i * kStep;
    walker.step(i == 0 ? 0.0 : kStep, sample.angles, pose);
    sample.root = pose.root;
    truth.push_back(sample);
    bones.push_back(pose.bone_in_world);
  }
  // Each bone's acceleration at each 100 Hz sample, from second differences.
  std::vector<std::array<double, kBoneCount>> acceleration(bones.size());
  for (std::size_t i = 1; i + 1 < bones.size(); ++i) {
    for (std::size_t b = 0; b < kBoneCount; ++b) {
      const Eigen::Vector3d second =
          bones[i + 1][b].translation - 2.0 * bones[i][b].translation + bones[i - 1][b].translation;
      acceleration[i][b] = second.norm() / (kStep * kStep);
    }
  }
  const double h = kEvery * kStep;
  PoseTrack track;
  double worst_share = 0.0;  // of the bound
  std::size_t judged = 0;
  for (std::size_t i = 100; i + 1 < truth.size(); ++i) {
    if (i % kEvery == 0) {
      ASSERT_TRUE(track.add(truth[i]));
    }
    if (i < 100 + 2 * kEvery || i % kEvery == 0) continue;
    // Drawn a sample interval behind: between the two newest samples, as the display draws.
    const std::size_t drawn = i - kEvery;
    const std::size_t before = drawn - drawn % kEvery, after = before + kEvery;
    RigidTransform root;
    JointAngles angles{};
    track.at(truth[drawn].time, root, angles);
    kinematics.compute(root, angles, pose);
    for (std::size_t b = 0; b < kBoneCount; ++b) {
      double local = 0.0;  // the bone's largest acceleration between the two samples
      for (std::size_t k = before; k <= after; ++k) local = std::max(local, acceleration[k][b]);
      const double bound = 2.0 * h * h / 8.0 * local + kFloorMetres;
      const double error = (pose.bone_in_world[b].translation - bones[drawn][b].translation).norm();
      EXPECT_LE(error, bound) << "bone " << b << " at " << truth[drawn].time << " s";
      worst_share = std::max(worst_share, error / bound);
      ++judged;
    }
  }
  EXPECT_GT(judged, 3000u);
  std::printf("worst error %.2f of its bound\n", worst_share);
}

}  // namespace
}  // namespace dressed_human
