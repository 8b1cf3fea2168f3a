#pragma once
// Gait period from the data: the lag that maximises the pooled, normalised autocorrelation of
// all channels.
//
// Every channel (uniformly sampled) loses its least-squares straight line first, so that a slow
// drift does not read as a long period. For each lag k the autocorrelation is pooled over the
// channels and normalised over the overlapping part only:
//   r(k) = sum_c sum_i x_c[i] x_c[i+k] / sqrt(sum_c sum_i x_c[i]^2 * sum_c sum_i x_c[i+k]^2),
//   i = 0 .. N-k-1,
// so r = 1 for an exactly periodic signal at any lag that is a multiple of its period, whatever
// the overlap. Pooling weights channels by their energy: the large leg and arm swings dominate,
// and since left and right are half a cycle apart, the stride (not the step) wins. The period is
// the highest local maximum of r for lags from min_period up to half the record (two cycles must
// be seen) -- or the shortest peak it is a whole multiple of, if that one is as high within the
// noise of the two estimates (r(T) and r(3T) of a capture differ by noise and by how its cycles
// differ): 0.02, or twice the standard error of the difference, each r's standard error taken
// from the spread of r over the overlap's stretches of one shorter lag -- refined to sub-frame
// precision by a parabola through the peak and its neighbours.
// No local maximum, or a highest one below min_correlation, means no clear period: an error, not
// a guess. PeriodEstimate::correlation is r at the period chosen, which may lie below it.

#include <cstddef>
#include <vector>

namespace dressed_human {

struct PeriodOptions {
  double min_period = 0.3;       // seconds: faster than any gait cycle
  double max_period = 0.0;       // seconds; 0: half the record
  double min_correlation = 0.6;  // the peak must be at least this clear
};

struct PeriodEstimate {
  double period = 0.0;                  // seconds
  double correlation = 0.0;             // r at the peak
  std::vector<double> autocorrelation;  // r(k) for k = 0 .. max lag (r(0) = 1), for plots and reports
};

// Throws MotionError: too few frames for two cycles, constant channels, no clear period.
PeriodEstimate estimateGaitPeriod(const std::vector<std::vector<double>>& channels, double frame_time,
                                  const PeriodOptions& options = PeriodOptions());

}  // namespace dressed_human
