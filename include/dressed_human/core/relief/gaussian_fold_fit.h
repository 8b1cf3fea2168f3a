// Gaussian approximation of a buckling pattern's footprint height (seed paper 000 §4.2, Fig. 7),
// the smooth surface the paper bump-maps instead of the creased exact folds.
//
// h(x, y) ~ sum_k a_k exp(-(x - cx_k)^2 / (2 sx_k^2) - (y - cy_k)^2 / (2 sy_k^2)).
// Fit: orthogonal matching pursuit over a fixed dictionary of anisotropic Gaussians (centres on a
// grid over the footprint, widths proportional to L_x and alpha L_y), amplitudes by linear least
// squares on the chosen set after every pick. Greedy + re-solve gives a fit whose RMS error never
// increases with K (each set contains the previous one), which is what a level-of-detail knob needs;
// a full non-linear fit of centres and widths would be tighter but has local minima.
#pragma once

#include "dressed_human/core/relief/buckling_pattern.h"

#include <vector>

namespace dressed_human {

struct GaussianTerm {
  double amplitude = 0.0;
  double centre_x = 0.0, centre_y = 0.0;
  double sigma_x = 1.0, sigma_y = 1.0;
};

class GaussianFoldApproximation {
 public:
  GaussianFoldApproximation() = default;
  explicit GaussianFoldApproximation(std::vector<GaussianTerm> terms) : terms_(std::move(terms)) {}

  const std::vector<GaussianTerm>& terms() const { return terms_; }
  ReliefSample sample(double x, double y) const;

 private:
  std::vector<GaussianTerm> terms_;
};

struct GaussianFitOptions {
  int samples_per_axis = 48;  ///< fit grid over the footprint (>= 4)
  int centres_per_axis = 9;   ///< dictionary centre grid (>= 2)
};

/// Fit `term_count` (>= 1) Gaussians to the pattern's footprint height. Stops early (fewer terms)
/// when the pattern is flat. Throws std::invalid_argument for bad counts.
GaussianFoldApproximation fitGaussians(const BucklingPattern& pattern, int term_count,
                                       const GaussianFitOptions& options = {});

/// RMS of (approximation - exact) over a samples x samples grid covering the footprint.
double rmsApproximationError(const BucklingPattern& pattern, const GaussianFoldApproximation& approximation,
                             int samples_per_axis = 64);

}  // namespace dressed_human
