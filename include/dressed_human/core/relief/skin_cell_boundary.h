// The closed boundary of a skin cell as it owns pixels in the rasteriser
// (skin_relief_rasterizer.h): its walls' wobbled polylines between the cell's corners.
#pragma once

#include "dressed_human/core/relief/skin_cell_hierarchy.h"

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
std::vector<Eigen::Vector2d> boundaryChain(const std::vector<CellLevel>& levels, std::size_t level_index, const Cell& cell);

}  // namespace skin_detail
}  // namespace dressed_human
