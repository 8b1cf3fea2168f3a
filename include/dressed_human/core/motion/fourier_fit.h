#pragma once
// Least-squares fit of one sampled channel with a truncated Fourier series (SPEC Eq. 1), optionally
// plus a linear term (the root's forward progression), and the choice of the smallest order that
// reaches a tolerance.

#include <cstddef>
#include <vector>

#include "dressed_human/core/motion/motion.h"

namespace dressed_human {

struct FourierFit {
  FourierSeries series;       // period as given, phase 0: t = 2 pi time / period
  double linear_rate = 0.0;   // units per second; 0 unless fitted with the linear term
  double rms_residual = 0.0;  // root mean square of (sample - model), in the samples' unit
  bool reached_tolerance = true;
};

// Removes the 2 pi jumps of angles read as (-pi, pi]: every step is replaced by the equivalent step
// in (-pi, pi]. The result is continuous as long as the true motion moves less than pi per sample.
std::vector<double> unwrapAngles(const std::vector<double>& wrapped);

// Householder QR on the design matrix [time (optional), 1/2, cos(n w t), sin(n w t)], n = 1..order.
// Throws MotionError when there are fewer samples than unknowns or a value is not finite.
FourierFit fitFourierSeries(const std::vector<double>& times, const std::vector<double>& values, double period,
                            std::size_t order, bool with_linear_term = false);

// The smallest order 0..max_order whose RMS residual is <= tolerance; max_order (and
// reached_tolerance = false) when none is.
FourierFit fitFourierSeriesToTolerance(const std::vector<double>& times, const std::vector<double>& values,
                                       double period, double tolerance, std::size_t max_order,
                                       bool with_linear_term = false);

}  // namespace dressed_human
