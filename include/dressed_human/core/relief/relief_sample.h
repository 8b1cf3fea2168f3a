// The value every relief source hands the renderer: buckling patterns, their Gaussian fits,
// wrinkle and relief maps, the skin's Voronoi cells.
#pragma once

#include <Eigen/Core>

namespace dressed_human {

/// Height and gradient of a relief at one point.
struct ReliefSample {
  double height = 0.0;
  Eigen::Vector2d slope = Eigen::Vector2d::Zero();  ///< (dh/dx, dh/dy)
};

}  // namespace dressed_human
