// The fast path of SkinReliefSampler (skin_relief_sampler.h): the reference's decisions
// (skin_relief_reference.cpp) in the same order on packed per-level data, so only rounding differs.
#include "dressed_human/core/relief/skin_relief_sampler.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace dressed_human {

using skin_detail::Cell;
using skin_detail::CellLevel;
using skin_detail::Wall;

SkinReliefSampler::SkinReliefSampler(std::shared_ptr<const SkinCellHierarchy> hierarchy,
                                     const SkinReliefParameters& parameters)
    : hierarchy_(std::move(hierarchy)), profile_table_(parameters.profile) {
  // roundness -> exponent of the q-norm over walls: 0 keeps the max (polygonal contours), 1 gives
  // q = 2 (round contours, corners pressed flat).
  roundness_exponent_ =
      parameters.roundness > 0.0 ? std::max(2, static_cast<int>(std::lround(2.0 / parameters.roundness))) : 0;
  buildPackedLevels();
}

void SkinReliefSampler::buildPackedLevels() {
  const std::vector<CellLevel>& levels = hierarchy_->levels();
  packed_.resize(levels.size());
  for (std::size_t index = 0; index < levels.size(); ++index) {
    const CellLevel& level = levels[index];
    PackedLevel& packed = packed_[index];
    packed.depth = level.depth;
    packed.segment_count = level.subdivisions > 0 ? 1 << level.subdivisions : 0;
    packed.cells.reserve(level.cells.size());
    for (const Cell& cell : level.cells) {
      packed.cells.push_back({cell.centre.x(), cell.centre.y(), cell.first_wall, cell.wall_count});
      max_wall_count_ = std::max(max_wall_count_, cell.wall_count);
    }
    packed.walls.reserve(level.walls.size());
    packed.segments.reserve(level.walls.size() * static_cast<std::size_t>(packed.segment_count));
    for (const Wall& wall : level.walls) {
      PackedWall out;
      out.normal_x = wall.normal.x();
      out.normal_y = wall.normal.y();
      out.centre_distance = wall.centre_distance;
      out.inverse_distance = 1.0 / wall.centre_distance;
      out.inverse_outer = 1.0 / (wall.centre_distance + wall.wobble_extent);
      const double reach = wall.centre_distance - wall.wobble_extent;
      out.inverse_inner = reach > 0.0 ? 1.0 / reach : INFINITY;
      out.tangent_x = wall.tangent.x() / wall.length;
      out.tangent_y = wall.tangent.y() / wall.length;
      out.centre_u = wall.centre_u;
      out.neighbour = wall.neighbour;
      out.neighbour_offset_x = wall.neighbour_offset.x();
      out.neighbour_offset_y = wall.neighbour_offset.y();
      const bool wobbled = wall.wobble >= 0 && packed.segment_count > 0;
      // The wobble membership test runs on every wobbled wall; the ray hit only where the extent
      // is positive (as in the reference).
      out.wobble_extent = wobbled ? wall.wobble_extent : 0.0;
      // The wobble test skips a wall while outside <= -extent, i.e. q . n <= d - extent; walls
      // without a neighbour (the parent's) and levels without wobble never test.
      out.wobble_threshold =
          wall.neighbour >= 0 && packed.segment_count > 0 ? wall.centre_distance - out.wobble_extent : INFINITY;
      out.first_segment = -1;
      if (wobbled) {
        const int segments = packed.segment_count;
        out.first_segment = static_cast<int>(packed.segments.size());
        const double* samples = level.wobble_samples.data() +
                                static_cast<std::size_t>(wall.wobble) * static_cast<std::size_t>(segments + 1);
        for (int segment = 0; segment < segments; ++segment) {
          PackedSegment piece;
          piece.offset = wall.wobble_sign * samples[segment];
          piece.step = wall.wobble_sign * (samples[segment + 1] - samples[segment]);
          piece.slope = wall.wobble_sign * (samples[segment + 1] - samples[segment]) * segments;
          piece.start_u = static_cast<double>(segment) / segments;
          piece.numerator = wall.centre_distance + piece.offset + (wall.centre_u - piece.start_u) * piece.slope;
          piece.inverse_numerator = piece.numerator > 0.0 ? 1.0 / piece.numerator : 0.0;
          if (piece.numerator > 0.0) {
            const Eigen::Vector2d gradient =
                (wall.normal - wall.tangent * (piece.slope / wall.length)) / piece.numerator;
            piece.gradient_x = gradient.x();
            piece.gradient_y = gradient.y();
          }
          packed.segments.push_back(piece);
        }
      }
      packed.walls.push_back(out);
    }
  }
}

namespace {

// Fills the entered cell for `candidate`; returns whether the point lies inside its straight
// polygon (inside every wall line -- bisectors and the parent's walls -- is exactly "nearest seed
// among the siblings, within the parent's straight polygon").
template <typename Level, typename Hit, typename Entered>
inline bool enterCell(const Level& level, double x, double y, const Hit& candidate, Entered& entered) {
  const auto* cell = &level.cells[static_cast<std::size_t>(candidate.cell)];
  const auto* walls = level.walls.data() + cell->first_wall;
  // In locals: the stores to the projections could otherwise alias them.
  const double qx = x + candidate.offset_x - cell->centre_x;
  const double qy = y + candidate.offset_y - cell->centre_y;
  const int wall_count = cell->wall_count;
  double* projection = entered.projection;
  bool inside = true;
  bool near_wobble = false;
  for (int k = 0; k < wall_count; ++k) {
    const double along_normal = qx * walls[k].normal_x + qy * walls[k].normal_y;
    projection[k] = along_normal;
    inside &= along_normal <= walls[k].centre_distance;
    near_wobble |= along_normal > walls[k].wobble_threshold;
  }
  entered.hit = candidate;
  entered.cell = cell;
  entered.walls = walls;
  entered.qx = qx;
  entered.qy = qy;
  entered.near_wobble = near_wobble;
  return inside;
}

// Where the ray centre -> centre + q meets a wall: s = 1 / (ray parameter at the hit) and its
// gradient; on each segment of the wobbled polyline the hit condition is linear, with the
// segment's numerator, 1 / numerator and gradient precomputed.
template <typename Segment, typename Wall>
inline void packedRayHit(const Segment* level_segments, int segments, double inverse_segments, const Wall& wall,
                         double qx, double qy, double along_normal, double& s, double& gradient_x, double& gradient_y) {
  s = along_normal * wall.inverse_distance;
  gradient_x = wall.normal_x * wall.inverse_distance;
  gradient_y = wall.normal_y * wall.inverse_distance;
  if (wall.first_segment < 0 || !(wall.wobble_extent > 0.0)) return;
  const double along_tangent = qx * wall.tangent_x + qy * wall.tangent_y;
  double u = wall.centre_u + along_tangent / s;
  // A straight hit just past an end can still meet the wobbled polyline near that end.
  if (!(u > -inverse_segments && u < 1.0 + inverse_segments)) return;
  const Segment* pieces = level_segments + wall.first_segment;
  // floor(u * segments) for u * segments in (-1, segments + 1), without a libm call (the
  // portable build has no SSE4.1 rounding instruction).
  const double position = u * segments;
  int segment = static_cast<int>(position);
  if (position < segment) --segment;
  segment = std::clamp(segment, 0, segments - 1);
  constexpr double tolerance = 1e-12;
  for (int step = 0; step <= segments; ++step) {
    const Segment& piece = pieces[segment];
    if (!(piece.numerator > 0.0)) return;  // keep the straight hit
    const double denominator = along_normal - along_tangent * piece.slope;
    if (!(denominator > 0.0)) return;
    u = wall.centre_u + along_tangent * piece.numerator / denominator;
    if (u < piece.start_u - tolerance && segment > 0) {
      --segment;
      continue;
    }
    if (u > piece.start_u + inverse_segments + tolerance && segment < segments - 1) {
      ++segment;
      continue;
    }
    if (u < -tolerance || u > 1.0 + tolerance) return;  // past the ends the wall is straight
    s = denominator * piece.inverse_numerator;
    gradient_x = piece.gradient_x;
    gradient_y = piece.gradient_y;
    return;
  }
}

}  // namespace

// The cell (cache or search, then the wobble test). Same decisions, in the same order, as
// findLevelZero/findChild + applyWobble.
inline void SkinReliefSampler::locateCell(int level_index, double x, double y, const FastHit& parent, FastCache* cache,
                                          EnteredCell& entered) const {
  const PackedLevel& level = packed_[static_cast<std::size_t>(level_index)];
  const auto slot = static_cast<std::size_t>(level_index);
  bool found = false;
  if (cache && cache->valid[slot] &&
      (level_index == 0 ||
       (cache->parent[slot].cell == parent.cell && cache->parent[slot].offset_x == parent.offset_x &&
        cache->parent[slot].offset_y == parent.offset_y))) {
    found = enterCell(level, x, y, cache->straight[slot], entered);
  }
  if (!found) {
    const Eigen::Vector2d point(x, y);
    Hit searched;
    if (level_index == 0) {
      searched = findLevelZero(point, false);
    } else {
      Hit parent_hit;
      parent_hit.cell = parent.cell;
      parent_hit.offset = Eigen::Vector2i(parent.offset_x, parent.offset_y);
      searched = findChild(level_index, parent_hit, point, false);
    }
    FastHit candidate;
    candidate.cell = searched.cell;
    candidate.offset_x = searched.offset.x();
    candidate.offset_y = searched.offset.y();
    enterCell(level, x, y, candidate, entered);
  }
  if (cache) {
    cache->straight[slot] = entered.hit;
    cache->parent[slot] = parent;
    cache->valid[slot] = true;
  }
  if (!entered.near_wobble) return;
  // Beyond a wobbled furrow the point belongs to the cell on the other side (first such wall
  // in wall order). Parent walls were settled on the parent's level.
  for (int k = 0; k < entered.cell->wall_count; ++k) {
    const PackedWall& wall = entered.walls[k];
    const double outside = entered.projection[k] - wall.centre_distance;
    if (wall.neighbour < 0 || outside <= -wall.wobble_extent) continue;
    double wobble = 0.0;
    const double u = wall.centre_u + (entered.qx * wall.tangent_x + entered.qy * wall.tangent_y);
    if (wall.first_segment >= 0 && u > 0.0 && u < 1.0) {
      const double position = u * level.segment_count;
      const int segment = std::min(static_cast<int>(position), level.segment_count - 1);
      const PackedSegment& piece = level.segments[static_cast<std::size_t>(wall.first_segment + segment)];
      wobble = piece.offset + (position - segment) * piece.step;
    }
    if (outside > wobble) {
      FastHit across;
      across.cell = wall.neighbour;
      across.offset_x = entered.hit.offset_x - wall.neighbour_offset_x;
      across.offset_y = entered.hit.offset_y - wall.neighbour_offset_y;
      enterCell(level, x, y, across, entered);
      break;
    }
  }
}

// s and its gradient over the entered cell's walls: their max, or their q-norm (roundness > 0).
// Same decisions as accumulate.
inline void SkinReliefSampler::rayParameter(const PackedLevel& level, const EnteredCell& entered,
                                            LevelResult& out) const {
  const int segments = level.segment_count;
  const double inverse_segments = segments > 0 ? 1.0 / segments : 0.0;
  const PackedSegment* level_segments = level.segments.data();
  const PackedWall* walls = entered.walls;
  const double* projection = entered.projection;
  const int wall_count = entered.cell->wall_count;
  double s = 0.0, gradient_x = 0.0, gradient_y = 0.0;
  if (roundness_exponent_ == 0) {
    // Max over walls; the wobble keeps each wall's s between the two bounds below, so only
    // walls that can still win get the exact polyline hit.
    // Both passes without data-dependent branches (those mispredicted most); walls behind the
    // centre (q . n <= 0) count 0 -- a negative product could stem from a negative 1 / (d + e).
    double best_lower = 0.0;
    for (int k = 0; k < wall_count; ++k)
      best_lower = std::max(best_lower, std::max(projection[k], 0.0) * walls[k].inverse_outer);
    std::uint64_t candidates = 0;
    for (int k = 0; k < wall_count; ++k) {
      const bool towards = projection[k] > 0.0;
      const bool can_win = !(projection[k] * walls[k].inverse_inner < best_lower);
      candidates |= static_cast<std::uint64_t>(towards & can_win) << k;
    }
    while (candidates != 0) {
      const int k = __builtin_ctzll(candidates);
      candidates &= candidates - 1;
      const double along_normal = projection[k];
      double wall_s, wall_gradient_x, wall_gradient_y;
      packedRayHit(level_segments, segments, inverse_segments, walls[k], entered.qx, entered.qy, along_normal, wall_s,
                   wall_gradient_x, wall_gradient_y);
      if (wall_s > s) {
        s = wall_s;
        gradient_x = wall_gradient_x;
        gradient_y = wall_gradient_y;
      }
    }
  } else {
    double power_sum = 0.0, weighted_x = 0.0, weighted_y = 0.0;
    for (int k = 0; k < wall_count; ++k) {
      const double along_normal = projection[k];
      if (along_normal <= 0.0) continue;
      double wall_s, wall_gradient_x, wall_gradient_y;
      packedRayHit(level_segments, segments, inverse_segments, walls[k], entered.qx, entered.qy, along_normal, wall_s,
                   wall_gradient_x, wall_gradient_y);
      const double lower_power = integerPower(wall_s, roundness_exponent_ - 1);
      power_sum += lower_power * wall_s;
      weighted_x += lower_power * wall_gradient_x;
      weighted_y += lower_power * wall_gradient_y;
    }
    if (power_sum > 0.0) {
      s = std::pow(power_sum, 1.0 / roundness_exponent_);
      gradient_x = weighted_x * (s / power_sum);
      gradient_y = weighted_y * (s / power_sum);
    }
  }
  out.s = s;
  out.gradient_x = gradient_x;
  out.gradient_y = gradient_y;
}

// One level at (x, y): the cell, its s and gradient. The wall projections q . n are computed once
// and shared by the straight-cell test, the wobble test and the ray hit.
void SkinReliefSampler::evaluateLevel(int level_index, double x, double y, const FastHit& parent, FastCache* cache,
                                      LevelResult& out) const {
  EnteredCell entered;
  locateCell(level_index, x, y, parent, cache, entered);
  out.hit = entered.hit;
  rayParameter(packed_[static_cast<std::size_t>(level_index)], entered, out);
}

ReliefSample SkinReliefSampler::evaluateFast(double x, double y, int first_level, int end_level, FastCache* cache,
                                             int* cells_out) const {
  ReliefSample sum;
  FastHit parent;
  LevelResult result;
  for (int level_index = 0; level_index < end_level; ++level_index) {
    evaluateLevel(level_index, x, y, parent, cache, result);
    if (cells_out) cells_out[level_index] = result.hit.cell;
    parent = result.hit;
    if (level_index < first_level || result.s >= 1.0) continue;  // on or past the furrow line: height 0, flat
    const double depth = packed_[static_cast<std::size_t>(level_index)].depth;
    double height, slope;
    profile_table_.evaluate(1.0 - result.s, height, slope);
    sum.height += depth * height;
    sum.slope.x() -= (depth * slope) * result.gradient_x;
    sum.slope.y() -= (depth * slope) * result.gradient_y;
  }
  return sum;
}

ReliefSample SkinReliefSampler::sample(const Eigen::Vector2d& point, int first_level, int end_level) const {
  if (!packed()) return evaluate(point, first_level, end_level, false);
  const Eigen::Vector2d wrapped = point - point.array().floor().matrix();
  return evaluateFast(wrapped.x(), wrapped.y(), first_level, end_level, nullptr);
}

std::vector<int> SkinReliefSampler::cellsAt(const Eigen::Vector2d& point) const {
  const Eigen::Vector2d wrapped = point - point.array().floor().matrix();
  const int level_count = hierarchy_->levelCount();
  std::vector<int> cells;
  if (!packed()) {
    Hit hit = applyWobble(0, findLevelZero(wrapped, false), wrapped);
    cells.push_back(hit.cell);
    for (int level = 1; level < level_count; ++level) {
      hit = applyWobble(level, findChild(level, hit, wrapped, false), wrapped);
      cells.push_back(hit.cell);
    }
    return cells;
  }
  int found[3] = {-1, -1, -1};
  evaluateFast(wrapped.x(), wrapped.y(), level_count, level_count, nullptr, found);
  cells.assign(found, found + level_count);
  return cells;
}

ReliefMap SkinReliefSampler::render(int width, int height, int only_level, bool brute_force) const {
  ReliefMap map(width, height);
  if (only_level >= 0) hierarchy_->levelAt(only_level);
  const int first = only_level >= 0 ? only_level : 0;
  const int end = only_level >= 0 ? only_level + 1 : hierarchy_->levelCount();
  const bool fast = !brute_force && packed();
  for (int row = 0; row < height; ++row) {
    const double v = (row + 0.5) / height;
    RowCache cache;  // the brute-force reference must search every pixel
    FastCache fast_cache;
    for (int column = 0; column < width; ++column) {
      const double u = (column + 0.5) / width;
      const ReliefSample sample =
          fast ? evaluateFast(u, v, first, end, &fast_cache)
               : evaluate(Eigen::Vector2d(u, v), first, end, brute_force, brute_force ? nullptr : &cache);
      const std::size_t at = map.index(column, row);
      map.heights[at] = static_cast<float>(sample.height);
      map.slope_u[at] = static_cast<float>(sample.slope.x());
      map.slope_v[at] = static_cast<float>(sample.slope.y());
    }
  }
  return map;
}

}  // namespace dressed_human
