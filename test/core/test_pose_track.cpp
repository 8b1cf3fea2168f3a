#include "dressed_human/core/skeleton/pose_track.h"

#include <gtest/gtest.h>

#include <cmath>

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
