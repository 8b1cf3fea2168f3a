// Least-squares Fourier fits: known coefficients come back exactly, the order search stops at the
// smallest sufficient m, angles wrapping at +-180 degrees fit like their unwrapped twin, and the
// gait period is found (or refused) from the data.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "dressed_human/core/motion/fourier_fit.h"
#include "dressed_human/core/motion/gait_period.h"

namespace dressed_human {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

std::vector<double> uniformTimes(std::size_t count, double step) {
  std::vector<double> times(count);
  for (std::size_t i = 0; i < count; ++i) times[i] = static_cast<double>(i) * step;
  return times;
}

std::vector<double> sample(const FourierSeries& series, const std::vector<double>& times, double rate = 0.0) {
  std::vector<double> values;
  for (const double t : times) values.push_back(series.valueBySummation(t) + rate * t);
  return values;
}

FourierSeries knownSeries(double period) {
  FourierSeries s;
  s.period = period;
  s.a0 = 0.7;
  s.a = {0.31, -0.12, 0.05, 0.0, -0.02};
  s.b = {-0.44, 0.08, 0.0, 0.015, 0.01};
  return s;
}

TEST(FourierFit, RecoversKnownCoefficients) {
  const double period = 1.13;
  const FourierSeries truth = knownSeries(period);
  // Not a whole number of cycles and not aligned with the period: least squares, not a DFT.
  const std::vector<double> times = uniformTimes(301, 0.0071);
  const FourierFit fit = fitFourierSeries(times, sample(truth, times), period, 5);
  EXPECT_NEAR(fit.series.a0, truth.a0, 1e-9);
  for (std::size_t n = 0; n < 5; ++n) {
    EXPECT_NEAR(fit.series.a[n], truth.a[n], 1e-9) << n;
    EXPECT_NEAR(fit.series.b[n], truth.b[n], 1e-9) << n;
  }
  EXPECT_LT(fit.rms_residual, 1e-9);
}

TEST(FourierFit, RecoversLinearProgression) {
  const double period = 1.1;
  const FourierSeries truth = knownSeries(period);
  const std::vector<double> times = uniformTimes(264, 1.0 / 120.0);
  const FourierFit fit = fitFourierSeries(times, sample(truth, times, 1.25), period, 5, true);
  EXPECT_NEAR(fit.linear_rate, 1.25, 1e-9);
  EXPECT_NEAR(fit.series.a0, truth.a0, 1e-9);
  EXPECT_NEAR(fit.series.b[0], truth.b[0], 1e-9);
}

TEST(FourierFit, SmallestOrderReachingTheTolerance) {
  const double period = 1.0;
  FourierSeries truth = knownSeries(period);  // |harmonics 4, 5| ~ 0.02: below 0.05 RMS from m = 3
  const std::vector<double> times = uniformTimes(200, 0.005);
  const std::vector<double> values = sample(truth, times);
  const FourierFit fit = fitFourierSeriesToTolerance(times, values, period, 0.05, 8);
  EXPECT_TRUE(fit.reached_tolerance);
  EXPECT_LE(fit.rms_residual, 0.05);
  ASSERT_GE(fit.series.order(), 1u);
  EXPECT_GT(fitFourierSeries(times, values, period, fit.series.order() - 1).rms_residual, 0.05);
  const FourierFit capped = fitFourierSeriesToTolerance(times, values, period, 1e-12, 2);
  EXPECT_FALSE(capped.reached_tolerance);
  EXPECT_EQ(capped.series.order(), 2u);
}

TEST(FourierFit, WrappedAngleFitsLikeItsUnwrappedTwin) {
  // A heading-like channel oscillating around 170 degrees: it crosses +-180 every cycle.
  const double period = 1.0;
  const std::vector<double> times = uniformTimes(240, 1.0 / 120.0);
  std::vector<double> twin;
  std::vector<double> wrapped;
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.5 * kDegree);
  for (const double t : times) {
    const double angle = 170.0 * kDegree + 25.0 * kDegree * std::sin(2 * kPi * t / period) +
                         5.0 * kDegree * std::cos(4 * kPi * t / period) + noise(random);
    twin.push_back(angle);
    wrapped.push_back(std::remainder(angle, 2 * kPi));
  }
  double largest_jump = 0.0;
  for (std::size_t i = 1; i < wrapped.size(); ++i)
    largest_jump = std::max(largest_jump, std::abs(wrapped[i] - wrapped[i - 1]));
  ASSERT_GT(largest_jump, kPi);  // the raw channel does wrap

  const std::vector<double> unwrapped = unwrapAngles(wrapped);
  const double turns = std::round((unwrapped[0] - twin[0]) / (2 * kPi));
  for (std::size_t i = 0; i < twin.size(); ++i) EXPECT_NEAR(unwrapped[i], twin[i] + 2 * kPi * turns, 1e-12);
  const FourierFit twin_fit = fitFourierSeries(times, twin, period, 4);
  const FourierFit wrapped_fit = fitFourierSeries(times, unwrapped, period, 4);
  EXPECT_NEAR(wrapped_fit.rms_residual, twin_fit.rms_residual, 1e-12);
  EXPECT_LT(wrapped_fit.rms_residual, 0.6 * kDegree);
  // Without unwrapping the same fit is ruined: that is what the unwrapping is for.
  EXPECT_GT(fitFourierSeries(times, wrapped, period, 4).rms_residual, 30 * kDegree);
}

TEST(FourierFit, RefusesUnderdeterminedAndBadInput) {
  const std::vector<double> times = uniformTimes(6, 0.1);
  const std::vector<double> values(6, 1.0);
  EXPECT_THROW(fitFourierSeries(times, values, 1.0, 3), MotionError);  // 7 unknowns, 6 samples
  EXPECT_THROW(fitFourierSeries(times, values, 0.0, 1), MotionError);
  std::vector<double> bad = values;
  bad[2] = std::nan("");
  EXPECT_THROW(fitFourierSeries(times, bad, 1.0, 1), MotionError);
}

// -------------------------------------------------------------------- period estimation

std::vector<std::vector<double>> gaitLikeChannels(double period, double step, std::size_t frames) {
  // Left and right legs half a cycle apart, a vertical bounce at twice the stride frequency.
  std::vector<std::vector<double>> channels(3, std::vector<double>(frames));
  for (std::size_t i = 0; i < frames; ++i) {
    const double phase = 2 * kPi * static_cast<double>(i) * step / period;
    channels[0][i] = 0.5 * std::sin(phase) + 0.1 * std::sin(2 * phase + 0.3);
    channels[1][i] = 0.5 * std::sin(phase + kPi) + 0.1 * std::sin(2 * phase + 0.3);
    channels[2][i] = 0.05 * std::cos(2 * phase) + 0.001 * static_cast<double>(i);  // with a drift
  }
  return channels;
}

TEST(GaitPeriod, FindsTheStrideNotTheStep) {
  const PeriodEstimate estimate = estimateGaitPeriod(gaitLikeChannels(1.1063, 1.0 / 120.0, 344), 1.0 / 120.0);
  EXPECT_NEAR(estimate.period, 1.1063, 0.003);
  EXPECT_GT(estimate.correlation, 0.95);
}

TEST(GaitPeriod, RefusesNonPeriodicInput) {
  std::mt19937 random(3);
  std::normal_distribution<double> step(0.0, 1.0);
  std::vector<std::vector<double>> walk(4, std::vector<double>(400));
  for (auto& channel : walk) {
    double value = 0.0;
    for (double& v : channel) v = value += step(random);
  }
  try {
    estimateGaitPeriod(walk, 0.01);
    FAIL() << "a random walk has no period";
  } catch (const MotionError& error) {
    EXPECT_NE(std::string(error.what()).find("no clear period"), std::string::npos) << error.what();
  }
}

TEST(GaitPeriod, RefusesTooFewFramesAndNoMotion) {
  try {
    estimateGaitPeriod(gaitLikeChannels(1.0, 0.02, 30), 0.02);  // 0.6 s: not two cycles
    FAIL();
  } catch (const MotionError& error) {
    EXPECT_NE(std::string(error.what()).find("too few frames"), std::string::npos) << error.what();
  }
  EXPECT_THROW(estimateGaitPeriod({std::vector<double>(300, 1.0)}, 0.01), MotionError);
}

}  // namespace
}  // namespace dressed_human
