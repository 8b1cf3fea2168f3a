// Cross-section of a skin ridge cell (paper 004 §4.1, Fig. 6): a cubic Bezier curve in
// (x, z) with x = normalised distance from the cell edge (0) to the centre (1) and z the
// normalised height (0 at the edge, 1 at the centre).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace dressed_human {

struct BezierProfile {
  /// Inner control points P1, P2 (P0 = (0, 0), P3 = (1, 1)). Require 0 <= P1.x <= P2.x <= 1 so
  /// that x(t) is monotone and z is a function of x; z may leave [0, 1] (overshoot is allowed).
  Eigen::Vector2d first_inner{1.0 / 3.0, 1.0 / 3.0};
  Eigen::Vector2d second_inner{2.0 / 3.0, 1.0};

  /// The paper's "slope" knob (Fig. 11): the furrow wall rises with dz/dx = edge_slope at the
  /// edge and the top is flat. edge_slope > 0.
  static BezierProfile fromEdgeSlope(double edge_slope);
};

/// Tabulated z(x) and dz/dx of a profile: per-pixel evaluation must not solve a cubic.
class BezierProfileTable {
 public:
  /// Throws std::invalid_argument when the control points violate the monotonicity rule or
  /// entries < 16.
  explicit BezierProfileTable(const BezierProfile& profile, int entries = 2048);

  /// x is clamped to [0, 1]; linear interpolation between entries.
  void evaluate(double x, double& height, double& slope) const {
    const double position = (x <= 0.0 ? 0.0 : (x >= 1.0 ? 1.0 : x)) * last_;
    int index = static_cast<int>(position);
    if (index >= static_cast<int>(last_)) index = static_cast<int>(last_) - 1;
    const double fraction = position - index;
    const auto at = static_cast<std::size_t>(index);
    height = heights_[at] + fraction * (heights_[at + 1] - heights_[at]);
    slope = slopes_[at] + fraction * (slopes_[at + 1] - slopes_[at]);
  }

  /// The table itself: entries last() + 1 at x = k / last(), evaluate() interpolates them.
  double last() const { return last_; }
  const std::vector<double>& heights() const { return heights_; }
  const std::vector<double>& slopes() const { return slopes_; }

  /// Exact evaluation by solving x(t) = x (for tests and table construction).
  static void evaluateExact(const BezierProfile& profile, double x, double& height, double& slope);

 private:
  double last_ = 0.0;
  std::vector<double> heights_;
  std::vector<double> slopes_;
};

}  // namespace dressed_human
