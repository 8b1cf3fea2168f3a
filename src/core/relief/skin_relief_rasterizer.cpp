// SkinReliefRasterizer (skin_relief_rasterizer.h), construction: for polygonal contours
// (roundness 0) each cell is rasterised from its centre as angular sectors, instead of searching
// the cell of every pixel.
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
// where two tie, d perpendicular to g_a - g_b (SectorBuilder::envelope walks that upper envelope).
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
#include "dressed_human/core/relief/skin_relief_rasterizer.h"

#include "dressed_human/core/relief/skin_cell_boundary.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace dressed_human {

using skin_detail::BoundarySector;
using skin_detail::Cell;
using skin_detail::CellLevel;
using skin_detail::cross;
using skin_detail::diamondAngle;
using skin_detail::diamondDirection;
using skin_detail::RasterCell;
using skin_detail::RasterLevel;
using skin_detail::RasterSector;
using skin_detail::Wall;
using skin_detail::wallPoint;

namespace {

// Exact comparison (the same wall segment gives the same bits); NaN, from a degenerate wall,
// counts as equal to itself so the bisection below does not chase it.
bool sameGradient(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  return same(a.x(), b.x()) && same(a.y(), b.y());
}

struct CriticalDirection {
  double angle;               // diamondAngle, in [0, 4)
  Eigen::Vector2d direction;  // unit
  int wall;                   // whose decision can change here (-1: none, a piece boundary only)
};

struct PrunedDirection {
  double angle;  // diamondAngle, in [0, 4)
  int wall;
};

// Appends a boundary sector's sectors of the reference's s; a new one only where the gradient
// changes.
struct SectorEmitter {
  const BoundarySector& sector;
  std::vector<RasterSector>& sectors;
  Eigen::Vector2d carried = Eigen::Vector2d(0.0, 0.0);
  bool started = false;

  void operator()(const Eigen::Vector2d& start, const Eigen::Vector2d& gradient) {
    // Where the winning wall segment is the boundary's own edge the two gradients are the
    // same up to rounding (the ray hit's formula and the fan triangle's 2x2 solve): store
    // the ray hit's for both, so render's test "inside the boundary" is its "s < 1".
    const Eigen::Vector2d boundary =
        (sector.boundary - gradient).squaredNorm() <= 1e-24 * gradient.squaredNorm() ? gradient : sector.boundary;
    if (!started) {
      sectors.push_back({sector.direction.x(), sector.direction.y(), gradient.x(), gradient.y(), boundary.x(),
                         boundary.y(), 0.0, 0.0});
      started = true;
    } else if (!sameGradient(gradient, carried)) {
      sectors.push_back({start.x(), start.y(), gradient.x(), gradient.y(), boundary.x(), boundary.y(), 0.0, 0.0});
    }
    carried = gradient;
  }
};

// Builds the cells' sectors one after another; its vectors are scratch kept from cell to cell.
class SectorBuilder {
 public:
  explicit SectorBuilder(const std::vector<CellLevel>& levels) : levels_(levels) {}

  // Appends the cell to `out`; false when the cell is wider than the tile (it would meet its own
  // periodic image in the row loop).
  bool addCell(std::size_t level_index, const Cell& cell, RasterLevel& out);

 private:
  void collectCriticalDirections();
  void addCritical(const Eigen::Vector2d& direction, int wall_index);
  std::uint64_t candidatesIn(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                             const Eigen::Vector2d& direction) const;
  void gradientsAt(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const Eigen::Vector2d& direction);
  void envelope(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, SectorEmitter& emit_at);
  void walkBoundarySectors(RasterLevel& out);
  void splitIntoPieces(double from, double to, const Eigen::Vector2d& from_direction,
                       const Eigen::Vector2d& to_direction);
  void pushUpTo(double angle, const Eigen::Vector2d& direction, int wall);
  void walkPiece(std::size_t piece, SectorEmitter& emit_at);
  void advancePruned();
  void finishCell(RasterCell& raster, RasterLevel& out) const;

  const std::vector<CellLevel>& levels_;
  // The cell being built.
  const CellLevel* level_ = nullptr;
  const Cell* cell_ = nullptr;
  const Wall* cell_walls_ = nullptr;
  // Per wall 1 / (d + e) and 1 / (d - e) (the latter +inf where d <= e: never pruned).
  std::vector<double> inverse_outer_, inverse_inner_;
  std::vector<Eigen::Vector2d> relative_;  // boundary vertices from the centre
  std::vector<BoundarySector> chain_sectors_;
  std::vector<CriticalDirection> critical_, pieces_;
  std::vector<PrunedDirection> pruned_, splits_;
  std::vector<Eigen::Vector2d> candidate_gradients_;
  // Per wall of the current cell, its gradient at the last piece evaluated, valid until the walk
  // passes one of that wall's critical directions (the wall's decision is fixed in between).
  std::vector<Eigen::Vector2d> cached_gradient_;
  std::vector<char> cached_usable_;
  std::uint64_t cached_ = 0;
  double scale_ = 0.0;
  // The walk round the boundary: pseudo-angles along it are unwrapped (+4 per turn) to compare
  // with the set-aside directions, found by one pointer going round with the walk.
  double unwrap_ = 0.0, pruned_cycle_ = 0.0;
  std::size_t pruned_index_ = 0;
  skin_detail::BoundaryFanScratch fan_scratch_;
};

bool SectorBuilder::addCell(std::size_t level_index, const Cell& cell, RasterLevel& out) {
  level_ = &levels_[level_index];
  cell_ = &cell;
  cell_walls_ = level_->walls.data() + cell.first_wall;
  RasterCell raster;
  raster.centre_x = cell.centre.x();
  raster.centre_y = cell.centre.y();
  raster.parent = cell.parent;
  raster.first_sector = static_cast<int>(out.sectors.size());
  const std::vector<Eigen::Vector2d> chain = skin_detail::boundaryChain(levels_, level_index, cell);
  relative_.clear();
  Eigen::Vector2d low = chain.front(), high = chain.front();
  for (const Eigen::Vector2d& vertex : chain) {
    low = low.cwiseMin(vertex);
    high = high.cwiseMax(vertex);
    const Eigen::Vector2d r = vertex - cell.centre;
    if (relative_.empty() || (r - relative_.back()).squaredNorm() > 1e-30) relative_.push_back(r);
  }
  while (relative_.size() > 1 && (relative_.front() - relative_.back()).squaredNorm() <= 1e-30) relative_.pop_back();
  raster.low_x = low.x();
  raster.low_y = low.y();
  raster.high_x = high.x();
  raster.high_y = high.y();
  const bool fits = !(high.x() - low.x() >= 1.0 || high.y() - low.y() >= 1.0);
  skin_detail::boundaryFan(relative_, chain_sectors_, fan_scratch_);
  collectCriticalDirections();
  walkBoundarySectors(out);
  finishCell(raster, out);
  return fits;
}

// The reference's s inside each boundary sector: its ray hit is decided by the direction alone
// (which wall wins, which segment its walk settles on, or the straight line where the walk gives
// up), so its gradient is piecewise constant in the angle and changes only at the directions
// collected here -- through a wall's knots, through the points of the straight wall where the
// walk starts on another segment, parallel to a segment -- or where two walls' s cross
// (continuous there; walkPiece finds those).
void SectorBuilder::collectCriticalDirections() {
  const CellLevel& level = *level_;
  const Cell& cell = *cell_;
  critical_.clear();
  // A wall's change of segment only matters where that wall can have the largest s: the bounds
  // of the reference's own pruning (the wobble keeps each wall's s within them).
  inverse_outer_.resize(static_cast<std::size_t>(cell.wall_count));
  inverse_inner_.resize(static_cast<std::size_t>(cell.wall_count));
  for (int k = 0; k < cell.wall_count; ++k) {
    const Wall& wall = cell_walls_[k];
    inverse_outer_[static_cast<std::size_t>(k)] = 1.0 / (wall.centre_distance + wall.wobble_extent);
    const double reach = wall.centre_distance - wall.wobble_extent;
    inverse_inner_[static_cast<std::size_t>(k)] = reach > 0.0 ? 1.0 / reach : INFINITY;
  }
  pruned_.clear();
  for (int k = 0; k < cell.wall_count; ++k) {
    // Where q . n changes sign the reference starts or stops casting to the wall at all.
    const Eigen::Vector2d& n = cell_walls_[k].normal;
    pruned_.push_back({diamondAngle(-n.y(), n.x()), k});
    pruned_.push_back({diamondAngle(n.y(), -n.x()), k});
  }
  if (level.subdivisions > 0) {
    const int segments = 1 << level.subdivisions;
    for (int k = 0; k < cell.wall_count; ++k) {
      const Wall& wall = level.walls[static_cast<std::size_t>(cell.first_wall + k)];
      if (wall.wobble < 0 || !(wall.wobble_extent > 0.0)) continue;
      // The walk only runs while the straight hit is within a segment of the wall's ends.
      const Eigen::Vector2d window_from = wall.start - wall.tangent * (wall.length / segments) - cell.centre;
      const Eigen::Vector2d window_to =
          wall.start + wall.tangent * (wall.length * (segments + 1) / segments) - cell.centre;
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
          if (cross(window_from, along) * window_turn > 0.0 && cross(along, window_to) * window_turn > 0.0)
            addCritical(along, k);
        }
        previous = point;
      }
    }
  }
  std::sort(critical_.begin(), critical_.end(),
            [](const CriticalDirection& a, const CriticalDirection& b) { return a.angle < b.angle; });
  std::sort(pruned_.begin(), pruned_.end(),
            [](const PrunedDirection& a, const PrunedDirection& b) { return a.angle < b.angle; });
  // (Coincident directions stay: each names its wall; they make empty pieces, skipped.)
}

void SectorBuilder::addCritical(const Eigen::Vector2d& direction, int wall_index) {
  double best_lower = 0.0;
  for (int j = 0; j < cell_->wall_count; ++j)
    best_lower =
        std::max(best_lower, direction.dot(cell_walls_[j].normal) * inverse_outer_[static_cast<std::size_t>(j)]);
  const double along = direction.dot(cell_walls_[wall_index].normal);
  if (!(along > 0.0)) return;  // the wall is behind: nothing of it can win here
  if (along * inverse_inner_[static_cast<std::size_t>(wall_index)] < best_lower * (1.0 - 1e-9)) {
    // Cannot win here; kept aside in case a piece where the wall can win contains it.
    pruned_.push_back({diamondAngle(direction.x(), direction.y()), wall_index});
    return;
  }
  critical_.push_back({diamondAngle(direction.x(), direction.y()), direction.normalized(), wall_index});
}

// Walls that can win somewhere in the piece [lo, hi] (less than a half turn): a wall's s lies
// within q . n / (d + e) and q . n / (d - e) (the wobble moves it by at most e), and over the arc
// q . n is smallest at an end and largest at an end or at n itself.
std::uint64_t SectorBuilder::candidatesIn(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                                          const Eigen::Vector2d& direction) const {
  double best_lower = 0.0;
  for (int k = 0; k < cell_->wall_count; ++k) {
    const Wall& wall = cell_walls_[k];
    best_lower = std::max(
        best_lower, std::min(lo.dot(wall.normal), hi.dot(wall.normal)) * inverse_outer_[static_cast<std::size_t>(k)]);
  }
  std::uint64_t mask = 0;
  for (int k = 0; k < cell_->wall_count; ++k) {
    const Wall& wall = cell_walls_[k];
    if (!(direction.dot(wall.normal) > 0.0)) continue;
    // (normals are unit vectors)
    const double highest = cross(lo, wall.normal) > 0.0 && cross(wall.normal, hi) > 0.0
                               ? 1.0
                               : std::max(lo.dot(wall.normal), hi.dot(wall.normal));
    if (highest * inverse_inner_[static_cast<std::size_t>(k)] < best_lower * (1.0 - 1e-9)) continue;
    mask |= std::uint64_t{1} << k;
  }
  return mask;
}

// Between consecutive critical directions every wall's decision (straight hit, or which segment
// its walk settles on) is fixed, so each wall's s is g_k . q with one g_k, taken from the wall's
// own ray hit at the piece's middle direction: candidate_gradients_ gets those of the walls that
// can win in [lo, hi].
void SectorBuilder::gradientsAt(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                                const Eigen::Vector2d& direction) {
  candidate_gradients_.clear();
  const Eigen::Vector2d q = scale_ * direction;
  // A sliver between two nearly equal critical directions has its middle within rounding
  // of one of them, where the decision may fall either way: evaluated afresh, not kept.
  const bool sliver = !(cross(lo, hi) > 1e-10);
  for (std::uint64_t mask = candidatesIn(lo, hi, direction); mask != 0; mask &= mask - 1) {
    const int k = __builtin_ctzll(mask);
    if ((cached_ >> k & 1) && !sliver) {
      if (cached_usable_[static_cast<std::size_t>(k)])
        candidate_gradients_.push_back(cached_gradient_[static_cast<std::size_t>(k)]);
      continue;
    }
    const Wall& wall = cell_walls_[k];
    double s;
    Eigen::Vector2d gradient;
    SkinReliefSampler::wallRayHit(*level_, wall, q, s, gradient);
    // The reference's "s > best" never takes NaN.
    const bool usable = !std::isnan(s) && gradient.allFinite();
    if (!sliver) cached_ |= std::uint64_t{1} << k;
    cached_gradient_[static_cast<std::size_t>(k)] = gradient;
    cached_usable_[static_cast<std::size_t>(k)] = usable;
    if (usable) candidate_gradients_.push_back(gradient);
  }
}

// The max over walls of their linear s changes winner only where two of them tie,
// g_a . d = g_b . d, i.e. d perpendicular to g_a - g_b: walks the upper envelope over [lo, hi]
// (unit directions, counter-clockwise, less than a half turn apart) from lo, each time to the
// first direction where another wall overtakes the current winner, and emits every sector of it,
// the first at lo. (Walls are not pruned here: the reference's pruning only drops walls that
// cannot win.)
void SectorBuilder::envelope(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, SectorEmitter& emit_at) {
  gradientsAt(lo, hi, (lo + hi).normalized());
  const std::size_t count = candidate_gradients_.size();
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
      if (candidate_gradients_[j].dot(probe) > candidate_gradients_[winner].dot(probe)) winner = j;
    return winner;
  };
  std::size_t winner = winnerAfter(lo);
  emit_at(lo, candidate_gradients_[winner]);
  Eigen::Vector2d current = lo;
  for (std::size_t guard = 0; guard < 4 * count + 4; ++guard) {
    std::size_t next = count;
    Eigen::Vector2d best_tie(0.0, 0.0);
    for (std::size_t j = 0; j < count; ++j) {
      if (j == winner) continue;
      const Eigen::Vector2d difference = candidate_gradients_[j] - candidate_gradients_[winner];
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
    emit_at(current, candidate_gradients_[winner]);
  }
}

// Goes round the boundary's sectors once counter-clockwise from the first one's start, and splits
// each into the sectors of the reference's s.
void SectorBuilder::walkBoundarySectors(RasterLevel& out) {
  cached_ = 0;
  cached_gradient_.resize(static_cast<std::size_t>(cell_->wall_count));
  cached_usable_.resize(static_cast<std::size_t>(cell_->wall_count));
  scale_ = 0.25 * level_->spacing;
  const std::size_t chain_count = chain_sectors_.size();
  unwrap_ = 0.0;
  pruned_cycle_ = 0.0;
  pruned_index_ = 0;
  double previous_from = -1.0;
  for (std::size_t k = 0; k < chain_count && chain_count >= 3; ++k) {
    const BoundarySector& sector = chain_sectors_[k];
    const Eigen::Vector2d from_direction = sector.direction.normalized();
    const Eigen::Vector2d to_direction = chain_sectors_[(k + 1) % chain_count].direction.normalized();
    // Pseudo-angles (diamondAngle, period 4) order the directions.
    const double from = diamondAngle(from_direction.x(), from_direction.y());
    double to = diamondAngle(to_direction.x(), to_direction.y());
    while (to <= from) to += 4.0;
    if (k == 0) {
      pruned_index_ = static_cast<std::size_t>(
          std::lower_bound(pruned_.begin(), pruned_.end(), from,
                           [](const PrunedDirection& entry, double value) { return entry.angle < value; }) -
          pruned_.begin());
      if (pruned_index_ == pruned_.size()) {
        pruned_index_ = 0;
        pruned_cycle_ = 4.0;
      }
    } else if (from < previous_from) {
      unwrap_ += 4.0;
    }
    previous_from = from;
    splitIntoPieces(from, to, from_direction, to_direction);
    SectorEmitter emit_at{sector, out.sectors};
    for (std::size_t piece = 0; piece + 1 < pieces_.size(); ++piece) walkPiece(piece, emit_at);
  }
}

// pieces_: the boundary sector [from, to] cut at the critical directions (which may wrap past 4),
// none wider than a quarter of the pseudo-angle period's half (so less than a half turn).
void SectorBuilder::splitIntoPieces(double from, double to, const Eigen::Vector2d& from_direction,
                                    const Eigen::Vector2d& to_direction) {
  pieces_.clear();
  pieces_.push_back({from, from_direction, -1});
  // critical_ is sorted in [0, 4); from is in [0, 4) and to < from + 4. Those within 1e-12 of the
  // sector's start make no piece but still end their wall's cached gradient (the previous sector
  // stopped 1e-13 short of them).
  for (int turn = 0; turn < 2; ++turn) {
    const double low = from - 1e-12 - turn * 4.0, high = to - 1e-13 - turn * 4.0;
    auto it = std::upper_bound(critical_.begin(), critical_.end(), low,
                               [](double value, const CriticalDirection& entry) { return value < entry.angle; });
    for (; it != critical_.end() && it->angle < high; ++it) {
      if (it->angle + turn * 4.0 <= from + 1e-13) {
        cached_ &= ~(std::uint64_t{1} << it->wall);
      } else {
        pushUpTo(it->angle + turn * 4.0, it->direction, it->wall);
      }
    }
  }
  pushUpTo(to, to_direction, -1);
}

void SectorBuilder::pushUpTo(double angle, const Eigen::Vector2d& direction, int wall) {
  const double previous = pieces_.back().angle;
  const int extra = static_cast<int>(std::ceil((angle - previous) / 0.5)) - 1;
  for (int e = 1; e <= extra; ++e) {
    const double a = previous + (angle - previous) * e / (extra + 1);
    pieces_.push_back({a, diamondDirection(a), -1});
  }
  pieces_.push_back({angle, direction, wall});
}

void SectorBuilder::advancePruned() {
  if (++pruned_index_ == pruned_.size()) {
    pruned_index_ = 0;
    pruned_cycle_ += 4.0;
  }
}

void SectorBuilder::walkPiece(std::size_t piece, SectorEmitter& emit_at) {
  const Eigen::Vector2d& lo = pieces_[piece].direction;
  const Eigen::Vector2d& hi = pieces_[piece + 1].direction;
  if (pieces_[piece].wall >= 0) cached_ &= ~(std::uint64_t{1} << pieces_[piece].wall);
  if (!(cross(lo, hi) > 0.0)) return;  // coincident directions
  // A wall that can win somewhere in the piece must keep one decision over all of it: split at
  // its directions set aside above (where it could not win) inside the piece.
  splits_.clear();
  // Those in [a0, a1) (one exactly on a piece boundary only ends its wall's cached gradient), by
  // a pointer that goes round the sorted list once with the walk.
  const double a0 = pieces_[piece].angle + unwrap_, a1 = pieces_[piece + 1].angle + unwrap_;
  if (!pruned_.empty()) {
    while (pruned_[pruned_index_].angle + pruned_cycle_ < a0) advancePruned();
    for (int guard = 0; guard < static_cast<int>(pruned_.size()) && pruned_[pruned_index_].angle + pruned_cycle_ < a1;
         ++guard) {
      splits_.push_back({pruned_[pruned_index_].angle + pruned_cycle_ - unwrap_, pruned_[pruned_index_].wall});
      advancePruned();
    }
  }
  std::uint64_t mask = 0;
  if (!splits_.empty()) mask = candidatesIn(lo, hi, (lo + hi).normalized());
  // Walls that cannot win in this piece are not evaluated in it: their changes here apply from
  // its start.
  for (const PrunedDirection& split : splits_)
    if (!(mask >> split.wall & 1)) cached_ &= ~(std::uint64_t{1} << split.wall);
  Eigen::Vector2d from_direction_piece = lo;
  for (const PrunedDirection& split : splits_) {
    if (!(mask >> split.wall & 1)) continue;
    const Eigen::Vector2d at = diamondDirection(split.angle);
    if (cross(from_direction_piece, at) > 0.0 && cross(at, hi) > 0.0) {
      envelope(from_direction_piece, at, emit_at);
      from_direction_piece = at;
    }
    cached_ &= ~(std::uint64_t{1} << split.wall);
  }
  envelope(from_direction_piece, hi, emit_at);
}

void SectorBuilder::finishCell(RasterCell& raster, RasterLevel& out) const {
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
    // Where a pixel row leaves a sector, as qx / dy of the ray it leaves through: the sector's
    // start ray clockwise (above the centre), the next one's counter-clockwise.
    RasterSector& sector = out.sectors[static_cast<std::size_t>(raster.first_sector + k)];
    const RasterSector& next =
        out.sectors[static_cast<std::size_t>(raster.first_sector + (k + 1) % raster.sector_count)];
    constexpr double never = std::numeric_limits<double>::quiet_NaN();
    sector.crossing_above = sector.direction_y > 0.0 ? sector.direction_x / sector.direction_y : never;
    sector.crossing_below = next.direction_y < 0.0 ? next.direction_x / next.direction_y : never;
  }
  raster.first_vertex = static_cast<int>(out.vertices.size());
  raster.vertex_count = raster.sector_count > 0 ? static_cast<int>(relative_.size()) : 0;
  if (raster.sector_count > 0) out.vertices.insert(out.vertices.end(), relative_.begin(), relative_.end());
  out.most_sectors = std::max(out.most_sectors, raster.sector_count);
  out.cells.push_back(raster);
}

}  // namespace

SkinReliefRasterizer::SkinReliefRasterizer(const SkinCellHierarchy& hierarchy, const SkinReliefSampler& sampler) {
  const std::vector<CellLevel>& levels = hierarchy.levels();
  levels_.assign(levels.size(), RasterLevel());
  ready_ = sampler.roundnessExponent() == 0 && sampler.maxWallCount() <= 64;  // walls as bits of a 64-bit mask
  SectorBuilder builder(levels);
  for (std::size_t index = 0; index < levels.size() && ready_; ++index) {
    const CellLevel& level = levels[index];
    RasterLevel& out = levels_[index];
    out.depth = level.depth;
    out.cells.reserve(level.cells.size());
    // Sectors and boundary vertices grow by the tens per cell: reserve about what the
    // benchmark's maps use, so growth does not copy megabytes time and again.
    out.sectors.reserve(level.cells.size() * 40);
    out.vertices.reserve(level.cells.size() * 40);
    for (const Cell& cell : level.cells)
      if (!builder.addCell(index, cell, out)) ready_ = false;
  }
  if (!ready_) levels_.clear();
  // Each table interval as a line in the table position x * last(): value = offset + position *
  // step, height and slope side by side, and one more entry at the end for position == last()
  // (the profile's centre value, step 0), so the inner loop's lookup needs neither the fraction
  // nor a clamp. Differs from BezierProfileTable::evaluate() by rounding only.
  const BezierProfileTable& table = sampler.profileTable();
  profile_last_ = table.last();
  const std::vector<double>& heights = table.heights();
  const std::vector<double>& slopes = table.slopes();
  const std::size_t intervals = heights.size() - 1;
  profile_lines_.reserve(4 * (intervals + 1));
  for (std::size_t k = 0; k < intervals; ++k) {
    const double height_step = heights[k + 1] - heights[k], slope_step = slopes[k + 1] - slopes[k];
    const double at = static_cast<double>(k);
    profile_lines_.insert(profile_lines_.end(),
                          {heights[k] - at * height_step, height_step, slopes[k] - at * slope_step, slope_step});
  }
  profile_lines_.insert(profile_lines_.end(), {heights[intervals], 0.0, slopes[intervals], 0.0});
}

}  // namespace dressed_human
