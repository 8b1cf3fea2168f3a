// The closed boundary of a skin cell as it owns pixels in the rasteriser
// (skin_relief_rasterizer.h): its walls' wobbled polylines between the cell's corners, and its
// fan seen from the cell's centre.
#pragma once

#include "dressed_human/core/relief/skin_cell_hierarchy.h"

#include <cmath>
#include <vector>

namespace dressed_human {
namespace skin_detail {

/// The point of a wall's wobbled polyline at parameter u along it.
inline Eigen::Vector2d wallPoint(const CellLevel& level, const Wall& wall, double u) {
  return wall.start + wall.tangent * (u * wall.length) + wall.normal * outwardWobble(level, wall, u);
}

/// Counter-clockwise, in the cell's frame. Where a finer furrow ends on a coarser (inherited)
/// one, the boundary follows the finer furrow's straight line on to the coarser one's wobble --
/// the same point on both sides and on every level below.
std::vector<Eigen::Vector2d> boundaryChain(const std::vector<CellLevel>& levels, std::size_t level_index,
                                           const Cell& cell);

/// One sector of a boundary's fan seen from the cell's centre.
struct BoundarySector {
  Eigen::Vector2d direction;  ///< start ray
  Eigen::Vector2d boundary;   ///< gradient of the ray ratio to the boundary (< 1 inside)
};

/// Scratch of boundaryFan, kept from cell to cell.
struct BoundaryFanScratch {
  std::vector<double> angles;
  std::vector<int> order;
  std::vector<std::size_t> rank;
  std::vector<Eigen::Vector2d> piece_direction, piece_gradient;
  std::vector<double> piece_best;
  std::vector<int> piece_winner;
};

/// `sectors` (cleared first) from the boundary's vertices relative to the centre: one per fan
/// triangle where the boundary is star-shaped from the centre; where it folds, per angular piece
/// the nearest boundary crossing, the pockets behind the fold claimed by no sector.
void boundaryFan(const std::vector<Eigen::Vector2d>& relative, std::vector<BoundarySector>& sectors,
                 BoundaryFanScratch& scratch);

inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Monotone in the angle of (x, y), in [0, 4): orders directions without atan2.
inline double diamondAngle(double x, double y) {
  const double sum = std::abs(x) + std::abs(y);
  if (!(sum > 0.0)) return 0.0;
  const double t = y / sum;
  return x >= 0.0 ? (t < 0.0 ? 4.0 + t : t) : 2.0 - t;
}

/// Inverse of diamondAngle: a direction (not unit) of pseudo-angle a, any real a.
inline Eigen::Vector2d diamondDirection(double a) {
  a -= 4.0 * std::floor(a / 4.0);
  if (a < 1.0) return Eigen::Vector2d(1.0 - a, a).normalized();
  if (a < 2.0) return Eigen::Vector2d(1.0 - a, 2.0 - a).normalized();
  if (a < 3.0) return Eigen::Vector2d(a - 3.0, 2.0 - a).normalized();
  return Eigen::Vector2d(a - 3.0, a - 4.0).normalized();
}

}  // namespace skin_detail
}  // namespace dressed_human
