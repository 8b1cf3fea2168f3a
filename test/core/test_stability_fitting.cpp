// Stability of the motion fitting where its methods fail (issue #8, docs/stability.md): Euler
// splits at and near gimbal lock and at the +-180 degree wrap, and period detection and Fourier
// fits fed non-periodic or constant input.
#include <gtest/gtest.h>

#include "dressed_human/core/motion/bvh_file.h"
#include "dressed_human/core/motion/fourier_fit.h"
#include "dressed_human/core/motion/gait_period.h"
#include "dressed_human/core/motion/mocap_joint_map.h"
#include "dressed_human/core/motion/mocap_retarget.h"
#include "dressed_human/core/motion/motion.h"
#include "dressed_human/core/motion/motion_fit.h"

#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace dressed_human {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

Eigen::Matrix3d yxz(double y, double x, double z) {
  return (Eigen::AngleAxisd(y, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(x, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(z, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

Eigen::Matrix3d rollPitchYaw(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// The x angles a gimbal test visits: exactly +-90 degrees and 10^-k short of it.
std::vector<double> nearGimbalAngles() {
  std::vector<double> out = {kPi / 2, -kPi / 2};
  for (int k = 1; k <= 16; ++k) {
    out.push_back(kPi / 2 - std::pow(10.0, -k));
    out.push_back(-kPi / 2 + std::pow(10.0, -k));
  }
  return out;
}

// Retargeting splits every local rotation into our Ry Rx Rz. Near x = +-90 degrees y and z are
// individually ill-conditioned, but their composition must give back the rotation: that is what
// FK sees. The angles must stay finite and in their documented ranges.
TEST(StabilityFitting, YxzSplitReproducesTheRotationAtAndNearGimbalLock) {
  const std::vector<double> others = {-kPi, -2.5, -0.7, 0.0, 0.3, 1.9, kPi};
  double worst = 0.0;
  for (double x : nearGimbalAngles()) {
    for (double y : others) {
      for (double z : others) {
        const Eigen::Matrix3d r = yxz(y, x, z);
        const Eigen::Vector3d split = decomposeYxz(r);
        ASSERT_TRUE(split.allFinite()) << y << " " << x << " " << z;
        EXPECT_LE(std::abs(split[1]), kPi / 2);
        EXPECT_LE(std::abs(split[0]), kPi);
        EXPECT_LE(std::abs(split[2]), kPi);
        worst = std::max(worst, (yxz(split[0], split[1], split[2]) - r).norm());
      }
    }
  }
  EXPECT_LT(worst, 1e-7) << "worst reconstruction error near gimbal lock";
  // Roll-pitch-yaw of the root: the same at pitch +-90 degrees.
  worst = 0.0;
  for (double pitch : nearGimbalAngles()) {
    for (double roll : others) {
      for (double yaw : others) {
        const Eigen::Matrix3d r = rollPitchYaw(roll, pitch, yaw);
        const Eigen::Vector3d split = decomposeRollPitchYaw(r);
        ASSERT_TRUE(split.allFinite());
        EXPECT_LE(std::abs(split[1]), kPi / 2);
        worst = std::max(worst, (rollPitchYaw(split[0], split[1], split[2]) - r).norm());
      }
    }
  }
  EXPECT_LT(worst, 1e-7) << "worst reconstruction error near pitch +-90";
}

// A rotation that passes through gimbal lock: the split angles may jump (y and z swap their share
// of the rotation), the rotation they compose to does not.
TEST(StabilityFitting, YxzSplitComposesContinuouslyThroughGimbalLock) {
  const int steps = 2000;
  Eigen::Matrix3d previous = Eigen::Matrix3d::Identity();
  double largest_angle_jump = 0.0;
  Eigen::Vector3d last_split = Eigen::Vector3d::Zero();
  for (int k = 0; k <= steps; ++k) {
    const double s = static_cast<double>(k) / steps;
    const Eigen::Matrix3d r = yxz(0.5 + 0.2 * s, kPi / 2 - 0.3 + 0.6 * s, 0.4 - 0.5 * s);  // x crosses 90
    const Eigen::Vector3d split = decomposeYxz(r);
    const Eigen::Matrix3d back = yxz(split[0], split[1], split[2]);
    EXPECT_LT((back - r).norm(), 1e-7) << k;
    if (k > 0) {
      // The composed rotation moves as little as the input does (at most ~1 mrad per step here).
      EXPECT_LT((back - previous).norm(), 2e-3) << k;
      largest_angle_jump = std::max(largest_angle_jump, (split - last_split).cwiseAbs().maxCoeff());
    }
    last_split = split;
    previous = back;
  }
  // Documented limitation, not a bug: the split itself jumps by about pi where x passes 90
  // degrees (x turns back, y and z flip by pi). A Fourier fit cannot follow that channel.
  EXPECT_GT(largest_angle_jump, 2.0);
}

// The real captures stay far from gimbal lock, which is why the limitation above does not reach
// the fitted walks. A new capture that comes close should fail here and be looked at.
TEST(StabilityFitting, CmuWalkStaysAwayFromGimbalLock) {
  const std::string source = DRESSED_HUMAN_SOURCE_DIR;
  const Skeleton skeleton = Skeleton::fromUrdfFile(source + "/urdf/human.urdf");
  const std::string path = source + "/data/motion/cmu_02_01_walk.bvh";
  const BvhClip clip = loadBvhFile(path);
  const SampledMotion motion = retargetBvh(clip, chooseBvhJointMap(clip, path), skeleton, path);
  double largest_x = 0.0;
  for (std::size_t f = 1; f < motion.angles.size(); ++f) {  // frame 0 is CMU's bind pose
    for (std::size_t j = 0; j < kJointCount; ++j) {
      if (motion.driven[j]) largest_x = std::max(largest_x, std::abs(motion.angles[f][j * kDofsPerJoint + 1]));
    }
  }
  RecordProperty("largest_abduction_degrees", std::to_string(largest_x / kDegree));
  EXPECT_LT(largest_x, 70.0 * kDegree);
}

// A walk heading along -x: the root yaw sits at +-180 degrees and wraps every sway cycle. The
// walk frame absorbs the heading, so the fit sees a small periodic yaw, not the wrap.
TEST(StabilityFitting, RootHeadingAtPlusMinus180Fits) {
  SampledMotion motion;
  motion.source = "heading 180";
  motion.driven.fill(true);
  for (int f = 0; f < 300; ++f) {
    const double t = 0.01 * f;
    const double phase = 2 * kPi * t;
    JointAngles angles{};
    angles[11 * kDofsPerJoint] = 0.5 + 0.4 * std::sin(phase);
    angles[14 * kDofsPerJoint] = 0.5 + 0.4 * std::sin(phase + kPi);
    RigidTransform root;
    root.translation = Eigen::Vector3d(-1.2 * t, -0.02 * std::sin(phase), 0.95 + 0.02 * std::cos(2 * phase));
    root.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(kPi + 0.08 * std::sin(phase), Eigen::Vector3d::UnitZ()));
    motion.times.push_back(t);
    motion.angles.push_back(angles);
    motion.root.push_back(root);
  }
  MotionFitOptions options;
  options.fixed_order = 3;
  const MotionFit fit = fitMotion(motion, options);
  EXPECT_NEAR(fit.motion.period, 1.0, 0.01);
  EXPECT_NEAR(fit.motion.root.forward_speed, 1.2, 1e-3);
  for (std::size_t s = kDofCount; s < Motion::kSeriesCount; ++s) {
    EXPECT_TRUE(std::isfinite(fit.reports[s].rms_residual)) << s;
  }
  // Yaw relative to the walk frame: amplitude 0.08 rad, fitted to well below a degree.
  EXPECT_LT(fit.reports[Motion::kSeriesCount - 1].rms_residual, 0.5 * kDegree);
}

std::string periodError(const std::vector<std::vector<double>>& channels, double frame_time) {
  try {
    const PeriodEstimate estimate = estimateGaitPeriod(channels, frame_time);
    return "(found a period of " + std::to_string(estimate.period) + " s, r = " + std::to_string(estimate.correlation) +
           ")";
  } catch (const MotionError& error) {
    return error.what();
  }
}

bool saysNoPeriod(const std::string& message) {
  return message.find("no clear period") != std::string::npos || message.find("no motion") != std::string::npos;
}

// Period detection on inputs that do not repeat must refuse, whatever their scale, instead of
// reading a period out of rounding noise or drift.
TEST(StabilityFitting, PeriodDetectionRefusesNonPeriodicInput) {
  const std::size_t frames = 600;
  const double frame_time = 0.01;
  // Ramps of any size: the straight line is removed, nothing must remain.
  for (double scale : {1.0, 1e3, 1e6, 1e9}) {
    std::vector<double> ramp(frames);
    for (std::size_t i = 0; i < frames; ++i) ramp[i] = scale * (0.37 + 1.3 * static_cast<double>(i) / frames);
    const std::string message = periodError({ramp}, frame_time);
    EXPECT_TRUE(saysNoPeriod(message)) << "ramp x" << scale << ": " << message;
  }
  // Constant channels, also large ones.
  for (double value : {0.0, 1.0, 12345.678}) {
    const std::string message = periodError({std::vector<double>(frames, value)}, frame_time);
    EXPECT_NE(message.find("no motion"), std::string::npos) << message;
  }
  // A step, a parabola, an exponential and a chirp (frequency tripling over the record).
  std::vector<double> step(frames), parabola(frames), exponential(frames), chirp(frames);
  for (std::size_t i = 0; i < frames; ++i) {
    const double t = static_cast<double>(i) / frames;
    step[i] = t < 0.43 ? 0.0 : 1.0;
    parabola[i] = (t - 0.3) * (t - 0.3);
    exponential[i] = std::exp(4.0 * t);
    chirp[i] = std::sin(2 * kPi * (1.0 * t + 1.5 * t * t) * 3.0);
  }
  for (const auto& [name, channel] : std::vector<std::pair<std::string, std::vector<double>>>{
           {"step", step}, {"parabola", parabola}, {"exponential", exponential}, {"chirp", chirp}}) {
    const std::string message = periodError({channel}, frame_time);
    EXPECT_TRUE(saysNoPeriod(message)) << name << ": " << message;
  }
  // Random walks, many seeds: a false period would be a fitted walk that is not one.
  for (unsigned seed = 1; seed <= 30; ++seed) {
    std::mt19937 random(seed);
    std::normal_distribution<double> increment(0.0, 1.0);
    std::vector<std::vector<double>> walk(3, std::vector<double>(frames));
    for (auto& channel : walk) {
      double value = 0.0;
      for (double& v : channel) v = value += increment(random);
    }
    const std::string message = periodError(walk, frame_time);
    EXPECT_TRUE(saysNoPeriod(message)) << "random walk seed " << seed << ": " << message;
  }
}

// Long records hold the period several times: r(T), r(2T), r(3T) are all ~1 and which one is
// highest is down to noise. The estimate must be the fundamental, not a multiple.
TEST(StabilityFitting, PeriodDetectionPrefersTheFundamentalOverItsMultiples) {
  int multiples = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937 random(seed);
    std::normal_distribution<double> noise(0.0, 0.02);
    const double period = seed % 2 ? 1.1 : 0.9 + 0.013 * seed;
    const double frame_time = 0.01;
    const std::size_t frames = static_cast<std::size_t>((5.0 + 0.05 * seed) * period / frame_time);
    std::vector<std::vector<double>> channels(2, std::vector<double>(frames));
    for (std::size_t i = 0; i < frames; ++i) {
      const double phase = 2 * kPi * static_cast<double>(i) * frame_time / period;
      channels[0][i] = 0.5 * std::sin(phase) + 0.1 * std::sin(2 * phase + 0.3) + noise(random);
      channels[1][i] = 0.5 * std::sin(phase + kPi) + 0.1 * std::sin(2 * phase + 0.3) + noise(random);
    }
    const PeriodEstimate estimate = estimateGaitPeriod(channels, frame_time);
    EXPECT_NEAR(estimate.period, period, 0.01 * period) << "seed " << seed;
    if (std::abs(estimate.period - period) > 0.01 * period) ++multiples;
  }
  RecordProperty("multiples_picked", multiples);
}

// A capture's cycles differ: each cycle's swing a little larger or smaller, a little early or
// late, changing smoothly from cycle to cycle, and the take starts and ends with a cycle that
// swings up from and back down to a standstill. r(2T) or r(3T) then often beats r(T) by more than
// plain noise would (0.02): the period must still be one gait cycle. A motion that really repeats
// only every third cycle (a slower sway under the cycle) must keep the three cycles.
std::vector<std::vector<double>> capturedCycles(unsigned seed, double period, double frame_time, double cycles,
                                                double three_cycle_sway) {
  std::mt19937 random(seed);
  std::normal_distribution<double> per_cycle(0.0, 1.0);
  std::vector<double> amplitude, delay;
  for (int c = 0; c < static_cast<int>(cycles) + 3; ++c) {
    amplitude.push_back(1.0 + 0.12 * per_cycle(random));
    delay.push_back(0.06 * per_cycle(random));
  }
  // Cosine interpolation between the cycles' values: smooth, no step at a cycle's start.
  const auto smooth = [](const std::vector<double>& values, double cycle) {
    const auto c = static_cast<std::size_t>(cycle);
    const double w = 0.5 - 0.5 * std::cos(kPi * (cycle - static_cast<double>(c)));
    return (1.0 - w) * values[c] + w * values[c + 1];
  };
  std::normal_distribution<double> noise(0.0, 0.01);
  const auto frames = static_cast<std::size_t>(cycles * period / frame_time);
  std::vector<std::vector<double>> channels(3, std::vector<double>(frames));
  for (std::size_t i = 0; i < frames; ++i) {
    const double t = static_cast<double>(i) * frame_time;
    const double cycle = t / period;
    const double ramp = std::min({1.0, cycle, cycles - cycle});  // from and back to a standstill
    const double phase = 2 * kPi * (cycle + smooth(delay, cycle));
    const double swing = ramp * smooth(amplitude, cycle);
    const double sway = three_cycle_sway * std::sin(phase / 3.0);
    channels[0][i] = swing * (0.5 * std::sin(phase) + 0.1 * std::sin(2 * phase + 0.3)) + sway + noise(random);
    channels[1][i] = swing * (0.5 * std::sin(phase + kPi) + 0.1 * std::sin(2 * phase + 0.3)) + sway + noise(random);
    channels[2][i] = ramp * 0.05 * std::cos(2 * phase) + noise(random);
  }
  return channels;
}

// With 0.02 alone 14 of these 40 took a multiple; the standard error leaves one (seed 31: r 0.841
// at T against 0.899 at 3T). Two sigma is not a certainty: at most 2 of 40 may.
TEST(StabilityFitting, PeriodDetectionFindsOneCycleOfACaptureWhoseCyclesDiffer) {
  int multiples = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const double period = 1.0 + 0.01 * seed;
    const double cycles = 6.0 + 0.05 * seed;
    const PeriodEstimate estimate = estimateGaitPeriod(capturedCycles(seed, period, 1.0 / 30.0, cycles, 0.0), 1.0 / 30.0);
    if (std::abs(estimate.period - period) > 0.05 * period) {
      ++multiples;
      std::cout << "seed " << seed << ": " << estimate.period << " s for a cycle of " << period << " s\n";
    }
  }
  EXPECT_LE(multiples, 2);
  RecordProperty("multiples_picked", multiples);
}

TEST(StabilityFitting, PeriodDetectionKeepsAMotionThatRepeatsEveryThirdCycle) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const double period = 1.0 + 0.01 * seed;
    const double cycles = 9.0 + 0.05 * seed;
    const PeriodEstimate estimate = estimateGaitPeriod(capturedCycles(seed, period, 1.0 / 30.0, cycles, 0.35), 1.0 / 30.0);
    EXPECT_NEAR(estimate.period, 3.0 * period, 0.15 * period) << "seed " << seed;
  }
}

// When the caller gives the period, nothing checks that the data repeat: the documented fallback
// is a fit that reports its residual and that it missed the tolerance, never a silent success.
TEST(StabilityFitting, FourierFitOfNonPeriodicInputReportsItsFailure) {
  std::vector<double> times, ramp, walk;
  std::mt19937 random(11);
  std::normal_distribution<double> increment(0.0, 0.02);
  double value = 0.0;
  for (int i = 0; i < 400; ++i) {
    times.push_back(0.01 * i);
    ramp.push_back(0.5 * times.back());
    walk.push_back(value += increment(random));
  }
  // A ramp over exactly one "period": its sawtooth needs every harmonic.
  const FourierFit ramp_fit = fitFourierSeriesToTolerance(times, ramp, 4.0, 1e-3, 8);
  EXPECT_FALSE(ramp_fit.reached_tolerance);
  EXPECT_TRUE(std::isfinite(ramp_fit.rms_residual));
  EXPECT_GT(ramp_fit.rms_residual, 1e-3);
  // ...unless the linear term (the root's forward progression) takes it: then order 0 is exact.
  const FourierFit linear_fit = fitFourierSeriesToTolerance(times, ramp, 4.0, 1e-3, 8, true);
  EXPECT_TRUE(linear_fit.reached_tolerance);
  EXPECT_EQ(linear_fit.series.a.size(), 0u);
  EXPECT_NEAR(linear_fit.linear_rate, 0.5, 1e-12);
  const FourierFit walk_fit = fitFourierSeriesToTolerance(times, walk, 1.0, 1e-3, 8);
  EXPECT_FALSE(walk_fit.reached_tolerance);
  EXPECT_TRUE(std::isfinite(walk_fit.rms_residual));
  // A constant is fitted exactly by order 0.
  const FourierFit constant = fitFourierSeriesToTolerance(times, std::vector<double>(times.size(), 0.7), 1.0, 1e-9, 8);
  EXPECT_TRUE(constant.reached_tolerance);
  EXPECT_EQ(constant.series.a.size(), 0u);
  EXPECT_NEAR(constant.series.a0 / 2, 0.7, 1e-12);
}

// fitMotion on a constant (motionless) capture: "no motion", not a division by zero.
TEST(StabilityFitting, MotionFitOfAStillCaptureIsRefusedByName) {
  SampledMotion still;
  still.source = "still";
  still.driven.fill(true);
  for (int f = 0; f < 300; ++f) {
    still.times.push_back(0.01 * f);
    JointAngles angles{};
    angles[3] = 0.2;
    still.angles.push_back(angles);
    RigidTransform root;
    root.translation.z() = 0.95;
    still.root.push_back(root);
  }
  try {
    fitMotion(still, MotionFitOptions());
    FAIL() << "a still capture has no period";
  } catch (const MotionError& error) {
    EXPECT_NE(std::string(error.what()).find("no motion"), std::string::npos) << error.what();
  }
  // With a given period it fits exactly, every series at order 0.
  MotionFitOptions given;
  given.period = 1.0;
  const MotionFit fit = fitMotion(still, given);
  for (std::size_t s = 0; s < Motion::kSeriesCount; ++s) {
    EXPECT_TRUE(fit.reports[s].reached_tolerance) << s;
    EXPECT_LT(fit.reports[s].rms_residual, 1e-9) << s;
  }
}

}  // namespace
}  // namespace dressed_human
