// The boundary of a skin cell as it owns pixels in the rasteriser (skin_relief_rasterizer.h).
#include "dressed_human/core/relief/skin_cell_boundary.h"

#include <algorithm>
#include <cmath>

namespace dressed_human {
namespace skin_detail {

namespace {

double wallParameter(const Wall& wall, const Eigen::Vector2d& point) {
  return (point - wall.start).dot(wall.tangent) / wall.length;
}

// Knots of a wall's polyline strictly between u_from and u_to, in that order.
void appendKnots(const CellLevel& level, const Wall& wall, double u_from, double u_to,
                 std::vector<Eigen::Vector2d>& chain) {
  if (level.subdivisions == 0 || wall.wobble < 0) return;
  const int segments = 1 << level.subdivisions;
  if (u_from < u_to) {
    for (int k = 1; k < segments; ++k) {
      const double u = static_cast<double>(k) / segments;
      if (u > u_from && u < u_to) chain.push_back(wallPoint(level, wall, u));
    }
  } else {
    for (int k = segments - 1; k >= 1; --k) {
      const double u = static_cast<double>(k) / segments;
      if (u < u_from && u > u_to) chain.push_back(wallPoint(level, wall, u));
    }
  }
}

// Where a sibling furrow that ends on the parent's straight wall at `junction` meets the parent's
// wobbled wall. Where the parent's wall bulges outward, the reference hands the bulge to the
// nearest sibling, so the boundary between siblings continues straight (direction `outward`)
// until it meets the wobble; where it dents inward the dent is another parent's and the parent
// mask cuts it off, so the wobbled wall point at the junction is enough.
Eigen::Vector2d junctionOnParentWall(const CellLevel& level, const Wall& wall, const Eigen::Vector2d& junction,
                                     const Eigen::Vector2d& outward) {
  const double u0 = wallParameter(wall, junction);
  const double h0 = (junction - wall.start).dot(wall.normal);
  const double rise = outward.dot(wall.normal);                  // height gain per unit along `outward`
  const double drift = outward.dot(wall.tangent) / wall.length;  // u per unit along `outward`
  const double f0 = h0 - outwardWobble(level, wall, u0);
  if (!(f0 < 0.0) || !(rise > 0.0) || level.subdivisions == 0) return wallPoint(level, wall, u0);
  // f(t) = height - wobble along the ray is linear between the wall's knots: walk them.
  const int segments = 1 << level.subdivisions;
  const auto f = [&](double t) { return h0 + rise * t - outwardWobble(level, wall, u0 + drift * t); };
  double t_previous = 0.0, f_previous = f0;
  int knot =
      drift > 0.0 ? static_cast<int>(std::floor(u0 * segments)) + 1 : static_cast<int>(std::ceil(u0 * segments)) - 1;
  for (int step = 0; step <= segments + 1 && drift != 0.0; ++step) {
    const double u_knot = static_cast<double>(knot) / segments;
    const double t_knot = (u_knot - u0) / drift;
    if (t_knot > t_previous) {
      const double f_knot = f(t_knot);
      if (f_knot >= 0.0) {
        const double t = t_previous + (t_knot - t_previous) * (-f_previous) / (f_knot - f_previous);
        return junction + t * outward;
      }
      t_previous = t_knot;
      f_previous = f_knot;
    }
    if (knot <= 0 || knot >= segments) break;  // beyond the wall's ends the wobble is 0
    knot += drift > 0.0 ? 1 : -1;
  }
  // Constant wobble ahead (past an end, or u fixed): f grows at `rise` minus the local wobble slope.
  const double t_probe = t_previous + 1.0;
  const double growth = f(t_probe) - f_previous;
  if (!(growth > 0.0)) return wallPoint(level, wall, u0);
  return junction + (t_previous - f_previous / growth) * outward;
}

// The level on which a wall is a furrow between siblings: its own level, or for an inherited
// wall (a copy of the parent's whole wall) the parent's answer for the same wall.
int wallOrigin(const std::vector<CellLevel>& levels, std::size_t level_index, const Cell& cell, const Wall& wall) {
  if (wall.neighbour >= 0 || level_index == 0) return static_cast<int>(level_index);
  const CellLevel& parents = levels[level_index - 1];
  const Cell& parent = parents.cells[static_cast<std::size_t>(cell.parent)];
  for (int k = 0; k < parent.wall_count; ++k) {
    const Wall& candidate = parents.walls[static_cast<std::size_t>(parent.first_wall + k)];
    if (candidate.start == wall.start && candidate.tangent == wall.tangent && candidate.length == wall.length)
      return wallOrigin(levels, level_index - 1, parent, candidate);
  }
  return -1;
}

// s = g . q with g . r_k = g . r_k+1 = 1 on the triangle (c, v_k, v_k+1).
Eigen::Vector2d fanGradient(const std::vector<Eigen::Vector2d>& relative, std::size_t k) {
  const std::size_t n = relative.size();
  const Eigen::Vector2d& a = relative[k];
  const Eigen::Vector2d& b = relative[(k + 1) % n];
  const double determinant = cross(a, b);
  return Eigen::Vector2d((b.y() - a.y()) / determinant, (a.x() - b.x()) / determinant);
}

// Folded somewhere: split the circle at every vertex direction and keep, per piece, the nearest
// boundary crossing (largest s); the pockets behind a fold are left to the per-pixel path
// (nothing here claims them).
void foldedBoundaryFan(const std::vector<Eigen::Vector2d>& relative, std::vector<BoundarySector>& sectors,
                       BoundaryFanScratch& scratch) {
  const std::size_t n = relative.size();
  scratch.angles.resize(n);
  scratch.order.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    scratch.angles[k] = diamondAngle(relative[k].x(), relative[k].y());
    scratch.order[k] = static_cast<int>(k);
  }
  const std::vector<double>& angles = scratch.angles;
  std::sort(scratch.order.begin(), scratch.order.end(),
            [&](int a, int b) { return angles[static_cast<std::size_t>(a)] < angles[static_cast<std::size_t>(b)]; });
  // Piece j lies between the sorted vertex directions j and j + 1. An edge can only cross
  // the pieces between its two ends' ranks, so each edge visits those (usually one) instead
  // of every piece testing every edge; edges in index order keep the first of equal values.
  scratch.rank.resize(n);
  for (std::size_t j = 0; j < n; ++j) scratch.rank[static_cast<std::size_t>(scratch.order[j])] = j;
  scratch.piece_direction.resize(n);
  scratch.piece_best.assign(n, 0.0);
  scratch.piece_winner.assign(n, -1);
  scratch.piece_gradient.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const double from = scratch.angles[static_cast<std::size_t>(scratch.order[j])];
    double to = scratch.angles[static_cast<std::size_t>(scratch.order[(j + 1) % n])];
    if (j + 1 == n) to += 4.0;
    scratch.piece_direction[j] = diamondDirection(0.5 * (from + to));
  }
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d& a = relative[k];
    const Eigen::Vector2d& b = relative[(k + 1) % n];
    const double orientation = cross(a, b);
    if (orientation == 0.0) continue;
    const std::size_t first_piece = orientation > 0.0 ? scratch.rank[k] : scratch.rank[(k + 1) % n];
    const std::size_t end_piece = orientation > 0.0 ? scratch.rank[(k + 1) % n] : scratch.rank[k];
    const Eigen::Vector2d g = fanGradient(relative, k);
    for (std::size_t j = first_piece; j != end_piece; j = j + 1 == n ? 0 : j + 1) {
      const Eigen::Vector2d& direction = scratch.piece_direction[j];
      const bool inside = orientation > 0.0 ? cross(a, direction) > 0.0 && cross(direction, b) > 0.0
                                            : cross(b, direction) > 0.0 && cross(direction, a) > 0.0;
      if (!inside) continue;
      const double value = g.dot(direction);
      if (value > scratch.piece_best[j]) {
        scratch.piece_best[j] = value;
        scratch.piece_winner[j] = static_cast<int>(k);
        scratch.piece_gradient[j] = g;
      }
    }
  }
  int previous_winner = -2;
  for (std::size_t j = 0; j < n; ++j) {
    const double from = scratch.angles[static_cast<std::size_t>(scratch.order[j])];
    double to = scratch.angles[static_cast<std::size_t>(scratch.order[(j + 1) % n])];
    if (j + 1 == n) to += 4.0;
    if (!(to - from > 1e-12)) continue;
    const int winner = scratch.piece_winner[j];
    Eigen::Vector2d best_gradient = winner >= 0 ? scratch.piece_gradient[j] : Eigen::Vector2d(0.0, 0.0);
    if (winner == previous_winner && winner >= 0) continue;  // same triangle continues
    previous_winner = winner;
    // No crossing at all (cannot happen for a closed boundary around the centre): nothing
    // in this sector is claimed.
    if (winner < 0) best_gradient = Eigen::Vector2d(INFINITY, INFINITY);
    const Eigen::Vector2d& start = relative[static_cast<std::size_t>(scratch.order[j])];
    sectors.push_back({start, best_gradient});
  }
}

}  // namespace

// The closed boundary of a cell as it owns pixels, counter-clockwise, in the cell's frame: each
// wall's polyline between the cell's corners. Where a finer furrow ends on a coarser (inherited)
// one, the boundary follows the finer furrow's straight line on to the coarser one's wobble
// (junctionOnParentWall) -- the same point on both sides and on every level below.
std::vector<Eigen::Vector2d> boundaryChain(const std::vector<CellLevel>& levels, std::size_t level_index,
                                           const Cell& cell) {
  const CellLevel& level = levels[level_index];
  std::vector<Eigen::Vector2d> chain;
  const std::size_t count = cell.polygon.size();
  const auto wallOf = [&](std::size_t edge) -> const Wall& {
    return level.walls[static_cast<std::size_t>(cell.first_wall) + edge];
  };
  std::vector<int> origin(count);
  for (std::size_t edge = 0; edge < count; ++edge) origin[edge] = wallOrigin(levels, level_index, cell, wallOf(edge));
  for (std::size_t edge = 0; edge < count; ++edge) {
    const Eigen::Vector2d& from = cell.polygon[edge];
    const Eigen::Vector2d& to = cell.polygon[(edge + 1) % count];
    const Wall& wall = wallOf(edge);
    chain.push_back(from);
    const std::size_t before = (edge + count - 1) % count, after = (edge + 1) % count;
    const bool junction_first = origin[before] > origin[edge] && wall.wobble >= 0 && level.subdivisions > 0;
    const bool junction_last = origin[after] > origin[edge] && wall.wobble >= 0 && level.subdivisions > 0;
    Eigen::Vector2d first = from, last = to;
    if (junction_first) {
      first = junctionOnParentWall(level, wall, from, (from - cell.polygon[before]).normalized());
      chain.push_back(first);
    }
    if (junction_last)
      last = junctionOnParentWall(level, wall, to, (to - cell.polygon[(edge + 2) % count]).normalized());
    const double u_from = wallParameter(wall, from), u_to = wallParameter(wall, to);
    double u_first = wallParameter(wall, first), u_last = wallParameter(wall, last);
    // Keep the junction points inside the edge's own u range order.
    if ((u_to - u_from) * (u_last - u_first) <= 0.0) u_last = u_first;
    appendKnots(level, wall, u_first, u_last, chain);
    if (junction_last) chain.push_back(last);
  }
  return chain;
}

void boundaryFan(const std::vector<Eigen::Vector2d>& relative, std::vector<BoundarySector>& sectors,
                 BoundaryFanScratch& scratch) {
  sectors.clear();
  const std::size_t n = relative.size();
  bool monotone = n >= 3;
  double turned = 0.0;
  for (std::size_t k = 0; k < n && monotone; ++k) {
    const Eigen::Vector2d& a = relative[k];
    const Eigen::Vector2d& b = relative[(k + 1) % n];
    if (!(cross(a, b) > 1e-14 * a.norm() * b.norm())) monotone = false;
    // Turn in pseudo-angle units (a half turn is 2; each step here is less than that).
    double step = diamondAngle(b.x(), b.y()) - diamondAngle(a.x(), a.y());
    if (step < 0.0) step += 4.0;
    turned += step;
  }
  if (monotone && std::abs(turned - 4.0) < 1e-6) {
    for (std::size_t k = 0; k < n; ++k) {
      const Eigen::Vector2d g = fanGradient(relative, k);
      sectors.push_back({relative[k], g});
    }
  } else if (n >= 3) {
    foldedBoundaryFan(relative, sectors, scratch);
  }
}

}  // namespace skin_detail
}  // namespace dressed_human
