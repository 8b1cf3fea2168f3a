// Fitting whole motions: the CMU walk and the OpenSim gait cycle. At a fixed order every series
// matches an independent least-squares solution; the fitted walk walks (knees, feet, arms); the
// joint-position error is measured; bad input is refused clearly.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <Eigen/Cholesky>

#include "dressed_human/core/motion/bvh_file.h"
#include "dressed_human/core/motion/fit_accuracy.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/motion/mocap_retarget.h"
#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_fit.h"
#include "dressed_human/core/motion/opensim_motion_file.h"

namespace dressed_human {
namespace {

const std::string kSource = DRESSED_HUMAN_SOURCE_DIR;
constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;
constexpr std::size_t kRootX = kDofCount;

const Skeleton& skeleton() {
  static const Skeleton s = Skeleton::fromUrdfFile(kSource + "/urdf/human.urdf");
  return s;
}

const SampledMotion& cmuWalk() {
  static const SampledMotion motion = [] {
    const std::string path = kSource + "/data/motion/cmu_02_01_walk.bvh";
    const BvhClip clip = loadBvhFile(path);
    return retargetBvh(clip, chooseBvhJointMap(clip, path), skeleton(), path);
  }();
  return motion;
}

// Normal equations with a Cholesky factorisation: independent of the fitter's Householder QR.
double normalEquationsRms(const std::vector<double>& times, const std::vector<double>& values, double period,
                          std::size_t order, bool linear) {
  const std::size_t columns = (linear ? 1 : 0) + 1 + 2 * order;
  Eigen::MatrixXd design(static_cast<Eigen::Index>(times.size()), static_cast<Eigen::Index>(columns));
  Eigen::VectorXd rhs(static_cast<Eigen::Index>(times.size()));
  for (std::size_t i = 0; i < times.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    Eigen::Index c = 0;
    if (linear) design(row, c++) = times[i];
    design(row, c++) = 1.0;
    for (std::size_t n = 1; n <= order; ++n) {
      design(row, c++) = std::cos(2 * kPi * static_cast<double>(n) * times[i] / period);
      design(row, c++) = std::sin(2 * kPi * static_cast<double>(n) * times[i] / period);
    }
    rhs[row] = values[i];
  }
  const Eigen::VectorXd x = (design.transpose() * design).ldlt().solve(design.transpose() * rhs);
  return std::sqrt((design * x - rhs).squaredNorm() / static_cast<double>(times.size()));
}

TEST(MotionFit, CmuOrderSixMatchesIndependentLeastSquares) {
  MotionFitOptions options;
  options.period = 1.1;  // fixed, not estimated
  options.fixed_order = 6;
  const MotionFit fit = fitMotion(cmuWalk(), options);
  EXPECT_EQ(fit.skipped_frames, 1u);  // the capture's leading bind-pose frame
  EXPECT_EQ(fit.cycles, 2u);
  EXPECT_EQ(fit.frames_used, 264u);
  std::size_t checked = 0;
  for (std::size_t i = 0; i < Motion::kSeriesCount; ++i) {
    const SeriesFitReport& report = fit.reports[i];
    if (!report.driven) continue;
    EXPECT_EQ(report.order, 6u) << fit.motion.seriesName(i);
    const double independent = normalEquationsRms(fit.times, fit.samples[i], 1.1, 6, i == kRootX);
    EXPECT_NEAR(report.rms_residual, independent, 1e-9) << fit.motion.seriesName(i);
    ++checked;
  }
  EXPECT_GE(checked, 40u);
}

TEST(MotionFit, CmuPeriodIsEstimatedByAutocorrelation) {
  const MotionFit fit = fitMotion(cmuWalk(), MotionFitOptions());
  ASSERT_TRUE(fit.period_estimated);
  EXPECT_GT(fit.motion.period, 1.0);  // README: cycles of about 1.1 s
  EXPECT_LT(fit.motion.period, 1.2);
  EXPECT_GT(fit.period_estimate.correlation, 0.8);
  EXPECT_EQ(fit.cycles, 2u);
  EXPECT_GT(fit.motion.root.forward_speed, 0.8);
  EXPECT_LT(fit.motion.root.forward_speed, 1.8);
  for (const SeriesFitReport& report : fit.reports) EXPECT_LE(report.order, 8u);
}

// The fitted walk, sampled through our FK: knees flex forward (+y), the feet alternate, the arms
// swing against the legs, the pelvis stays at walking height.
TEST(MotionFit, CmuFitWalksLikeAWalk) {
  const MotionFit fit = fitMotion(cmuWalk(), MotionFitOptions());
  MotionEvaluator evaluator(fit.motion);
  const ForwardKinematics kinematics(skeleton());
  const std::size_t l_ankle = static_cast<std::size_t>(skeleton().findBone("l_ankle"));
  const std::size_t r_ankle = static_cast<std::size_t>(skeleton().findBone("r_ankle"));
  const std::size_t l_wrist = static_cast<std::size_t>(skeleton().findBone("l_wrist"));
  std::vector<double> feet;   // left minus right ankle, forward, pelvis frame
  std::vector<double> hands;  // left minus right wrist
  double max_knee = -10, min_knee = 10, min_height = 10, max_height = 0;
  for (int k = 0; k < 100; ++k) {
    JointAngles angles{};
    RigidTransform root;
    evaluator.evaluate(fit.motion.period * k / 100.0, angles, root);
    for (const std::size_t knee : {11u, 14u}) {
      max_knee = std::max(max_knee, angles[knee * kDofsPerJoint]);
      min_knee = std::min(min_knee, angles[knee * kDofsPerJoint]);
    }
    min_height = std::min(min_height, root.translation.z());
    max_height = std::max(max_height, root.translation.z());
    SkeletonPose pose;
    kinematics.compute(RigidTransform(), angles, pose);
    feet.push_back(pose.bone_in_world[l_ankle].translation.x() - pose.bone_in_world[r_ankle].translation.x());
    hands.push_back(pose.bone_in_world[l_wrist].translation.x() -
                    pose.bone_in_world[static_cast<std::size_t>(skeleton().findBone("r_wrist"))].translation.x());
  }
  EXPECT_GT(max_knee, 0.8);
  EXPECT_LT(max_knee, 1.4);
  EXPECT_GT(min_knee, -0.1);
  EXPECT_GT(min_height, 0.75);
  EXPECT_LT(max_height, 1.05);
  // Each foot leads for part of the cycle, by a stride-sized margin.
  EXPECT_GT(*std::max_element(feet.begin(), feet.end()), 0.3);
  EXPECT_LT(*std::min_element(feet.begin(), feet.end()), -0.3);
  // Arms swing opposite to the legs: the left hand is ahead when the right foot is.
  double correlation = 0.0;
  for (std::size_t k = 0; k < feet.size(); ++k) correlation += feet[k] * hands[k];
  EXPECT_LT(correlation, 0.0);
}

TEST(MotionFit, JointPositionErrorAgainstTheCapture) {
  MotionFitOptions options;
  options.fixed_order = 6;
  const MotionFit fit = fitMotion(cmuWalk(), options);
  const FitAccuracy accuracy = measureFitAccuracy(skeleton(), cmuWalk(), fit, fit.motion);
  std::cout << "[ figure   ] m=6 joint-position error vs the capture's FK (stature-scaled): mean "
            << accuracy.against_capture.mean_cm << " cm, max " << accuracy.against_capture.max_cm
            << " cm; floor of the unsmoothed retarget " << accuracy.unsmoothed_against_capture.mean_cm
            << " cm; vs the unsmoothed retarget " << accuracy.against_samples.mean_cm << " cm (max "
            << accuracy.against_samples.max_cm << "); root " << accuracy.root_translation.mean_cm << " cm\n";
  std::cout << "[ figure   ] the capture's cycle-to-cycle variation: mean " << accuracy.capture_cycle_variation.mean_cm
            << " cm, max " << accuracy.capture_cycle_variation.max_cm << " cm over " << fit.cycles << " cycles\n";
  ASSERT_GT(accuracy.against_capture.samples, 0u);
  ASSERT_GT(accuracy.capture_cycle_variation.samples, 0u);
  // The truncated series adds little to what the different bone proportions already cost.
  EXPECT_LT(accuracy.against_samples.mean_cm, 2.0);
  EXPECT_LT(accuracy.against_capture.mean_cm - accuracy.unsmoothed_against_capture.mean_cm, 1.0);
  EXPECT_LT(accuracy.against_capture.mean_cm, 25.0);
  EXPECT_LT(accuracy.root_translation.mean_cm, 3.0);
}

// A capture whose cycles differ by a known offset: that offset is its cycle-to-cycle variation;
// an exactly periodic joint has none, at a period that is a whole number of frames or not.
TEST(MotionFit, CycleToCycleVariationIsTheDistanceToTheMeanCycle) {
  for (const double period : {1.0, 0.995}) {
    const double step = 0.01;
    std::vector<double> times;
    std::vector<JointPositions> positions;
    for (int f = 0; f < 320; ++f) {  // 3 cycles and a little more
      const double t = f * step;
      JointPositions p;
      for (Eigen::Vector3d& joint : p) joint.setZero();
      const double a = 2.0 * M_PI * t / period;
      p[0] = Eigen::Vector3d(0.1 * std::sin(a), 0.1 * std::cos(a), 0.0);
      const int cycle = static_cast<int>(std::floor(t / period));
      const double offset = cycle == 0 ? 0.03 : cycle == 1 ? -0.03 : 0.0;  // mean 0 over 3 cycles
      p[1] = p[0] + Eigen::Vector3d(offset, 0.0, 0.0);
      times.push_back(t);
      positions.push_back(p);
    }
    std::array<bool, kJointCount> used{};
    used[0] = used[1] = true;
    const PositionError v = periodicCycleVariation(times, positions, period, 3, used);
    // Joint 1 is 3 cm off in two cycles of three, joint 0 follows its mean cycle. The tolerance:
    // at 0.995 s a lookup between two frames that straddle a cycle's end mixes two offsets.
    EXPECT_NEAR(v.max_cm, 3.0, 0.05) << period;
    EXPECT_NEAR(v.mean_cm, 1.0, 0.05) << period;
    EXPECT_EQ(v.worst_joint, 1);
    used[1] = false;
    EXPECT_LT(periodicCycleVariation(times, positions, period, 3, used).max_cm, 0.02) << period;
    EXPECT_EQ(periodicCycleVariation(times, positions, period, 1, used).samples, 0u);  // one cycle: none
  }
}

TEST(MotionFit, OpenSimSingleCycleFitsWithPeriodOne) {
  const std::string path = kSource + "/data/motion/tutorial_normal_gait_cycle.mot";
  const SampledMotion sampled =
      retargetCoordinates(loadOpenSimMotionFile(path), builtinOpenSimGaitMap(), skeleton(), path);
  MotionFitOptions options;
  options.period = 1.0;
  const MotionFit fit = fitMotion(sampled, options);
  EXPECT_EQ(fit.motion.period, 1.0);
  EXPECT_EQ(fit.cycles, 1u);
  EXPECT_EQ(fit.frames_used, 50u);  // t = 0 .. 0.98; t = 1 is the next cycle's first sample
  EXPECT_EQ(fit.skipped_frames, 0u);
  for (std::size_t i = 0; i < Motion::kSeriesCount; ++i) {
    const SeriesFitReport& r = fit.reports[i];
    if (r.driven && r.is_angle) {
      EXPECT_LT(r.rms_residual, 2.0 * kDegree) << fit.motion.seriesName(i);
    }
  }
  // knee_angle < 0 is flexion in OpenSim; +y in our frames. Peak swing flexion ~60 degrees.
  double max_knee = -10.0;
  for (const double knee : fit.samples[11 * kDofsPerJoint]) max_knee = std::max(max_knee, knee);
  EXPECT_GT(max_knee, 50.0 * kDegree);
  EXPECT_LT(max_knee, 70.0 * kDegree);
  EXPECT_FALSE(fit.reports[4 * kDofsPerJoint].driven);  // the model has no arms
  // A single cycle cannot give its own period.
  EXPECT_THROW(fitMotion(sampled, MotionFitOptions()), MotionError);
}

SampledMotion syntheticWalk(std::size_t frames, double step, double period) {
  SampledMotion motion;
  motion.source = "synthetic";
  motion.driven.fill(true);
  for (std::size_t f = 0; f < frames; ++f) {
    const double t = static_cast<double>(f) * step;
    const double phase = 2 * kPi * t / period;
    JointAngles angles{};
    angles[11 * kDofsPerJoint] = 0.5 + 0.4 * std::sin(phase);
    angles[14 * kDofsPerJoint] = 0.5 + 0.4 * std::sin(phase + kPi);
    // Crosses +-180 degrees twice per cycle.
    angles[2 * kDofsPerJoint + 2] = std::remainder(kPi - 0.05 + 0.3 * std::sin(phase), 2 * kPi);
    RigidTransform root;
    root.translation = Eigen::Vector3d(1.2 * t, 0.02 * std::sin(phase), 0.95 + 0.02 * std::cos(2 * phase));
    motion.times.push_back(t);
    motion.angles.push_back(angles);
    motion.root.push_back(root);
  }
  return motion;
}

TEST(MotionFit, WrappingChannelFitsLikeItsTwin) {
  MotionFitOptions options;
  options.fixed_order = 3;
  const MotionFit estimated = fitMotion(syntheticWalk(300, 0.01, 1.0), options);
  EXPECT_NEAR(estimated.motion.period, 1.0, 0.01);
  options.period = 1.0;
  const MotionFit fit = fitMotion(syntheticWalk(300, 0.01, 1.0), options);
  // Its unwrapped twin: the same channel without the +-180 wrap, fitted the same way.
  SampledMotion twin = syntheticWalk(300, 0.01, 1.0);
  for (std::size_t f = 0; f < twin.times.size(); ++f) {
    twin.angles[f][2 * kDofsPerJoint + 2] = kPi - 0.05 + 0.3 * std::sin(2 * kPi * twin.times[f]);
  }
  const MotionFit twin_fit = fitMotion(twin, options);
  EXPECT_NEAR(fit.reports[2 * kDofsPerJoint + 2].rms_residual, twin_fit.reports[2 * kDofsPerJoint + 2].rms_residual,
              1e-12);
  EXPECT_LT(fit.reports[2 * kDofsPerJoint + 2].rms_residual, 1e-9);
  EXPECT_NEAR(fit.motion.root.forward_speed, 1.2, 1e-6);
  EXPECT_NEAR(std::abs(fit.motion.dofs[2 * kDofsPerJoint + 2].a0 / 2), kPi - 0.05, 1e-6);
}

TEST(MotionFit, RefusesBadInput) {
  const auto messageOf = [](const SampledMotion& motion, const MotionFitOptions& options) -> std::string {
    try {
      fitMotion(motion, options);
    } catch (const MotionError& error) {
      return error.what();
    }
    return "(no error)";
  };
  SampledMotion bad = syntheticWalk(300, 0.01, 1.0);
  bad.angles[100][33] = std::nan("");
  EXPECT_NE(messageOf(bad, {}).find("frame 101 holds a non-finite number"), std::string::npos);
  // Too few frames: a cycle of 5 samples.
  MotionFitOptions given;
  given.period = 0.05;
  EXPECT_NE(messageOf(syntheticWalk(300, 0.01, 0.05), given).find("too few frames"), std::string::npos);
  // Shorter than the period.
  given.period = 5.0;
  EXPECT_NE(messageOf(syntheticWalk(300, 0.01, 1.0), given).find("shorter than one period"), std::string::npos);
  // Non-periodic: a steady turn of the knees with noise.
  SampledMotion drift = syntheticWalk(300, 0.01, 1.0);
  std::uint32_t state = 1;
  double knee = 0.0;
  for (JointAngles& angles : drift.angles) {
    state = state * 1664525u + 1013904223u;
    knee += (static_cast<double>(state >> 8) / 16777216.0 - 0.5) * 0.05;
    for (double& a : angles) a = knee;
  }
  for (RigidTransform& root : drift.root) root.translation.z() = 0.9;
  EXPECT_NE(messageOf(drift, {}).find("no clear period"), std::string::npos) << messageOf(drift, {});
  MotionFitOptions too_high;
  too_high.period = 1.0;
  too_high.fixed_order = 60;
  EXPECT_NE(messageOf(syntheticWalk(300, 0.01, 1.0), too_high).find("at most order"), std::string::npos);
}

}  // namespace
}  // namespace dressed_human
