#include "dressed_human/core/motion/gait_period.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "dressed_human/core/motion/motion.h"

namespace dressed_human {
namespace {

std::vector<double> withoutStraightLine(const std::vector<double>& values) {
  const double n = static_cast<double>(values.size());
  double mean_i = 0.0;
  double mean_v = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    mean_i += static_cast<double>(i) / n;
    mean_v += values[i] / n;
  }
  double covariance = 0.0;
  double variance = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    covariance += (static_cast<double>(i) - mean_i) * (values[i] - mean_v);
    variance += (static_cast<double>(i) - mean_i) * (static_cast<double>(i) - mean_i);
  }
  const double slope = variance > 0.0 ? covariance / variance : 0.0;
  std::vector<double> residual(values.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    residual[i] = values[i] - mean_v - slope * (static_cast<double>(i) - mean_i);
  return residual;
}

std::string seconds(double value) {
  std::ostringstream text;
  text.precision(3);
  text << value << " s";
  return text.str();
}

// How far r at `lag` may stray from its expectation: the overlap cut into stretches of `chunk`
// frames, each stretch's own pooled correlation at `lag`, their standard error. It grows as the
// overlap shrinks and as the cycles differ from each other; 0 when fewer than two stretches fit.
double correlationStandardError(const std::vector<std::vector<double>>& x, std::size_t lag, std::size_t chunk) {
  const std::size_t frames = x.front().size();
  if (chunk == 0 || frames <= lag) return 0.0;
  const std::size_t count = (frames - lag) / chunk;
  if (count < 2) return 0.0;
  std::vector<double> values;
  for (std::size_t c = 0; c < count; ++c) {
    double product = 0.0, head = 0.0, tail = 0.0;
    for (const std::vector<double>& channel : x) {
      for (std::size_t i = c * chunk; i < (c + 1) * chunk; ++i) {
        product += channel[i] * channel[i + lag];
        head += channel[i] * channel[i];
        tail += channel[i + lag] * channel[i + lag];
      }
    }
    values.push_back(head > 0.0 && tail > 0.0 ? product / std::sqrt(head * tail) : 0.0);
  }
  double mean = 0.0;
  for (const double v : values) mean += v / static_cast<double>(count);
  double variance = 0.0;
  for (const double v : values) variance += (v - mean) * (v - mean) / static_cast<double>(count - 1);
  return std::sqrt(variance / static_cast<double>(count));
}

}  // namespace

PeriodEstimate estimateGaitPeriod(const std::vector<std::vector<double>>& channels, double frame_time,
                                  const PeriodOptions& options) {
  if (!std::isfinite(frame_time) || frame_time <= 0.0)
    throw MotionError("period estimation: the frame time must be > 0");
  if (channels.empty()) throw MotionError("period estimation: no channels");
  const std::size_t frames = channels.front().size();
  std::vector<std::vector<double>> detrended;
  double energy = 0.0;
  for (const std::vector<double>& channel : channels) {
    if (channel.size() != frames) throw MotionError("period estimation: channels of different lengths");
    for (const double v : channel) {
      if (!std::isfinite(v)) throw MotionError("period estimation: a sample is not a finite number");
    }
    detrended.push_back(withoutStraightLine(channel));
    // What remains of a constant or a straight line is rounding noise of the size of the values
    // (eps |v|): an absolute threshold lets a large constant or ramp through, and the
    // autocorrelation of that noise can show a "period". Below the rounding level it is no motion.
    double raw_energy = 0.0;
    double residual_energy = 0.0;
    for (const double v : channel) raw_energy += v * v;
    for (const double v : detrended.back()) residual_energy += v * v;
    constexpr double kRoundingLevel = 64.0 * std::numeric_limits<double>::epsilon();
    if (residual_energy <= kRoundingLevel * kRoundingLevel * raw_energy) {
      std::fill(detrended.back().begin(), detrended.back().end(), 0.0);
      residual_energy = 0.0;
    }
    energy += residual_energy;
  }
  const std::size_t min_lag =
      std::max<std::size_t>(2, static_cast<std::size_t>(std::ceil(options.min_period / frame_time)));
  std::size_t max_lag = frames / 2;
  if (options.max_period > 0.0) {
    max_lag = std::min(max_lag, static_cast<std::size_t>(std::floor(options.max_period / frame_time)));
  }
  const double duration = static_cast<double>(frames) * frame_time;
  if (max_lag < min_lag + 2) {
    throw MotionError("too few frames to estimate the period: " + std::to_string(frames) + " frames (" +
                      seconds(duration) + ") do not hold two cycles of at least " + seconds(options.min_period) +
                      "; give the period (--period) if the record is a single cycle");
  }
  if (!(energy > 1e-20)) throw MotionError("no motion: every channel is constant, there is no period to find");

  PeriodEstimate estimate;
  estimate.autocorrelation.assign(max_lag + 1, 0.0);
  for (std::size_t lag = 0; lag <= max_lag; ++lag) {
    double product = 0.0;
    double head = 0.0;
    double tail = 0.0;
    for (const std::vector<double>& x : detrended) {
      for (std::size_t i = 0; i + lag < frames; ++i) {
        product += x[i] * x[i + lag];
        head += x[i] * x[i];
        tail += x[i + lag] * x[i + lag];
      }
    }
    estimate.autocorrelation[lag] = head > 0.0 && tail > 0.0 ? product / std::sqrt(head * tail) : 0.0;
  }
  const std::vector<double>& r = estimate.autocorrelation;
  std::size_t best = 0;
  for (std::size_t lag = min_lag; lag < max_lag; ++lag) {
    const bool peak = r[lag] >= r[lag - 1] && r[lag] > r[lag + 1];
    if (peak && (best == 0 || r[lag] > r[best])) best = lag;
  }
  if (best == 0) {
    throw MotionError("no clear period: the autocorrelation has no peak between " + seconds(min_lag * frame_time) +
                      " and " + seconds(max_lag * frame_time) + " (is this a periodic motion, with two cycles?)");
  }
  if (r[best] < options.min_correlation) {
    std::ostringstream text;
    text.precision(3);
    text << "no clear period: the best autocorrelation peak is " << r[best] << " at " << seconds(best * frame_time)
         << ", below " << options.min_correlation << " (the motion does not repeat)";
    throw MotionError(text.str());
  }
  // A record of several cycles has peaks at T, 2T, 3T... and which is highest is down to noise
  // (measured: a multiple won 7 times in 40 noisy 5-cycle records) and, in a capture, to how its
  // cycles differ (a walk of 7 cycles: r 0.866 at T, 0.887 at 3T). Take the shortest lag that the
  // highest peak is a whole multiple of, when its peak is as high within the noise of the two
  // estimates: kTie, or twice their combined standard error, whichever is larger. Cycles vary in
  // length, so the multiple's peak may sit up to kMultipleSlack of a cycle off n T.
  // (test_stability_fitting: synthetic captures whose cycles differ, 14 of 40 took a multiple
  // with kTie alone, 1 with the standard error; a motion that repeats every third cycle keeps it.)
  const std::size_t highest = best;
  for (std::size_t lag = min_lag; lag < highest; ++lag) {
    const bool peak = r[lag] >= r[lag - 1] && r[lag] > r[lag + 1];
    const double ratio = static_cast<double>(highest) / static_cast<double>(lag);
    constexpr double kMultipleSlack = 0.2;
    if (!peak || std::abs(ratio - std::round(ratio)) >= kMultipleSlack) continue;
    constexpr double kTie = 0.02;
    const double noise = std::hypot(correlationStandardError(detrended, lag, lag),
                                    correlationStandardError(detrended, highest, lag));
    if (r[lag] >= r[highest] - std::max(kTie, 2.0 * noise)) {
      best = lag;
      break;
    }
  }
  const double curvature = r[best - 1] - 2.0 * r[best] + r[best + 1];
  double shift = curvature < 0.0 ? 0.5 * (r[best - 1] - r[best + 1]) / curvature : 0.0;
  shift = std::max(-0.5, std::min(0.5, shift));
  estimate.period = (static_cast<double>(best) + shift) * frame_time;
  estimate.correlation = r[best];
  return estimate;
}

}  // namespace dressed_human
