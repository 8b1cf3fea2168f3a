// Eq. 1 evaluated by the recurrence against direct summation; period, phase and speed.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"

namespace dressed_human {
namespace {

Motion randomMotion(std::size_t max_order, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coefficient(-0.8, 0.8);
  std::uniform_int_distribution<std::size_t> order(0, max_order);
  Motion motion;
  motion.period = 1.1;
  for (std::size_t i = 0; i < Motion::kSeriesCount; ++i) {
    FourierSeries& s = const_cast<FourierSeries&>(motion.series(i));
    s.period = motion.period;
    s.a0 = coefficient(rng);
    const std::size_t m = order(rng);
    // Divided by m + 1: within MotionLimits' amplitude (a full turn) at every order.
    for (std::size_t n = 0; n < m; ++n) {
      s.a.push_back(coefficient(rng) / static_cast<double>(m + 1));
      s.b.push_back(coefficient(rng) / static_cast<double>(m + 1));
    }
  }
  return motion;
}

RigidTransform rootBySummation(const Motion& motion, double time) {
  RigidTransform root;
  const auto& r = motion.root;
  root.translation = {motion.root.forward_speed * time + r.translation[0].valueBySummation(time),
                      r.translation[1].valueBySummation(time), r.translation[2].valueBySummation(time)};
  root.rotation = Eigen::AngleAxisd(r.rotation[2].valueBySummation(time), Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(r.rotation[1].valueBySummation(time), Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(r.rotation[0].valueBySummation(time), Eigen::Vector3d::UnitX());
  return root;
}

TEST(MotionEvaluator, MatchesDirectSummationOfEquationOne) {
  Motion motion = randomMotion(12, 1);
  motion.root.forward_speed = 1.3;
  MotionEvaluator evaluator(motion);
  EXPECT_EQ(evaluator.clockCount(), 1u);  // one sincos per update
  JointAngles angles{}, velocities{};
  RigidTransform root;
  double worst_angle = 0.0, worst_velocity = 0.0, worst_root = 0.0;
  for (double time : {0.0, 0.013, 0.55, 1.0999, 3.7, 123.456, 9876.5}) {
    evaluator.evaluate(time, angles, root, &velocities);
    // Long runs: summing cos(n * 2*pi*time/T) directly loses digits in the phase (1e-10 rad at
    // 10^4 s); the evaluator reduces time to one cycle first. Compare with the summation at the
    // exactly reduced time (fmod is exact), which is what a periodic motion means.
    const double cycle_time = std::fmod(time, motion.period);
    for (std::size_t i = 0; i < kDofCount; ++i) {
      worst_angle = std::max(worst_angle, std::abs(angles[i] - motion.dofs[i].valueBySummation(cycle_time)));
      worst_velocity =
          std::max(worst_velocity, std::abs(velocities[i] - motion.dofs[i].derivativeBySummation(cycle_time)));
    }
    RigidTransform expected = rootBySummation(motion, cycle_time);
    expected.translation.x() += motion.root.forward_speed * (time - cycle_time);
    worst_root = std::max({worst_root, (root.translation - expected.translation).norm(),
                           root.rotation.angularDistance(expected.rotation)});
  }
  EXPECT_LE(worst_angle, 1e-12);
  EXPECT_LE(worst_velocity, 1e-10);  // derivatives carry n * 2*pi/T: larger magnitude, same relative error
  EXPECT_LE(worst_root, 1e-9);       // includes forward_speed * 9876 s = 12.8 km of walking
}

TEST(MotionEvaluator, VelocityIsTheTimeDerivative) {
  const Motion motion = randomMotion(8, 2);
  MotionEvaluator evaluator(motion);
  JointAngles before{}, after{}, velocities{}, ignored{};
  RigidTransform root;
  const double time = 0.4, h = 1e-6;
  evaluator.evaluate(time, ignored, root, &velocities);
  evaluator.evaluate(time - h, before, root);
  evaluator.evaluate(time + h, after, root);
  for (std::size_t i = 0; i < kDofCount; ++i) EXPECT_NEAR(velocities[i], (after[i] - before[i]) / (2 * h), 1e-6) << i;
}

TEST(MotionEvaluator, RepeatsEveryPeriodAndProgressesAtTheForwardSpeed) {
  Motion motion = randomMotion(6, 3);
  motion.root.forward_speed = 1.25;
  MotionEvaluator evaluator(motion);
  JointAngles a{}, b{};
  RigidTransform root_a, root_b;
  evaluator.evaluate(0.3, a, root_a);
  evaluator.evaluate(0.3 + 2 * motion.period, b, root_b);
  for (std::size_t i = 0; i < kDofCount; ++i) EXPECT_NEAR(a[i], b[i], 1e-12);
  EXPECT_NEAR(root_b.translation.x() - root_a.translation.x(), 1.25 * 2 * motion.period, 1e-12);
  EXPECT_NEAR(root_b.translation.z(), root_a.translation.z(), 1e-12);
}

TEST(MotionEvaluator, PhaseShiftsTheSeries) {
  Motion motion;
  motion.period = 2.0;
  for (std::size_t i = 0; i < Motion::kSeriesCount; ++i) const_cast<FourierSeries&>(motion.series(i)).period = 2.0;
  motion.dofs[0].a = {1.0};
  motion.dofs[0].b = {0.0};
  motion.dofs[1] = motion.dofs[0];
  motion.dofs[1].phase = 3.14159265358979323846 / 2;  // cos(t + pi/2) = -sin t
  MotionEvaluator evaluator(motion);
  EXPECT_EQ(evaluator.clockCount(), 2u);
  JointAngles angles{};
  RigidTransform root;
  evaluator.evaluate(0.25, angles, root);  // t = pi/4
  EXPECT_NEAR(angles[0], std::cos(3.14159265358979323846 / 4), 1e-15);
  EXPECT_NEAR(angles[1], -std::sin(3.14159265358979323846 / 4), 1e-15);
}

TEST(MotionEvaluator, OwnPeriodPerDof) {
  Motion motion;
  motion.period = 1.0;
  for (std::size_t i = 0; i < Motion::kSeriesCount; ++i) const_cast<FourierSeries&>(motion.series(i)).period = 1.0;
  motion.dofs[3].period = 0.5;
  motion.dofs[3].b = {1.0};
  motion.dofs[3].a = {0.0};
  MotionEvaluator evaluator(motion);
  JointAngles angles{};
  RigidTransform root;
  evaluator.evaluate(0.125, angles, root);  // a quarter of the DOF's own period
  EXPECT_NEAR(angles[3], 1.0, 1e-15);
}

TEST(MotionEvaluator, RejectsAnInvalidMotion) {
  Motion motion;
  motion.period = 0.0;
  EXPECT_THROW(MotionEvaluator{motion}, MotionError);
  motion.period = 1.0;
  motion.dofs[7].a0 = std::nan("");
  EXPECT_THROW(MotionEvaluator{motion}, MotionError);
}

TEST(MotionEvaluator, ShippedWalkIsAWalk) {
  const Motion walk = loadMotionFile(std::string(DRESSED_HUMAN_SOURCE_DIR) + "/config/motions/walk.yaml");
  MotionEvaluator evaluator(walk);
  JointAngles angles{};
  RigidTransform root;
  double max_knee = -10, min_knee = 10, min_height = 10, max_height = 0;
  for (int k = 0; k < 100; ++k) {
    evaluator.evaluate(walk.period * k / 100.0, angles, root);
    const double knee = angles[11 * kDofsPerJoint];  // l_knee, y: + is flexion
    max_knee = std::max(max_knee, knee);
    min_knee = std::min(min_knee, knee);
    min_height = std::min(min_height, root.translation.z());
    max_height = std::max(max_height, root.translation.z());
  }
  EXPECT_GT(max_knee, 0.6);  // swing-phase flexion of roughly 35..70 degrees
  EXPECT_LT(max_knee, 1.3);
  EXPECT_GT(min_knee, -0.2);  // the knee does not bend backwards
  EXPECT_GT(min_height, 0.7);
  EXPECT_LT(max_height, 1.1);
}

}  // namespace
}  // namespace dressed_human
