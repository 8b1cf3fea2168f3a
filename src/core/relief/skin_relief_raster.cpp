// render() for polygonal contours (roundness 0): each cell is rasterised from its centre as
// angular sectors, instead of searching the cell of every pixel.
//
// Why this gives the reference's heights: with roundness 0 the height parameter at p is
// s = max over walls of the ray ratio |p - c| / |hit - c|, and the reference decides which wall
// wins and which of its segments is hit (or that its segment walk keeps the straight line) from
// the direction of p - c alone. On one straight segment s is linear in p, s = g . (p - c). So
// s has a constant gradient inside each angular sector between the directions where one of those
// decisions changes. The sectors are built at construction without sampling: one wall's decision
// can only change at directions through its polyline knots, through the points of its straight
// line where the segment walk starts on another segment (and one segment past either end), and
// parallel to a segment; between consecutive such directions every wall's g is fixed (one ray hit
// per wall at the piece's middle), and the max over walls of those linear functions changes only
// where two tie, d perpendicular to g_a - g_b (buildRasterLevels walks that upper envelope).
// A pixel only needs its sector -- found incrementally along a row, the row split at the columns
// where it crosses a sector's ray.
// Which cell owns a pixel follows the cell's boundary polygon (the wobbled walls, and on child
// levels the parent's wobbled wall pieces): inside the polygon exactly where the ray ratio to it,
// linear per sector too, is < 1; a pixel also needs its parent on the level above. Pixels no
// cell claims -- pockets where a wobbled wall folds back as seen from the centre, slivers at
// junctions, pixels exactly on a boundary -- go through the per-pixel path (the reference's
// decisions). The ownership rule differs from the reference's nearest-seed-then-wobble rule at a
// few pixels along furrows (near corners, where two walls' wobbled polylines cross and the
// reference flips a pixel at most once, the boundary polygons of two cells can overlap and the
// first cell in index order takes the pixel); skin_relief.h states how many,
// test_skin_relief.cpp checks it.
#include "dressed_human/core/relief/skin_relief.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dressed_human {

using skin_detail::Cell;
using skin_detail::CellLevel;
using skin_detail::Wall;
using skin_detail::outwardWobble;

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }


Eigen::Vector2d wallPoint(const CellLevel& level, const Wall& wall, double u) {
  return wall.start + wall.tangent * (u * wall.length) + wall.normal * outwardWobble(level, wall, u);
}

double wallParameter(const Wall& wall, const Eigen::Vector2d& point) {
  return (point - wall.start).dot(wall.tangent) / wall.length;
}

// Knots of a wall's polyline strictly between u_from and u_to, in that order.
void appendKnots(const CellLevel& level, const Wall& wall, double u_from, double u_to, std::vector<Eigen::Vector2d>& chain) {
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
  const double rise = outward.dot(wall.normal);  // height gain per unit along `outward`
  const double drift = outward.dot(wall.tangent) / wall.length;  // u per unit along `outward`
  const double f0 = h0 - outwardWobble(level, wall, u0);
  if (!(f0 < 0.0) || !(rise > 0.0) || level.subdivisions == 0) return wallPoint(level, wall, u0);
  // f(t) = height - wobble along the ray is linear between the wall's knots: walk them.
  const int segments = 1 << level.subdivisions;
  const auto f = [&](double t) { return h0 + rise * t - outwardWobble(level, wall, u0 + drift * t); };
  double t_previous = 0.0, f_previous = f0;
  int knot = drift > 0.0 ? static_cast<int>(std::floor(u0 * segments)) + 1 : static_cast<int>(std::ceil(u0 * segments)) - 1;
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

// The closed boundary of a cell as it owns pixels, counter-clockwise, in the cell's frame: each
// wall's polyline between the cell's corners. Where a finer furrow ends on a coarser (inherited)
// one, the boundary follows the finer furrow's straight line on to the coarser one's wobble
// (junctionOnParentWall) -- the same point on both sides and on every level below.
std::vector<Eigen::Vector2d> boundaryChain(const std::vector<CellLevel>& levels, std::size_t level_index, const Cell& cell) {
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
    if (junction_last) last = junctionOnParentWall(level, wall, to, (to - cell.polygon[(edge + 2) % count]).normalized());
    const double u_from = wallParameter(wall, from), u_to = wallParameter(wall, to);
    double u_first = wallParameter(wall, first), u_last = wallParameter(wall, last);
    // Keep the junction points inside the edge's own u range order.
    if ((u_to - u_from) * (u_last - u_first) <= 0.0) u_last = u_first;
    appendKnots(level, wall, u_first, u_last, chain);
    if (junction_last) chain.push_back(last);
  }
  return chain;
}

// Monotone in the angle of (x, y), in [0, 4): orders directions without atan2.
double diamondAngle(double x, double y) {
  const double sum = std::abs(x) + std::abs(y);
  if (!(sum > 0.0)) return 0.0;
  const double t = y / sum;
  return x >= 0.0 ? (t < 0.0 ? 4.0 + t : t) : 2.0 - t;
}

// Inverse of diamondAngle: a direction (not unit) of pseudo-angle a, any real a.
Eigen::Vector2d diamondDirection(double a) {
  a -= 4.0 * std::floor(a / 4.0);
  if (a < 1.0) return Eigen::Vector2d(1.0 - a, a).normalized();
  if (a < 2.0) return Eigen::Vector2d(1.0 - a, 2.0 - a).normalized();
  if (a < 3.0) return Eigen::Vector2d(a - 3.0, 2.0 - a).normalized();
  return Eigen::Vector2d(a - 3.0, a - 4.0).normalized();
}

// Exact comparison (the same wall segment gives the same bits); NaN, from a degenerate wall,
// counts as equal to itself so the bisection below does not chase it.
bool sameGradient(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  return same(a.x(), b.x()) && same(a.y(), b.y());
}

}  // namespace

void SkinRelief::buildRasterLevels() {
  raster_.assign(levels_.size(), RasterLevel());
  raster_ready_ = roundness_exponent_ == 0 && max_wall_count_ <= 64;  // walls as bits of a 64-bit mask
  std::vector<Eigen::Vector2d> relative;
  std::vector<double> angles;
  std::vector<int> order;
  std::vector<std::size_t> rank;
  std::vector<Eigen::Vector2d> piece_direction, piece_gradient;
  std::vector<double> piece_best;
  std::vector<int> piece_winner;
  struct ChainSector {
    Eigen::Vector2d direction;  // start ray
    Eigen::Vector2d boundary;   // gradient of the ray ratio to the boundary
  };
  std::vector<ChainSector> chain_sectors;
  struct CriticalDirection {
    double angle;  // diamondAngle, in [0, 4)
    Eigen::Vector2d direction;  // unit
    int wall;  // whose decision can change here (-1: none, a piece boundary only)
  };
  std::vector<CriticalDirection> critical, pieces;
  struct PrunedDirection {
    double angle;  // diamondAngle, in [0, 4)
    int wall;
  };
  std::vector<PrunedDirection> pruned, splits;
  std::vector<Eigen::Vector2d> candidate_gradients;
  // Per wall of the current cell, its gradient at the last piece evaluated, valid until the walk
  // passes one of that wall's critical directions (the wall's decision is fixed in between).
  std::vector<Eigen::Vector2d> cached_gradient;
  std::vector<char> cached_usable;
  std::uint64_t cached = 0;
  for (std::size_t index = 0; index < levels_.size() && raster_ready_; ++index) {
    const CellLevel& level = levels_[index];
    RasterLevel& out = raster_[index];
    out.depth = level.depth;
    out.cells.reserve(level.cells.size());
    // Sectors and boundary vertices grow by the tens per cell: reserve about what the
    // benchmark's maps use, so growth does not copy megabytes time and again.
    out.sectors.reserve(level.cells.size() * 40);
    out.vertices.reserve(level.cells.size() * 40);
    for (const Cell& cell : level.cells) {
      RasterCell raster;
      raster.centre_x = cell.centre.x();
      raster.centre_y = cell.centre.y();
      raster.parent = cell.parent;
      raster.first_sector = static_cast<int>(out.sectors.size());
      const std::vector<Eigen::Vector2d> chain = boundaryChain(levels_, index, cell);
      relative.clear();
      Eigen::Vector2d low = chain.front(), high = chain.front();
      for (const Eigen::Vector2d& vertex : chain) {
        low = low.cwiseMin(vertex);
        high = high.cwiseMax(vertex);
        const Eigen::Vector2d r = vertex - cell.centre;
        if (relative.empty() || (r - relative.back()).squaredNorm() > 1e-30) relative.push_back(r);
      }
      while (relative.size() > 1 && (relative.front() - relative.back()).squaredNorm() <= 1e-30) relative.pop_back();
      raster.low_x = low.x();
      raster.low_y = low.y();
      raster.high_x = high.x();
      raster.high_y = high.y();
      // A cell wider than the tile would meet its own periodic image in the row loop.
      if (high.x() - low.x() >= 1.0 || high.y() - low.y() >= 1.0) raster_ready_ = false;
      const std::size_t n = relative.size();
      // s = g . q with g . r_k = g . r_k+1 = 1 on the triangle (c, v_k, v_k+1).
      const auto gradientOf = [&](std::size_t k) {
        const Eigen::Vector2d& a = relative[k];
        const Eigen::Vector2d& b = relative[(k + 1) % n];
        const double determinant = cross(a, b);
        return Eigen::Vector2d((b.y() - a.y()) / determinant, (a.x() - b.x()) / determinant);
      };
      chain_sectors.clear();
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
        // The boundary is star-shaped from the centre: one sector per fan triangle.
        for (std::size_t k = 0; k < n; ++k) {
          const Eigen::Vector2d g = gradientOf(k);
          chain_sectors.push_back({relative[k], g});
        }
      } else if (n >= 3) {
        // Folded somewhere: split the circle at every vertex direction and keep, per piece, the
        // nearest boundary crossing (largest s); the pockets behind a fold are left to the
        // per-pixel path (nothing here claims them).
        angles.resize(n);
        order.resize(n);
        for (std::size_t k = 0; k < n; ++k) {
          angles[k] = diamondAngle(relative[k].x(), relative[k].y());
          order[k] = static_cast<int>(k);
        }
        std::sort(order.begin(), order.end(), [&](int a, int b) { return angles[static_cast<std::size_t>(a)] < angles[static_cast<std::size_t>(b)]; });
        // Piece j lies between the sorted vertex directions j and j + 1. An edge can only cross
        // the pieces between its two ends' ranks, so each edge visits those (usually one) instead
        // of every piece testing every edge; edges in index order keep the first of equal values.
        rank.resize(n);
        for (std::size_t j = 0; j < n; ++j) rank[static_cast<std::size_t>(order[j])] = j;
        piece_direction.resize(n);
        piece_best.assign(n, 0.0);
        piece_winner.assign(n, -1);
        piece_gradient.resize(n);
        for (std::size_t j = 0; j < n; ++j) {
          const double from = angles[static_cast<std::size_t>(order[j])];
          double to = angles[static_cast<std::size_t>(order[(j + 1) % n])];
          if (j + 1 == n) to += 4.0;
          piece_direction[j] = diamondDirection(0.5 * (from + to));
        }
        for (std::size_t k = 0; k < n; ++k) {
          const Eigen::Vector2d& a = relative[k];
          const Eigen::Vector2d& b = relative[(k + 1) % n];
          const double orientation = cross(a, b);
          if (orientation == 0.0) continue;
          const std::size_t first_piece = orientation > 0.0 ? rank[k] : rank[(k + 1) % n];
          const std::size_t end_piece = orientation > 0.0 ? rank[(k + 1) % n] : rank[k];
          const Eigen::Vector2d g = gradientOf(k);
          for (std::size_t j = first_piece; j != end_piece; j = j + 1 == n ? 0 : j + 1) {
            const Eigen::Vector2d& direction = piece_direction[j];
            const bool inside = orientation > 0.0 ? cross(a, direction) > 0.0 && cross(direction, b) > 0.0
                                                  : cross(b, direction) > 0.0 && cross(direction, a) > 0.0;
            if (!inside) continue;
            const double value = g.dot(direction);
            if (value > piece_best[j]) {
              piece_best[j] = value;
              piece_winner[j] = static_cast<int>(k);
              piece_gradient[j] = g;
            }
          }
        }
        int previous_winner = -2;
        for (std::size_t j = 0; j < n; ++j) {
          const double from = angles[static_cast<std::size_t>(order[j])];
          double to = angles[static_cast<std::size_t>(order[(j + 1) % n])];
          if (j + 1 == n) to += 4.0;
          if (!(to - from > 1e-12)) continue;
          const int winner = piece_winner[j];
          Eigen::Vector2d best_gradient = winner >= 0 ? piece_gradient[j] : Eigen::Vector2d(0.0, 0.0);
          if (winner == previous_winner && winner >= 0) continue;  // same triangle continues
          previous_winner = winner;
          // No crossing at all (cannot happen for a closed boundary around the centre): nothing
          // in this sector is claimed.
          if (winner < 0) best_gradient = Eigen::Vector2d(INFINITY, INFINITY);
          const Eigen::Vector2d& start = relative[static_cast<std::size_t>(order[j])];
          chain_sectors.push_back({start, best_gradient});
        }
      }
      // The reference's s inside each boundary sector: its ray hit is decided by the direction
      // alone (which wall wins, which segment its walk settles on, or the straight line where
      // the walk gives up), so its gradient is piecewise constant in the angle and changes only
      // at the directions collected here -- through a wall's knots, through the points of the
      // straight wall where the walk starts on another segment, parallel to a segment -- or where
      // two walls' s cross (continuous there). Sample it just inside both ends of every piece
      // between those directions and bisect where the two samples differ.
      critical.clear();
      const Wall* cell_walls = level.walls.data() + cell.first_wall;
      // A wall's change of segment only matters where that wall can have the largest s: the
      // bounds of the reference's own pruning (the wobble keeps each wall's s within them).
      // 1 / (d + e) and 1 / (d - e) per wall (the latter +inf where d <= e: never pruned).
      const PackedWall* packed_walls = packed_[index].walls.data() + cell.first_wall;
      const auto addCritical = [&](const Eigen::Vector2d& direction, int wall_index) {
        double best_lower = 0.0;
        for (int j = 0; j < cell.wall_count; ++j)
          best_lower = std::max(best_lower, direction.dot(cell_walls[j].normal) * packed_walls[j].inverse_outer);
        const double along = direction.dot(cell_walls[wall_index].normal);
        if (!(along > 0.0)) return;  // the wall is behind: nothing of it can win here
        if (along * packed_walls[wall_index].inverse_inner < best_lower * (1.0 - 1e-9)) {
          // Cannot win here; kept aside in case a piece where the wall can win contains it.
          pruned.push_back({diamondAngle(direction.x(), direction.y()), wall_index});
          return;
        }
        critical.push_back({diamondAngle(direction.x(), direction.y()), direction.normalized(), wall_index});
      };
      pruned.clear();
      for (int k = 0; k < cell.wall_count; ++k) {
        // Where q . n changes sign the reference starts or stops casting to the wall at all.
        const Eigen::Vector2d& n = cell_walls[k].normal;
        pruned.push_back({diamondAngle(-n.y(), n.x()), k});
        pruned.push_back({diamondAngle(n.y(), -n.x()), k});
      }
      if (level.subdivisions > 0) {
        const int segments = 1 << level.subdivisions;
        for (int k = 0; k < cell.wall_count; ++k) {
          const Wall& wall = level.walls[static_cast<std::size_t>(cell.first_wall + k)];
          if (wall.wobble < 0 || !(wall.wobble_extent > 0.0)) continue;
          // The walk only runs while the straight hit is within a segment of the wall's ends.
          const Eigen::Vector2d window_from = wall.start - wall.tangent * (wall.length / segments) - cell.centre;
          const Eigen::Vector2d window_to = wall.start + wall.tangent * (wall.length * (segments + 1) / segments) - cell.centre;
          const double window_turn = cross(window_from, window_to);
          Eigen::Vector2d previous = wallPoint(level, wall, 0.0) - cell.centre;
          for (int knot = -1; knot <= segments + 1; ++knot) {
            addCritical(wall.start + wall.tangent * (wall.length * knot / segments) - cell.centre, k);
            if (knot < 0 || knot > segments) continue;
            const Eigen::Vector2d point = wallPoint(level, wall, static_cast<double>(knot) / segments) - cell.centre;
            addCritical(point, k);
            if (knot > 0) {
              Eigen::Vector2d along = point - previous;
              if (along.dot(wall.normal) < 0.0) along = -along;
              if (cross(window_from, along) * window_turn > 0.0 && cross(along, window_to) * window_turn > 0.0) addCritical(along, k);
            }
            previous = point;
          }
        }
      }
      std::sort(critical.begin(), critical.end(), [](const CriticalDirection& a, const CriticalDirection& b) { return a.angle < b.angle; });
      std::sort(pruned.begin(), pruned.end(), [](const PrunedDirection& a, const PrunedDirection& b) { return a.angle < b.angle; });
      // (Coincident directions stay: each names its wall; they make empty pieces, skipped.)
      cached = 0;
      cached_gradient.resize(static_cast<std::size_t>(cell.wall_count));
      cached_usable.resize(static_cast<std::size_t>(cell.wall_count));
      // Between consecutive critical directions every wall's decision (straight hit, or which
      // segment its walk settles on) is fixed, so each wall's s is g_k . q with one g_k, taken
      // from the wall's own ray hit at the piece's middle direction. The max over walls of those
      // linear functions changes winner only where two of them tie, g_a . d = g_b . d, i.e. d
      // perpendicular to g_a - g_b: walk the upper envelope from the piece's start, each time to
      // the first direction where another wall overtakes the current winner. (Walls are not
      // pruned here: the reference's pruning only drops walls that cannot win.)
      const double scale = 0.25 * level.spacing;
      // Walls that can win somewhere in the piece [lo, hi] (less than a half turn): a wall's s
      // lies within q . n / (d + e) and q . n / (d - e) (the wobble moves it by at most e), and
      // over the arc q . n is smallest at an end and largest at an end or at n itself.
      const auto candidatesIn = [&](const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const Eigen::Vector2d& direction) {
        double best_lower = 0.0;
        for (int k = 0; k < cell.wall_count; ++k) {
          const Wall& wall = cell_walls[k];
          best_lower = std::max(best_lower, std::min(lo.dot(wall.normal), hi.dot(wall.normal)) * packed_walls[k].inverse_outer);
        }
        std::uint64_t mask = 0;
        for (int k = 0; k < cell.wall_count; ++k) {
          const Wall& wall = cell_walls[k];
          if (!(direction.dot(wall.normal) > 0.0)) continue;
          // (normals are unit vectors)
          const double highest = cross(lo, wall.normal) > 0.0 && cross(wall.normal, hi) > 0.0 ? 1.0
                                                                                               : std::max(lo.dot(wall.normal), hi.dot(wall.normal));
          if (highest * packed_walls[k].inverse_inner < best_lower * (1.0 - 1e-9)) continue;
          mask |= std::uint64_t{1} << k;
        }
        return mask;
      };
      const auto gradientsAt = [&](const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const Eigen::Vector2d& direction) {
        candidate_gradients.clear();
        const Eigen::Vector2d q = scale * direction;
        // A sliver between two nearly equal critical directions has its middle within rounding
        // of one of them, where the decision may fall either way: evaluated afresh, not kept.
        const bool sliver = !(cross(lo, hi) > 1e-10);
        for (std::uint64_t mask = candidatesIn(lo, hi, direction); mask != 0; mask &= mask - 1) {
          const int k = __builtin_ctzll(mask);
          if ((cached >> k & 1) && !sliver) {
            if (cached_usable[static_cast<std::size_t>(k)]) candidate_gradients.push_back(cached_gradient[static_cast<std::size_t>(k)]);
            continue;
          }
          const Wall& wall = cell_walls[k];
          double s;
          Eigen::Vector2d gradient;
          wallRayHit(level, wall, q, s, gradient);
          // The reference's "s > best" never takes NaN.
          const bool usable = !std::isnan(s) && gradient.allFinite();
          if (!sliver) cached |= std::uint64_t{1} << k;
          cached_gradient[static_cast<std::size_t>(k)] = gradient;
          cached_usable[static_cast<std::size_t>(k)] = usable;
          if (usable) candidate_gradients.push_back(gradient);
        }
      };
      // Calls emit_at(start, gradient) for every sector of the envelope over [lo, hi] (unit
      // directions, counter-clockwise, less than a half turn apart), the first at lo.
      const auto envelope = [&](const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, auto&& emit_at) {
        gradientsAt(lo, hi, (lo + hi).normalized());
        const std::size_t count = candidate_gradients.size();
        if (count == 0) {
          emit_at(lo, Eigen::Vector2d(0.0, 0.0));  // no wall ahead: s = 0, as in the reference
          return;
        }
        // The winner just after a direction: the largest value a hair further counter-clockwise
        // (exact ties at polygon corners would otherwise be decided by rounding).
        constexpr double kNudge = 1e-12;  // radians; at a cell's radius far below a pixel
        const auto winnerAfter = [&](const Eigen::Vector2d& direction) {
          const Eigen::Vector2d probe(direction.x() - kNudge * direction.y(), direction.y() + kNudge * direction.x());
          std::size_t winner = 0;
          for (std::size_t j = 1; j < count; ++j)
            if (candidate_gradients[j].dot(probe) > candidate_gradients[winner].dot(probe)) winner = j;
          return winner;
        };
        std::size_t winner = winnerAfter(lo);
        emit_at(lo, candidate_gradients[winner]);
        Eigen::Vector2d current = lo;
        for (std::size_t guard = 0; guard < 4 * count + 4; ++guard) {
          std::size_t next = count;
          Eigen::Vector2d best_tie(0.0, 0.0);
          for (std::size_t j = 0; j < count; ++j) {
            if (j == winner) continue;
            const Eigen::Vector2d difference = candidate_gradients[j] - candidate_gradients[winner];
            // The direction where j overtakes: difference . tie = 0, growing counter-clockwise.
            const Eigen::Vector2d tie = Eigen::Vector2d(difference.y(), -difference.x());
            const double length = tie.norm();
            if (!(length > 0.0)) continue;
            if (!(cross(current, tie) > 2.0 * kNudge * length && cross(tie, hi) > 2.0 * kNudge * length)) continue;
            if (next == count || cross(tie, best_tie) > 0.0) {
              next = j;
              best_tie = tie;
            }
          }
          if (next == count) break;
          current = best_tie.normalized();
          winner = winnerAfter(current);
          emit_at(current, candidate_gradients[winner]);
        }
      };
      const std::size_t chain_count = chain_sectors.size();
      // The walk goes round once counter-clockwise from the first sector's start; pseudo-angles
      // along it are unwrapped (+4 per turn) to compare with the set-aside directions.
      double unwrap = 0.0, previous_from = -1.0, pruned_cycle = 0.0;
      std::size_t pruned_index = 0;
      const auto advancePruned = [&]() {
        if (++pruned_index == pruned.size()) {
          pruned_index = 0;
          pruned_cycle += 4.0;
        }
      };
      for (std::size_t k = 0; k < chain_count && chain_count >= 3; ++k) {
        const ChainSector& sector = chain_sectors[k];
        const Eigen::Vector2d from_direction = sector.direction.normalized();
        const Eigen::Vector2d to_direction = chain_sectors[(k + 1) % chain_count].direction.normalized();
        // Pseudo-angles (diamondAngle, period 4) order the directions.
        const double from = diamondAngle(from_direction.x(), from_direction.y());
        double to = diamondAngle(to_direction.x(), to_direction.y());
        while (to <= from) to += 4.0;
        if (k == 0) {
          pruned_index = static_cast<std::size_t>(
              std::lower_bound(pruned.begin(), pruned.end(), from, [](const PrunedDirection& entry, double value) { return entry.angle < value; }) -
              pruned.begin());
          if (pruned_index == pruned.size()) {
            pruned_index = 0;
            pruned_cycle = 4.0;
          }
        } else if (from < previous_from) {
          unwrap += 4.0;
        }
        previous_from = from;
        // Pieces of the sector between the critical directions (which may wrap past 4), none
        // wider than a quarter of the pseudo-angle period's half (so less than a half turn).
        pieces.clear();
        pieces.push_back({from, from_direction, -1});
        const auto pushUpTo = [&](double angle, const Eigen::Vector2d& direction, int wall) {
          const double previous = pieces.back().angle;
          const int extra = static_cast<int>(std::ceil((angle - previous) / 0.5)) - 1;
          for (int e = 1; e <= extra; ++e) {
            const double a = previous + (angle - previous) * e / (extra + 1);
            pieces.push_back({a, diamondDirection(a), -1});
          }
          pieces.push_back({angle, direction, wall});
        };
        // critical is sorted in [0, 4); from is in [0, 4) and to < from + 4. Those within 1e-12
        // of the sector's start make no piece but still end their wall's cached gradient (the
        // previous sector stopped 1e-13 short of them).
        for (int turn = 0; turn < 2; ++turn) {
          const double low = from - 1e-12 - turn * 4.0, high = to - 1e-13 - turn * 4.0;
          auto it = std::upper_bound(critical.begin(), critical.end(), low,
                                     [](double value, const CriticalDirection& entry) { return value < entry.angle; });
          for (; it != critical.end() && it->angle < high; ++it) {
            if (it->angle + turn * 4.0 <= from + 1e-13) {
              cached &= ~(std::uint64_t{1} << it->wall);
            } else {
              pushUpTo(it->angle + turn * 4.0, it->direction, it->wall);
            }
          }
        }
        pushUpTo(to, to_direction, -1);
        Eigen::Vector2d carried(0.0, 0.0);
        bool started = false;
        const auto emit_at = [&](const Eigen::Vector2d& start, const Eigen::Vector2d& gradient) {
          // Where the winning wall segment is the boundary's own edge the two gradients are the
          // same up to rounding (the ray hit's formula and the fan triangle's 2x2 solve): store
          // the ray hit's for both, so render's test "inside the boundary" is its "s < 1".
          const Eigen::Vector2d boundary =
              (sector.boundary - gradient).squaredNorm() <= 1e-24 * gradient.squaredNorm() ? gradient : sector.boundary;
          if (!started) {
            out.sectors.push_back({sector.direction.x(), sector.direction.y(), gradient.x(), gradient.y(), boundary.x(), boundary.y(), 0.0, 0.0});
            started = true;
          } else if (!sameGradient(gradient, carried)) {
            out.sectors.push_back({start.x(), start.y(), gradient.x(), gradient.y(), boundary.x(), boundary.y(), 0.0, 0.0});
          }
          carried = gradient;
        };
        for (std::size_t piece = 0; piece + 1 < pieces.size(); ++piece) {
          const Eigen::Vector2d& lo = pieces[piece].direction;
          const Eigen::Vector2d& hi = pieces[piece + 1].direction;
          if (pieces[piece].wall >= 0) cached &= ~(std::uint64_t{1} << pieces[piece].wall);
          if (!(cross(lo, hi) > 0.0)) continue;  // coincident directions
          // A wall that can win somewhere in the piece must keep one decision over all of it:
          // split at its directions set aside above (where it could not win) inside the piece.
          splits.clear();
          // Those in [a0, a1) (one exactly on a piece boundary only ends its wall's cached
          // gradient), by a pointer that goes round the sorted list once with the walk.
          const double a0 = pieces[piece].angle + unwrap, a1 = pieces[piece + 1].angle + unwrap;
          if (!pruned.empty()) {
            while (pruned[pruned_index].angle + pruned_cycle < a0) advancePruned();
            for (int guard = 0; guard < static_cast<int>(pruned.size()) && pruned[pruned_index].angle + pruned_cycle < a1; ++guard) {
              splits.push_back({pruned[pruned_index].angle + pruned_cycle - unwrap, pruned[pruned_index].wall});
              advancePruned();
            }
          }
          std::uint64_t mask = 0;
          if (!splits.empty()) mask = candidatesIn(lo, hi, (lo + hi).normalized());
          // Walls that cannot win in this piece are not evaluated in it: their changes here
          // apply from its start.
          for (const PrunedDirection& split : splits)
            if (!(mask >> split.wall & 1)) cached &= ~(std::uint64_t{1} << split.wall);
          Eigen::Vector2d from_direction_piece = lo;
          for (const PrunedDirection& split : splits) {
            if (!(mask >> split.wall & 1)) continue;
            const Eigen::Vector2d at = diamondDirection(split.angle);
            if (cross(from_direction_piece, at) > 0.0 && cross(at, hi) > 0.0) {
              envelope(from_direction_piece, at, emit_at);
              from_direction_piece = at;
            }
            cached &= ~(std::uint64_t{1} << split.wall);
          }
          envelope(from_direction_piece, hi, emit_at);
        }
      }
      raster.sector_count = static_cast<int>(out.sectors.size()) - raster.first_sector;
      // The row walk needs every sector narrower than a half turn (the centre strictly inside).
      for (int k = 0; k < raster.sector_count; ++k) {
        const RasterSector& a = out.sectors[static_cast<std::size_t>(raster.first_sector + k)];
        const RasterSector& b = out.sectors[static_cast<std::size_t>(raster.first_sector + (k + 1) % raster.sector_count)];
        if (!(a.direction_x * b.direction_y - a.direction_y * b.direction_x > 0.0)) raster.sector_count = 0;
      }
      if (raster.sector_count < 3) {
        out.sectors.resize(static_cast<std::size_t>(raster.first_sector));
        raster.sector_count = 0;  // left to the per-pixel path
      }
      for (int k = 0; k < raster.sector_count; ++k) {
        // Where a pixel row leaves a sector, as qx / dy of the ray it leaves through: the
        // sector's start ray clockwise (above the centre), the next one's counter-clockwise.
        RasterSector& sector = out.sectors[static_cast<std::size_t>(raster.first_sector + k)];
        const RasterSector& next = out.sectors[static_cast<std::size_t>(raster.first_sector + (k + 1) % raster.sector_count)];
        constexpr double never = std::numeric_limits<double>::quiet_NaN();
        sector.crossing_above = sector.direction_y > 0.0 ? sector.direction_x / sector.direction_y : never;
        sector.crossing_below = next.direction_y < 0.0 ? next.direction_x / next.direction_y : never;
      }
      raster.first_vertex = static_cast<int>(out.vertices.size());
      raster.vertex_count = raster.sector_count > 0 ? static_cast<int>(relative.size()) : 0;
      if (raster.sector_count > 0) out.vertices.insert(out.vertices.end(), relative.begin(), relative.end());
      out.most_sectors = std::max(out.most_sectors, raster.sector_count);
      out.cells.push_back(raster);
    }
  }
  if (!raster_ready_) raster_.clear();
}

ReliefMap SkinRelief::renderRaster(int width, int height, int only_level) const {
  ReliefMap map(width, height);  // first: it names a bad size
  const int first = only_level >= 0 ? only_level : 0;
  const int end = only_level >= 0 ? only_level + 1 : levelCount();
  // The map is rendered in bands of rows, every level of a band before the next band. Level by
  // level over the whole map, each level met its ~20 bytes per pixel of scratch and output long
  // evicted from L2 by the level before, a few pixels per row per cell (at 1024^2 the bands took
  // about 7 of 57 ms off). A band's scratch and output stay in L2.
  // Each pixel still sees the same cells in the same order (levels in turn, cells in index
  // order), so the map is the same. (A cell across the tile's top edge now walks its rows from
  // the wrapped part on; the row walk ends in the one sector holding the row's first pixel
  // whichever sector it starts from -- unless that pixel is exactly the centre, as before.)
  constexpr int kBandRows = 16;
  const int band_count = (height + kBandRows - 1) / kBandRows;
  const std::size_t band_capacity = static_cast<std::size_t>(kBandRows) * static_cast<std::size_t>(width);
  // Scratch kept per thread between calls (fresh pages cost page faults and zeroing).
  // The band's height and slopes, summed in double like the reference and rounded once into the
  // map at the band's end (summed in the map's floats, each band's slopes came back from L3 --
  // the map is 12 MB at 1024^2 -- and were rounded at every level).
  thread_local std::vector<double> heights, slopes_u, slopes_v;
  // One owner per pixel of the band, overwritten level by level: cell + code_base of its level,
  // so a child claims a pixel exactly when it still holds its parent's code (-1: nobody's yet).
  thread_local std::vector<int> owner;
  thread_local std::vector<double> span_low, span_high, vertex_rows;
  // One row of one cell (the band loop): its pixels' sectors as runs, and 1 at each column
  // (from the row's first) where a run ends.
  struct RowRun {
    double gradient_x, gradient_y, gradient_dy;  // s = gradient_x * qx + gradient_dy
    double boundary_x, boundary_dy;              // inside the boundary: boundary_x * qx + boundary_dy < 1
  };
  thread_local std::vector<RowRun> run_buffer;
  thread_local std::vector<int> run_end_buffer;
  // Per level and cell: its rows (unwrapped) and where their column ranges start in `spans`;
  // `sector` carries the row walk's sector from one band to the next.
  struct CellRows {
    int row_first = 0, row_last = -1;
    std::size_t first_span = 0;
    int sector = 0;
  };
  struct LevelRows {
    std::vector<CellRows> cells;
    std::vector<int> spans;  // first and last column per row; first > last: no pixel centre
    std::vector<int> band_start;  // band b's cells: band_cells[band_start[b] .. band_start[b + 1])
    std::vector<int> band_cells;  // in index order within each band
  };
  thread_local std::vector<LevelRows> level_rows;
  thread_local std::vector<int> cell_bands, band_fill;
  if (level_rows.size() < static_cast<std::size_t>(end)) level_rows.resize(static_cast<std::size_t>(end));
  for (int level_index = 0; level_index < end; ++level_index) {
    const RasterLevel& level = raster_[static_cast<std::size_t>(level_index)];
    LevelRows& rows_out = level_rows[static_cast<std::size_t>(level_index)];
    rows_out.cells.assign(level.cells.size(), CellRows());
    rows_out.spans.clear();
    rows_out.band_start.assign(static_cast<std::size_t>(band_count) + 1, 0);
    cell_bands.clear();  // (band, cell) pairs in cell order
    for (std::size_t cell_index = 0; cell_index < level.cells.size(); ++cell_index) {
      const RasterCell& cell = level.cells[cell_index];
      if (cell.sector_count == 0) continue;
      // Rows of pixel centres (row + 0.5) / height inside the boundary's extent, unwrapped (the
      // cell's frame); per row the columns between the boundary's outermost crossings.
      const int row_first = static_cast<int>(std::ceil(cell.low_y * height - 0.5));
      const int row_last = static_cast<int>(std::floor(cell.high_y * height - 0.5));
      if (row_last < row_first) continue;
      CellRows& cell_rows = rows_out.cells[cell_index];
      cell_rows.row_first = row_first;
      cell_rows.row_last = row_last;
      cell_rows.first_span = rows_out.spans.size();
      const std::size_t rows = static_cast<std::size_t>(row_last - row_first + 1);
      span_low.assign(rows, INFINITY);
      span_high.assign(rows, -INFINITY);
      const Eigen::Vector2d* vertices = level.vertices.data() + cell.first_vertex;
      // Each vertex's pixel-space row coordinate once, not once per edge it ends.
      vertex_rows.resize(static_cast<std::size_t>(cell.vertex_count));
      for (int k = 0; k < cell.vertex_count; ++k) vertex_rows[static_cast<std::size_t>(k)] = (cell.centre_y + vertices[k].y()) * height - 0.5;
      for (int k = 0; k < cell.vertex_count; ++k) {
        const int k_next = k + 1 == cell.vertex_count ? 0 : k + 1;
        const Eigen::Vector2d& a = vertices[k];
        const Eigen::Vector2d& b = vertices[k_next];
        // Pixel-space rows (y * height - 0.5) crossed by the edge, as in the row loop below.
        const double ya = vertex_rows[static_cast<std::size_t>(k)], yb = vertex_rows[static_cast<std::size_t>(k_next)];
        const double y_low = std::min(ya, yb), y_high = std::max(ya, yb);
        // Most edges cross no row, so this runs for nearly every edge of every cell: the same
        // integers as std::ceil / std::floor (finite values within a few tiles' rows) without
        // the rounding sequences those compile to on baseline x86-64 (SSE2 has no roundsd).
        const int truncated_low = static_cast<int>(y_low), truncated_high = static_cast<int>(y_high);
        const int edge_first = std::max(row_first, truncated_low + (truncated_low < y_low ? 1 : 0));
        const int edge_last = std::min(row_last, truncated_high - (truncated_high > y_high ? 1 : 0));
        if (edge_last < edge_first) continue;
        const double xa = (cell.centre_x + a.x()) * width - 0.5, xb = (cell.centre_x + b.x()) * width - 0.5;
        const double slope = (xb - xa) / (yb - ya);
        for (int row = edge_first; row <= edge_last; ++row) {
          const double x = xa + (row - ya) * slope;
          const auto slot = static_cast<std::size_t>(row - row_first);
          span_low[slot] = std::min(span_low[slot], x);
          span_high[slot] = std::max(span_high[slot], x);
        }
      }
      rows_out.spans.resize(cell_rows.first_span + 2 * rows);
      int* span = rows_out.spans.data() + cell_rows.first_span;
      for (std::size_t slot = 0; slot < rows; ++slot, span += 2) {
        if (!(span_low[slot] <= span_high[slot])) {
          // No boundary crossing, so no pixel of this cell: the row loop skips it.
          span[0] = std::numeric_limits<int>::max();
          span[1] = std::numeric_limits<int>::min();
          continue;
        }
        // Pixel centres within the row's outermost boundary crossings. One rounded the other
        // way from the ownership test is claimed by no cell here and so takes the per-pixel path.
        // (Integer ceil / floor as above.)
        const int truncated_low = static_cast<int>(span_low[slot]), truncated_high = static_cast<int>(span_high[slot]);
        span[0] = truncated_low + (truncated_low < span_low[slot] ? 1 : 0);
        span[1] = truncated_high - (truncated_high > span_high[slot] ? 1 : 0);
      }
      // The bands the cell's rows fall in, wrapped into the tile (rows are fewer than the
      // tile's, so each wrapped row comes from one unwrapped row).
      const std::size_t pairs_before = cell_bands.size();
      for (int wrap = -1; wrap <= 1; ++wrap) {
        const int low = std::max(row_first, wrap * height), high = std::min(row_last, wrap * height + height - 1);
        if (low > high) continue;
        for (int band = (low - wrap * height) / kBandRows; band <= (high - wrap * height) / kBandRows; ++band) {
          bool seen = false;
          for (std::size_t at = pairs_before; at < cell_bands.size(); at += 2) seen = seen || cell_bands[at] == band;
          if (seen) continue;
          cell_bands.push_back(band);
          cell_bands.push_back(static_cast<int>(cell_index));
          ++rows_out.band_start[static_cast<std::size_t>(band) + 1];
        }
      }
    }
    for (int band = 0; band < band_count; ++band)
      rows_out.band_start[static_cast<std::size_t>(band) + 1] += rows_out.band_start[static_cast<std::size_t>(band)];
    rows_out.band_cells.resize(cell_bands.size() / 2);
    band_fill.assign(rows_out.band_start.begin(), rows_out.band_start.end() - 1);
    for (std::size_t at = 0; at < cell_bands.size(); at += 2)
      rows_out.band_cells[static_cast<std::size_t>(band_fill[static_cast<std::size_t>(cell_bands[at])]++)] = cell_bands[at + 1];
  }
  if (heights.size() < band_capacity) heights.resize(band_capacity);
  if (slopes_u.size() < band_capacity) slopes_u.resize(band_capacity);
  if (slopes_v.size() < band_capacity) slopes_v.resize(band_capacity);
  if (owner.size() < band_capacity) owner.resize(band_capacity);
  std::size_t most_sectors = 0;
  for (int level_index = 0; level_index < end; ++level_index)
    most_sectors = std::max(most_sectors, static_cast<std::size_t>(raster_[static_cast<std::size_t>(level_index)].most_sectors));
  if (run_buffer.size() < most_sectors + 1) run_buffer.resize(most_sectors + 1);
  // Rows are narrower than the tile; zero between rows (each row clears what it marked).
  run_end_buffer.assign(static_cast<std::size_t>(width) + 2, 0);
  RowRun* const runs = run_buffer.data();
  int* const run_ends = run_end_buffer.data();
  const double inverse_width = 1.0 / width, inverse_height = 1.0 / height;
  FastCache unclaimed_cache;
  const double profile_last = profile_table_.last();
  const double* profile_lines = profile_lines_.data();
  for (int band = 0; band < band_count; ++band) {
    const int band_first = band * kBandRows, band_last = std::min(height, band_first + kBandRows) - 1;
    const std::size_t band_base = static_cast<std::size_t>(band_first) * static_cast<std::size_t>(width);
    const std::size_t band_pixels = static_cast<std::size_t>(band_last - band_first + 1) * static_cast<std::size_t>(width);
    std::fill(heights.begin(), heights.begin() + static_cast<std::ptrdiff_t>(band_pixels), 0.0);
    std::fill(slopes_u.begin(), slopes_u.begin() + static_cast<std::ptrdiff_t>(band_pixels), 0.0);
    std::fill(slopes_v.begin(), slopes_v.begin() + static_cast<std::ptrdiff_t>(band_pixels), 0.0);
    std::fill(owner.begin(), owner.begin() + static_cast<std::ptrdiff_t>(band_pixels), -1);
    int code_base = 0, parent_code_base = -1;
    for (int level_index = 0; level_index < end; ++level_index) {
      const RasterLevel& level = raster_[static_cast<std::size_t>(level_index)];
      LevelRows& rows_in = level_rows[static_cast<std::size_t>(level_index)];
      const bool accumulate = level_index >= first;
      const double depth = level.depth;
      const bool masked = level_index > 0;
      double* slope_u = slopes_u.data();
      double* slope_v = slopes_v.data();
      int* owners = owner.data();
      double* sums = heights.data();
      const int* band_cells = rows_in.band_cells.data();
      for (int listed = rows_in.band_start[static_cast<std::size_t>(band)]; listed < rows_in.band_start[static_cast<std::size_t>(band) + 1];
           ++listed) {
        const auto cell_index = static_cast<std::size_t>(band_cells[listed]);
        const RasterCell& cell = level.cells[cell_index];
        CellRows& cell_rows = rows_in.cells[cell_index];
        const int sector_count = cell.sector_count;
        const RasterSector* sectors = level.sectors.data() + cell.first_sector;
        const int code = static_cast<int>(cell_index) + code_base;
        const int expected = masked ? cell.parent + parent_code_base : -1;
        int sector = cell_rows.sector;
        for (int wrap = -1; wrap <= 1; ++wrap) {
          const int row_low = std::max(cell_rows.row_first, band_first + wrap * height);
          const int row_high = std::min(cell_rows.row_last, band_last + wrap * height);
          for (int row = row_low; row <= row_high; ++row) {
            const int* span = rows_in.spans.data() + cell_rows.first_span + 2 * static_cast<std::size_t>(row - cell_rows.row_first);
            if (span[0] == std::numeric_limits<int>::max()) continue;
            const int column_first = span[0];
            const int column_last = span[1];
            const std::size_t row_base = static_cast<std::size_t>(row - wrap * height - band_first) * static_cast<std::size_t>(width);
            const double dy = (row + 0.5) * inverse_height - cell.centre_y;
            // Sector of the row's first pixel: walk from the previous row's.
            const double qx_first = (column_first + 0.5) * inverse_width - cell.centre_x;
            for (int step = 0; step < 2 * sector_count; ++step) {
              const RasterSector& a = sectors[sector];
              const RasterSector& b = sectors[sector + 1 == sector_count ? 0 : sector + 1];
              if (a.direction_x * dy - a.direction_y * qx_first < 0.0) {
                sector = sector == 0 ? sector_count - 1 : sector - 1;
              } else if (b.direction_x * dy - b.direction_y * qx_first >= 0.0) {
                sector = sector + 1 == sector_count ? 0 : sector + 1;
              } else {
                break;
              }
            }
            // Unwrapped columns map to row_base + column + shift; the shift drops by width from
            // wrap_column on, where the row crosses the tile's right edge (rows are narrower than
            // the tile). Cells lie within a tile's width of the tile, so mostly no integer
            // division is needed.
            int column_wrapped_first = column_first;
            if (column_wrapped_first < 0) column_wrapped_first += width;
            if (column_wrapped_first >= width) column_wrapped_first -= width;
            if (column_wrapped_first < 0 || column_wrapped_first >= width) column_wrapped_first = ((column_first % width) + width) % width;
            const int wrap_column = column_first + (width - column_wrapped_first);
            const double column_offset = cell.centre_x * width - 0.5;
            // Two passes over the row, so that no branch depends on how many of its pixels a
            // sector holds (at 1024^2 a third of the finest level's sectors hold none of a row's
            // and most of the rest one or two; loops per sector mispredicted about once a sector).
            // 1. Walk the sectors the row crosses, in order (it leaves each through one ray),
            //    keeping one run per sector that holds a pixel -- written unconditionally, the
            //    count advanced by a comparison -- and marking the column after each run's last.
            //    The column where the row leaves a sector is clamped and floored without looking
            //    at the previous sector's, so from one sector to the next only an integer max
            //    depends on the last (not a chain of double <-> int conversions).
            const bool above = dy >= 0.0;
            const double dy_columns = dy * width;
            const double before_row = column_first - 1.0;
            int k = sector, column = column_first, run_count = 0;
            for (int visited = 0; visited < sector_count; ++visited) {
              const RasterSector& here = sectors[k];
              // Column where the row leaves the sector (NaN: it never does).
              const double edge = dy_columns * (above ? here.crossing_above : here.crossing_below) + column_offset;
              const double bounded = std::max(edge < column_last ? edge : static_cast<double>(column_last), before_row);
              const int truncated = static_cast<int>(bounded);
              const int last = std::max(truncated - (bounded < truncated ? 1 : 0), column - 1);
              RowRun& run = runs[run_count];
              run.gradient_x = here.gradient_x;
              run.gradient_y = here.gradient_y;
              run.gradient_dy = here.gradient_y * dy;
              run.boundary_x = here.boundary_x;
              run.boundary_dy = here.boundary_y * dy;
              run_count += last >= column ? 1 : 0;
              run_ends[last + 1 - column_first] = 1;
              column = last + 1;
              if (column > column_last) break;
              // Moving right turns the direction clockwise above the centre (out through the
              // sector's start ray) and counter-clockwise below it (through the next start ray).
              k = above ? (k == 0 ? sector_count : k) - 1 : (k + 1 == sector_count ? 0 : k + 1);
            }
            // Pixels past the last sector visited (a row the walk could not finish): nobody's.
            runs[run_count] = {0.0, 0.0, 0.0, 0.0, INFINITY};
            // 2. The pixels, each in the run the marks before it count to.
            const std::ptrdiff_t shift = static_cast<std::ptrdiff_t>(row_base) + (column_wrapped_first - column_first);
            const int span_width = column_last - column_first + 1;
            run_ends[0] = 0;  // an empty first sector's mark
            int run_index = 0;
            for (int at_column = 0; at_column < span_width; ++at_column) {
              run_index += run_ends[at_column];
              run_ends[at_column] = 0;
              const RowRun& run = runs[run_index];
              const int pixel_column = column_first + at_column;
              const double qx = (pixel_column + 0.5) * inverse_width - cell.centre_x;
              const std::ptrdiff_t at = shift + pixel_column - (pixel_column >= wrap_column ? width : 0);
              // The usual sector has the winning wall's own segment as its boundary: then
              // boundary == gradient and this is s, with the same operations.
              if (!(run.boundary_x * qx + run.boundary_dy < 1.0) || owners[at] != expected) continue;  // outside, taken, another parent's
              owners[at] = code;
              const double s = run.gradient_x * qx + run.gradient_dy;
              if (!accumulate || !(s < 1.0)) continue;  // on or past the furrow line: height 0, flat
              // profile_table_.evaluate(1 - s) with s < 1 (so the position is in (0, last]).
              const double position = std::min(1.0 - s, 1.0) * profile_last;
              const double* line = profile_lines + 4 * static_cast<int>(position);
              sums[at] += depth * (line[0] + position * line[1]);
              const double factor = depth * (line[2] + position * line[3]);
              slope_u[at] -= factor * run.gradient_x;
              slope_v[at] -= factor * run.gradient_y;
            }
            run_ends[span_width] = 0;
          }
        }
        cell_rows.sector = sector;
      }
      // What no cell claimed goes through the per-pixel path (same model as the reference).
      int cells_out[3] = {-1, -1, -1};
      // Unclaimed pixels come in short runs (slivers along a junction, a fold's pocket): the
      // per-pixel path's cache of the last straight cells finds most of them without a search
      // (its answers do not depend on it).
      for (std::size_t block = 0; block < band_pixels; block += 64) {
        // Blocks of 64 owners, tested with a vectorisable "any below": nearly all are claimed.
        const std::size_t block_end = std::min(block + 64, band_pixels);
        int unclaimed = 0;
        for (std::size_t at = block; at < block_end; ++at) unclaimed |= static_cast<int>(owners[at] < code_base);
        if (unclaimed == 0) continue;
        for (std::size_t at = block; at < block_end; ++at) {
          if (owners[at] >= code_base) continue;
          const std::size_t pixel = band_base + at;
          const int row = static_cast<int>(pixel / static_cast<std::size_t>(width));
          const int column = static_cast<int>(pixel - static_cast<std::size_t>(row) * static_cast<std::size_t>(width));
          const ReliefSample sample = evaluateFast((column + 0.5) * inverse_width, (row + 0.5) * inverse_height,
                                                   accumulate ? level_index : level_index + 1, level_index + 1, &unclaimed_cache, cells_out);
          owners[at] = cells_out[level_index] + code_base;
          sums[at] += sample.height;
          slope_u[at] += sample.slope.x();
          slope_v[at] += sample.slope.y();
        }
      }
      parent_code_base = code_base;
      code_base += static_cast<int>(level.cells.size());
    }
    for (std::size_t at = 0; at < band_pixels; ++at) {
      map.heights[band_base + at] = static_cast<float>(heights[at]);
      map.slope_u[band_base + at] = static_cast<float>(slopes_u[at]);
      map.slope_v[band_base + at] = static_cast<float>(slopes_v[at]);
    }
  }
  return map;
}

}  // namespace dressed_human
