#include "dressed_human/core/motion/motion_fit.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "dressed_human/core/motion/fourier_fit.h"

namespace dressed_human {
namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr std::size_t kMinSamplesPerCycle = 8;
constexpr std::size_t kRootX = kDofCount;  // series index of the root's forward translation
constexpr std::size_t kFirstRootRotation = kDofCount + 3;
constexpr double kWalkingSpeedThreshold = 0.05;  // m/s: slower counts as walking in place

std::string number(double value) {
  std::ostringstream text;
  text.precision(4);
  text << value;
  return text.str();
}

// Shifts an unwrapped angle channel by whole turns so that its mean lies in (-pi, pi].
void centreTurns(std::vector<double>& values) {
  if (values.empty()) return;
  double mean = 0.0;
  for (const double v : values) mean += v / static_cast<double>(values.size());
  const double shift = mean - std::remainder(mean, 2.0 * M_PI);
  for (double& v : values) v -= shift;
}

void validateSamples(const SampledMotion& sampled) {
  const std::size_t frames = sampled.times.size();
  if (frames < 2) throw MotionError(sampled.source + ": too few frames: " + std::to_string(frames));
  if (sampled.angles.size() != frames || sampled.root.size() != frames) {
    throw MotionError(sampled.source + ": times, angles and root poses differ in length");
  }
  for (std::size_t f = 0; f < frames; ++f) {
    bool finite = std::isfinite(sampled.times[f]) && sampled.root[f].translation.allFinite() &&
                  sampled.root[f].rotation.coeffs().allFinite();
    for (const double a : sampled.angles[f]) finite = finite && std::isfinite(a);
    if (!finite) throw MotionError(sampled.source + ": frame " + std::to_string(f + 1) + " holds a non-finite number");
    if (f > 0 && !(sampled.times[f] > sampled.times[f - 1])) {
      throw MotionError(sampled.source + ": frame " + std::to_string(f + 1) + ": the times do not increase");
    }
  }
}

void requireUniformSampling(const SampledMotion& sampled) {
  const double step = sampled.times[1] - sampled.times[0];
  for (std::size_t f = 1; f < sampled.times.size(); ++f) {
    const double this_step = sampled.times[f] - sampled.times[f - 1];
    if (std::abs(this_step - step) > 1e-3 * step) {
      throw MotionError(sampled.source + ": the frames are not evenly spaced in time (frame " + std::to_string(f + 1) +
                        "): the period can only be estimated from uniform samples; give it with --period");
    }
  }
}

void fitSeries(MotionFit& fit, std::size_t index, const MotionFitOptions& options) {
  SeriesFitReport& report = fit.reports[index];
  FourierSeries& series = index < kDofCount            ? fit.motion.dofs[index]
                          : index < kFirstRootRotation ? fit.motion.root.translation[index - kDofCount]
                                                       : fit.motion.root.rotation[index - kFirstRootRotation];
  const double period = fit.motion.period;
  if (!report.driven) {
    series = FourierSeries();
    series.period = period;
    report = SeriesFitReport{0, 0.0, report.is_angle, false, true};
    return;
  }
  const bool linear = index == kRootX;
  const double tolerance = report.is_angle ? options.tolerance_degrees * kDegree : options.tolerance_metres;
  const FourierFit result = options.fixed_order > 0
                                ? fitFourierSeries(fit.times, fit.samples[index], period, options.fixed_order, linear)
                                : fitFourierSeriesToTolerance(fit.times, fit.samples[index], period, tolerance,
                                                              fit.max_order_allowed, linear);
  series = result.series;
  if (linear) fit.motion.root.forward_speed = result.linear_rate;
  report.order = result.series.order();
  report.rms_residual = result.rms_residual;
  report.reached_tolerance = result.reached_tolerance;
}

// The largest change of any driven angle between two frames, radians.
double largestStep(const SampledMotion& sampled, std::size_t frame) {
  double step = 0.0;
  for (std::size_t i = 0; i < kDofCount; ++i) {
    if (!sampled.driven[i / kDofsPerJoint]) continue;
    step =
        std::max(step, std::abs(std::remainder(sampled.angles[frame + 1][i] - sampled.angles[frame][i], 2.0 * M_PI)));
  }
  return step;
}

SampledMotion withoutLeadingFrames(const SampledMotion& sampled, std::size_t count) {
  SampledMotion trimmed = sampled;
  const auto begin = [count](auto& v) { return v.begin() + static_cast<std::ptrdiff_t>(count); };
  trimmed.times.erase(trimmed.times.begin(), begin(trimmed.times));
  trimmed.angles.erase(trimmed.angles.begin(), begin(trimmed.angles));
  trimmed.root.erase(trimmed.root.begin(), begin(trimmed.root));
  if (trimmed.reference_joint_positions.size() >= count) {
    trimmed.reference_joint_positions.erase(trimmed.reference_joint_positions.begin(),
                                            begin(trimmed.reference_joint_positions));
  }
  return trimmed;
}

}  // namespace

std::size_t countLeadingOutlierFrames(const SampledMotion& sampled) {
  const std::size_t frames = sampled.times.size();
  if (frames < 20) return 0;
  std::vector<double> steps(frames - 1);
  for (std::size_t f = 0; f + 1 < frames; ++f) steps[f] = largestStep(sampled, f);
  std::vector<double> sorted = steps;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double threshold = std::max(15.0 * kDegree, 10.0 * sorted[sorted.size() / 2]);
  std::size_t skip = 0;
  for (std::size_t f = 0; f < std::min<std::size_t>(5, frames / 10); ++f) {
    if (steps[f] > threshold) skip = f + 1;
  }
  return skip;
}

MotionFit fitMotion(const SampledMotion& untrimmed, const MotionFitOptions& options) {
  validateSamples(untrimmed);
  const std::size_t skip =
      options.skip_frames >= 0 ? static_cast<std::size_t>(options.skip_frames) : countLeadingOutlierFrames(untrimmed);
  if (skip + 2 > untrimmed.times.size()) {
    throw MotionError(untrimmed.source + ": too few frames: skipping " + std::to_string(skip) + " of " +
                      std::to_string(untrimmed.times.size()) + " leaves nothing to fit");
  }
  const SampledMotion sampled = skip > 0 ? withoutLeadingFrames(untrimmed, skip) : untrimmed;
  const std::size_t frames = sampled.times.size();
  if (options.max_order == 0 && options.fixed_order == 0) throw MotionError("the maximum Fourier order must be >= 1");

  // Unwrapped over the whole record, so that a channel crossing +-180 degrees is continuous.
  std::array<std::vector<double>, kDofCount> unwrapped;
  for (std::size_t i = 0; i < kDofCount; ++i) {
    std::vector<double> values(frames);
    for (std::size_t f = 0; f < frames; ++f) values[f] = sampled.angles[f][i];
    unwrapped[i] = unwrapAngles(values);
  }

  MotionFit fit;
  fit.skipped_frames = skip;
  fit.motion.name = options.name;
  if (options.period > 0.0) {
    if (!std::isfinite(options.period)) throw MotionError("the period must be a finite number of seconds");
    fit.motion.period = options.period;
  } else {
    requireUniformSampling(sampled);
    std::vector<std::vector<double>> channels;
    for (std::size_t i = 0; i < kDofCount; ++i) {
      if (sampled.driven[i / kDofsPerJoint]) channels.push_back(unwrapped[i]);
    }
    std::vector<double> height(frames);
    for (std::size_t f = 0; f < frames; ++f) height[f] = sampled.root[f].translation.z();
    channels.push_back(height);
    try {
      fit.period_estimate = estimateGaitPeriod(channels, sampled.times[1] - sampled.times[0], options.period_options);
    } catch (const MotionError& error) {
      throw MotionError(sampled.source + ": " + error.what());
    }
    fit.period_estimated = true;
    fit.motion.period = fit.period_estimate.period;
  }
  const double period = fit.motion.period;

  // Whole cycles from the first frame; every sample stands for one frame time.
  const double step = (sampled.times.back() - sampled.times.front()) / static_cast<double>(frames - 1);
  const double covered = sampled.times.back() - sampled.times.front() + step;
  fit.cycles = static_cast<std::size_t>(std::floor(covered / period + 1e-9));
  if (fit.cycles == 0) {
    throw MotionError(sampled.source + ": the record (" + number(covered) + " s) is shorter than one period (" +
                      number(period) + " s)");
  }
  const double window_end = sampled.times.front() + static_cast<double>(fit.cycles) * period - 0.5 * step;
  while (fit.frames_used < frames && sampled.times[fit.frames_used] < window_end) ++fit.frames_used;
  const double samples_per_cycle = period / step;
  if (samples_per_cycle < static_cast<double>(kMinSamplesPerCycle)) {
    throw MotionError(sampled.source + ": too few frames: " + number(samples_per_cycle) + " per cycle, at least " +
                      std::to_string(kMinSamplesPerCycle) + " are needed");
  }
  const auto sampling_limit = static_cast<std::size_t>(std::floor((samples_per_cycle - 1.0) / 2.0));
  fit.max_order_allowed = std::min(options.max_order, sampling_limit);
  if (options.fixed_order > sampling_limit) {
    throw MotionError(sampled.source + ": order " + std::to_string(options.fixed_order) + " needs more than " +
                      number(samples_per_cycle) + " samples per cycle (at most order " +
                      std::to_string(sampling_limit) + ")");
  }

  const std::size_t n = fit.frames_used;
  fit.times.resize(n);
  for (std::size_t f = 0; f < n; ++f) fit.times[f] = sampled.times[f] - sampled.times.front();
  for (std::size_t i = 0; i < kDofCount; ++i) {
    fit.samples[i].assign(unwrapped[i].begin(), unwrapped[i].begin() + static_cast<std::ptrdiff_t>(n));
    centreTurns(fit.samples[i]);
    fit.reports[i].driven = sampled.driven[i / kDofsPerJoint];
  }

  // The walk frame from the average horizontal velocity over whole cycles.
  std::array<std::vector<double>, 2> horizontal;
  for (std::size_t f = 0; f < n; ++f) {
    for (std::size_t k = 0; k < 2; ++k) horizontal[k].push_back(sampled.root[f].translation[static_cast<int>(k)]);
  }
  const std::size_t trend_order = std::min<std::size_t>(4, sampling_limit);
  const FourierFit along_x = fitFourierSeries(fit.times, horizontal[0], period, trend_order, true);
  const FourierFit along_y = fitFourierSeries(fit.times, horizontal[1], period, trend_order, true);
  double heading = std::atan2(along_y.linear_rate, along_x.linear_rate);
  if (std::hypot(along_x.linear_rate, along_y.linear_rate) < kWalkingSpeedThreshold) {
    Eigen::Vector3d facing = Eigen::Vector3d::Zero();
    for (std::size_t f = 0; f < n; ++f) facing += sampled.root[f].rotation * Eigen::Vector3d::UnitX();
    heading = std::hypot(facing.x(), facing.y()) > 1e-9 ? std::atan2(facing.y(), facing.x()) : 0.0;
  }
  fit.walk_rotation = Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  fit.walk_origin = Eigen::Vector3d(0.5 * along_x.series.a0, 0.5 * along_y.series.a0, 0.0);

  std::array<std::vector<double>, 3> root_rotation;
  for (std::size_t f = 0; f < n; ++f) {
    const Eigen::Vector3d position = fit.walk_rotation.transpose() * (sampled.root[f].translation - fit.walk_origin);
    for (std::size_t k = 0; k < 3; ++k) fit.samples[kDofCount + k].push_back(position[static_cast<int>(k)]);
    const Eigen::Vector3d rpy =
        decomposeRollPitchYaw(fit.walk_rotation.transpose() * sampled.root[f].rotation.toRotationMatrix());
    for (std::size_t k = 0; k < 3; ++k) root_rotation[k].push_back(rpy[static_cast<int>(k)]);
  }
  for (std::size_t k = 0; k < 3; ++k) {
    fit.samples[kFirstRootRotation + k] = unwrapAngles(root_rotation[k]);
    centreTurns(fit.samples[kFirstRootRotation + k]);
    fit.reports[kDofCount + k].is_angle = false;
  }
  for (std::size_t i = 0; i < Motion::kSeriesCount; ++i) fitSeries(fit, i, options);
  fit.motion.validate();
  return fit;
}

MotionFit refitWithOrder(const MotionFit& fit, std::size_t order) {
  if (order > (fit.times.size() - 1) / 2) {
    throw MotionError("order " + std::to_string(order) + " needs more than " + std::to_string(fit.times.size()) +
                      " samples");
  }
  MotionFit refit = fit;
  MotionFitOptions options;
  options.fixed_order = order;
  for (std::size_t i = 0; i < Motion::kSeriesCount; ++i) fitSeries(refit, i, options);
  return refit;
}

}  // namespace dressed_human
