#include "dressed_human/core/relief/skin_relief.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dressed_human {

using skin_detail::Cell;
using skin_detail::CellLevel;
using skin_detail::Wall;
using skin_detail::outwardWobble;

namespace {

double integerPower(double base, int exponent) {
  double result = 1.0;
  while (exponent > 0) {
    if (exponent & 1) result *= base;
    base *= base;
    exponent >>= 1;
  }
  return result;
}

double metricDistanceSquared(const Eigen::Matrix2d& metric, const Eigen::Vector2d& difference) {
  return difference.dot(metric * difference);
}

// Where the ray centre -> centre + q meets the wall: s = 1 / (ray parameter at the hit), and its
// gradient. The wobbled wall is a polyline over the straight line, so on each of its segments the
// hit condition is linear and s is an affine function of the point.
void rayHit(const CellLevel& level, const Wall& wall, const Eigen::Vector2d& q, double along_normal, double& s,
            Eigen::Vector2d& gradient) {
  s = along_normal / wall.centre_distance;
  gradient = wall.normal / wall.centre_distance;
  if (wall.wobble < 0 || level.subdivisions == 0 || wall.wobble_extent <= 0.0) return;
  const double along_tangent = q.dot(wall.tangent) / wall.length;
  double u = wall.centre_u + along_tangent / s;
  const int segments = 1 << level.subdivisions;
  // A straight hit just past an end can still meet the wobbled polyline near that end.
  if (!(u > -1.0 / segments && u < 1.0 + 1.0 / segments)) return;
  const double* samples = level.wobble_samples.data() + static_cast<std::size_t>(wall.wobble) * static_cast<std::size_t>(segments + 1);
  int segment = std::clamp(static_cast<int>(std::floor(u * segments)), 0, segments - 1);
  constexpr double tolerance = 1e-12;
  for (int step = 0; step <= segments; ++step) {
    const double start_offset = wall.wobble_sign * samples[segment];
    const double slope = wall.wobble_sign * (samples[segment + 1] - samples[segment]) * segments;  // per unit u
    const double segment_u = static_cast<double>(segment) / segments;
    const double numerator = wall.centre_distance + start_offset + (wall.centre_u - segment_u) * slope;
    const double denominator = along_normal - along_tangent * slope;
    if (!(numerator > 0.0) || !(denominator > 0.0)) return;  // keep the straight hit
    u = wall.centre_u + along_tangent * numerator / denominator;
    if (u < segment_u - tolerance && segment > 0) {
      --segment;
      continue;
    }
    if (u > segment_u + 1.0 / segments + tolerance && segment < segments - 1) {
      ++segment;
      continue;
    }
    if (u < -tolerance || u > 1.0 + tolerance) return;  // past the ends the wall is straight
    s = denominator / numerator;
    gradient = (wall.normal - wall.tangent * (slope / wall.length)) / numerator;
    return;
  }
}

}  // namespace

namespace {

// Cells of more walls than this take the reference path (a Voronoi cell of a jittered triangular
// lattice, even clipped by its parent, has far fewer).
constexpr int kMaxPackedWalls = 64;

}  // namespace

SkinRelief::SkinRelief(const SkinReliefParameters& parameters)
    : parameters_(parameters), levels_(skin_detail::buildCellHierarchy(parameters)), profile_table_(parameters.profile) {
  // roundness -> exponent of the q-norm over walls: 0 keeps the max (polygonal contours), 1 gives
  // q = 2 (round contours, corners pressed flat).
  roundness_exponent_ = parameters.roundness > 0.0 ? std::max(2, static_cast<int>(std::lround(2.0 / parameters.roundness))) : 0;
  buildPackedLevels();
  buildRasterLevels();
  // Each table interval as a line in the table position x * last(): value = offset + position *
  // step, height and slope side by side, and one more entry at the end for position == last()
  // (the profile's centre value, step 0), so the rasteriser's lookup needs neither the fraction
  // nor a clamp. Differs from profile_table_.evaluate() by rounding only.
  const std::vector<double>& heights = profile_table_.heights();
  const std::vector<double>& slopes = profile_table_.slopes();
  const std::size_t intervals = heights.size() - 1;
  profile_lines_.reserve(4 * (intervals + 1));
  for (std::size_t k = 0; k < intervals; ++k) {
    const double height_step = heights[k + 1] - heights[k], slope_step = slopes[k + 1] - slopes[k];
    const double at = static_cast<double>(k);
    profile_lines_.insert(profile_lines_.end(), {heights[k] - at * height_step, height_step, slopes[k] - at * slope_step, slope_step});
  }
  profile_lines_.insert(profile_lines_.end(), {heights[intervals], 0.0, slopes[intervals], 0.0});
}

void SkinRelief::buildPackedLevels() {
  packed_.resize(levels_.size());
  for (std::size_t index = 0; index < levels_.size(); ++index) {
    const CellLevel& level = levels_[index];
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
      out.wobble_threshold = wall.neighbour >= 0 && packed.segment_count > 0 ? wall.centre_distance - out.wobble_extent : INFINITY;
      out.first_segment = -1;
      if (wobbled) {
        const int segments = packed.segment_count;
        out.first_segment = static_cast<int>(packed.segments.size());
        const double* samples = level.wobble_samples.data() + static_cast<std::size_t>(wall.wobble) * static_cast<std::size_t>(segments + 1);
        for (int segment = 0; segment < segments; ++segment) {
          PackedSegment piece;
          piece.offset = wall.wobble_sign * samples[segment];
          piece.step = wall.wobble_sign * (samples[segment + 1] - samples[segment]);
          piece.slope = wall.wobble_sign * (samples[segment + 1] - samples[segment]) * segments;
          piece.start_u = static_cast<double>(segment) / segments;
          piece.numerator = wall.centre_distance + piece.offset + (wall.centre_u - piece.start_u) * piece.slope;
          piece.inverse_numerator = piece.numerator > 0.0 ? 1.0 / piece.numerator : 0.0;
          if (piece.numerator > 0.0) {
            const Eigen::Vector2d gradient = (wall.normal - wall.tangent * (piece.slope / wall.length)) / piece.numerator;
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

const CellLevel& SkinRelief::levelAt(int level) const {
  if (level < 0 || level >= levelCount()) {
    std::ostringstream message;
    message << "SkinRelief: level must be in 0.." << levelCount() - 1 << ", got " << level;
    throw std::out_of_range(message.str());
  }
  return levels_[static_cast<std::size_t>(level)];
}

int SkinRelief::parentOf(int level, int cell) const {
  const CellLevel& cells = levelAt(level);
  if (cell < 0 || static_cast<std::size_t>(cell) >= cells.cells.size()) throw std::out_of_range("SkinRelief::parentOf: cell index out of range");
  return cells.cells[static_cast<std::size_t>(cell)].parent;
}

const std::vector<int>& SkinRelief::childrenOf(int level, int cell) const {
  const CellLevel& cells = levelAt(level);
  if (cell < 0 || static_cast<std::size_t>(cell) >= cells.cells.size()) throw std::out_of_range("SkinRelief::childrenOf: cell index out of range");
  return cells.cells[static_cast<std::size_t>(cell)].children;
}

SkinRelief::Hit SkinRelief::findLevelZero(const Eigen::Vector2d& point, bool brute_force) const {
  const CellLevel& level = levels_.front();
  Hit best;
  double best_distance = INFINITY;
  if (brute_force) {
    for (std::size_t index = 0; index < level.cells.size(); ++index) {
      for (int oy = -1; oy <= 1; ++oy) {
        for (int ox = -1; ox <= 1; ++ox) {
          const Eigen::Vector2i offset(ox, oy);
          const double distance = metricDistanceSquared(level.metric, point + offset.cast<double>() - level.cells[index].centre);
          if (distance < best_distance) {
            best_distance = distance;
            best.cell = static_cast<int>(index);
            best.offset = offset;
          }
        }
      }
    }
    return best;
  }
  const int bx = std::min(static_cast<int>(point.x() * level.buckets_x), level.buckets_x - 1);
  const int by = std::min(static_cast<int>(point.y() * level.buckets_y), level.buckets_y - 1);
  const std::size_t bucket = static_cast<std::size_t>(by) * static_cast<std::size_t>(level.buckets_x) + static_cast<std::size_t>(bx);
  for (int k = level.bucket_start[bucket]; k < level.bucket_start[bucket + 1]; ++k) {
    const auto at = static_cast<std::size_t>(k);
    const double distance = metricDistanceSquared(
        level.metric, point + level.bucket_offset[at].cast<double>() - level.cells[static_cast<std::size_t>(level.bucket_cell[at])].centre);
    if (distance < best_distance) {
      best_distance = distance;
      best.cell = level.bucket_cell[at];
      best.offset = level.bucket_offset[at];
    }
  }
  return best;
}

SkinRelief::Hit SkinRelief::findChild(int level_index, const Hit& parent, const Eigen::Vector2d& point, bool brute_force) const {
  const CellLevel& level = levels_[static_cast<std::size_t>(level_index)];
  const Eigen::Vector2d local = point + parent.offset.cast<double>();
  Hit best;
  best.offset = parent.offset;
  double best_distance = INFINITY;
  if (brute_force) {
    for (std::size_t index = 0; index < level.cells.size(); ++index) {
      const Cell& cell = level.cells[index];
      if (cell.parent != parent.cell) continue;
      const double distance = metricDistanceSquared(level.metric, local - cell.centre);
      if (distance < best_distance) {
        best_distance = distance;
        best.cell = static_cast<int>(index);
      }
    }
    return best;
  }
  for (int child : levels_[static_cast<std::size_t>(level_index - 1)].cells[static_cast<std::size_t>(parent.cell)].children) {
    const double distance = metricDistanceSquared(level.metric, local - level.cells[static_cast<std::size_t>(child)].centre);
    if (distance < best_distance) {
      best_distance = distance;
      best.cell = child;
    }
  }
  return best;
}

SkinRelief::Hit SkinRelief::applyWobble(int level_index, Hit hit, const Eigen::Vector2d& point) const {
  const CellLevel& level = levels_[static_cast<std::size_t>(level_index)];
  if (level.subdivisions == 0) return hit;
  const Cell& cell = level.cells[static_cast<std::size_t>(hit.cell)];
  const Eigen::Vector2d local = point + hit.offset.cast<double>();
  for (int k = 0; k < cell.wall_count; ++k) {
    const Wall& wall = level.walls[static_cast<std::size_t>(cell.first_wall + k)];
    if (wall.neighbour < 0) continue;  // parent walls were settled on the parent's level
    const Eigen::Vector2d relative = local - wall.start;
    const double outside = relative.dot(wall.normal);
    if (outside <= -wall.wobble_extent) continue;
    const double u = relative.dot(wall.tangent) / wall.length;
    if (outside > outwardWobble(level, wall, u)) {
      // Beyond the wobbled furrow: the point belongs to the cell on the other side.
      hit.cell = wall.neighbour;
      hit.offset -= wall.neighbour_offset;
      return hit;
    }
  }
  return hit;
}

void SkinRelief::accumulate(int level_index, const Hit& hit, const Eigen::Vector2d& point, ReliefSample& sum) const {
  const CellLevel& level = levels_[static_cast<std::size_t>(level_index)];
  const Cell& cell = level.cells[static_cast<std::size_t>(hit.cell)];
  const Eigen::Vector2d q = point + hit.offset.cast<double>() - cell.centre;
  const Wall* walls = level.walls.data() + cell.first_wall;
  double s = 0.0;
  Eigen::Vector2d gradient = Eigen::Vector2d::Zero();
  if (roundness_exponent_ == 0) {
    // Max over walls. The wobble moves a wall by at most its extent, which bounds each wall's
    // s between the two values below; only walls that can still win get the exact polyline hit.
    double best_lower = 0.0;
    for (int k = 0; k < cell.wall_count; ++k) {
      const double along_normal = q.dot(walls[k].normal);
      if (along_normal > 0.0) best_lower = std::max(best_lower, along_normal / (walls[k].centre_distance + walls[k].wobble_extent));
    }
    for (int k = 0; k < cell.wall_count; ++k) {
      const Wall& wall = walls[k];
      const double along_normal = q.dot(wall.normal);
      if (along_normal <= 0.0) continue;
      const double reach = wall.centre_distance - wall.wobble_extent;
      if (reach > 0.0 && along_normal / reach < best_lower) continue;
      double wall_s;
      Eigen::Vector2d wall_gradient;
      rayHit(level, wall, q, along_normal, wall_s, wall_gradient);
      if (wall_s > s) {
        s = wall_s;
        gradient = wall_gradient;
      }
    }
  } else {
    // q-norm over walls: near a corner two walls both approach 1, so s reaches 1 before the
    // corner -- the profile is compressed there relative to the middle of the walls.
    double power_sum = 0.0;
    Eigen::Vector2d weighted = Eigen::Vector2d::Zero();
    for (int k = 0; k < cell.wall_count; ++k) {
      const double along_normal = q.dot(walls[k].normal);
      if (along_normal <= 0.0) continue;
      double wall_s;
      Eigen::Vector2d wall_gradient;
      rayHit(level, walls[k], q, along_normal, wall_s, wall_gradient);
      const double lower_power = integerPower(wall_s, roundness_exponent_ - 1);
      power_sum += lower_power * wall_s;
      weighted += lower_power * wall_gradient;
    }
    if (power_sum > 0.0) {
      s = std::pow(power_sum, 1.0 / roundness_exponent_);
      gradient = weighted * (s / power_sum);  // s^(1-q) * sum s_j^(q-1) grad s_j
    }
  }
  if (s >= 1.0) return;  // on or past the furrow line: height 0, flat
  double height, slope;
  profile_table_.evaluate(1.0 - s, height, slope);
  sum.height += level.depth * height;
  sum.slope -= (level.depth * slope) * gradient;
}

void SkinRelief::wallRayHit(const CellLevel& level, const Wall& wall, const Eigen::Vector2d& q, double& s, Eigen::Vector2d& gradient) {
  rayHit(level, wall, q, q.dot(wall.normal), s, gradient);
}

bool SkinRelief::insideStraightCell(int level_index, const Hit& hit, const Eigen::Vector2d& point) const {
  const CellLevel& level = levels_[static_cast<std::size_t>(level_index)];
  const Cell& cell = level.cells[static_cast<std::size_t>(hit.cell)];
  const Eigen::Vector2d local = point + hit.offset.cast<double>();
  for (int k = 0; k < cell.wall_count; ++k) {
    const Wall& wall = level.walls[static_cast<std::size_t>(cell.first_wall + k)];
    // Inside every wall line (bisectors and the parent's walls) is exactly "nearest seed among
    // the siblings, within the parent's straight polygon"; the wobble bulges take the full search.
    if ((local - wall.start).dot(wall.normal) > 0.0) return false;
  }
  return true;
}

ReliefSample SkinRelief::evaluate(const Eigen::Vector2d& point, int first_level, int end_level, bool brute_force,
                                  RowCache* cache) const {
  const Eigen::Vector2d wrapped = point - point.array().floor().matrix();
  ReliefSample sum;
  Hit straight;
  if (cache && cache->valid[0] && insideStraightCell(0, cache->straight[0], wrapped)) {
    straight = cache->straight[0];
  } else {
    straight = findLevelZero(wrapped, brute_force);
  }
  if (cache) {
    cache->straight[0] = straight;
    cache->valid[0] = true;
  }
  Hit hit = applyWobble(0, straight, wrapped);
  if (first_level <= 0 && end_level > 0) accumulate(0, hit, wrapped, sum);
  for (int level = 1; level < end_level; ++level) {
    const auto index = static_cast<std::size_t>(level);
    if (cache && cache->valid[index] && cache->parent[index].cell == hit.cell && cache->parent[index].offset == hit.offset &&
        insideStraightCell(level, cache->straight[index], wrapped)) {
      straight = cache->straight[index];
    } else {
      straight = findChild(level, hit, wrapped, brute_force);
    }
    if (cache) {
      cache->straight[index] = straight;
      cache->parent[index] = hit;
      cache->valid[index] = true;
    }
    hit = applyWobble(level, straight, wrapped);
    if (level >= first_level) accumulate(level, hit, wrapped, sum);
  }
  return sum;
}


// One level at (x, y): the cell (cache or search, then the wobble test), its s and gradient.
// Same decisions, in the same order, as findLevelZero/findChild + applyWobble + accumulate; the
// wall projections q . n are computed once and shared by all three.
void SkinRelief::evaluateLevel(int level_index, double x, double y, const FastHit& parent, FastCache* cache,
                               LevelResult& out) const {
  const PackedLevel& level = packed_[static_cast<std::size_t>(level_index)];
  const auto slot = static_cast<std::size_t>(level_index);
  double projection[kMaxPackedWalls];
  FastHit hit;
  const PackedCell* cell = nullptr;
  const PackedWall* walls = nullptr;
  double qx = 0.0, qy = 0.0;
  bool near_wobble = false;  // some wall's wobble test can move the point
  // Enters a cell; returns whether the point lies inside its straight polygon (inside every wall
  // line -- bisectors and the parent's walls -- is exactly "nearest seed among the siblings,
  // within the parent's straight polygon").
  const auto enter = [&](const FastHit& candidate) {
    hit = candidate;
    cell = &level.cells[static_cast<std::size_t>(hit.cell)];
    walls = level.walls.data() + cell->first_wall;
    qx = x + hit.offset_x - cell->centre_x;
    qy = y + hit.offset_y - cell->centre_y;
    bool inside = true;
    near_wobble = false;
    for (int k = 0; k < cell->wall_count; ++k) {
      projection[k] = qx * walls[k].normal_x + qy * walls[k].normal_y;
      inside &= projection[k] <= walls[k].centre_distance;
      near_wobble |= projection[k] > walls[k].wobble_threshold;
    }
    return inside;
  };
  bool found = false;
  if (cache && cache->valid[slot] &&
      (level_index == 0 || (cache->parent[slot].cell == parent.cell && cache->parent[slot].offset_x == parent.offset_x &&
                            cache->parent[slot].offset_y == parent.offset_y))) {
    found = enter(cache->straight[slot]);
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
    enter(candidate);
  }
  if (cache) {
    cache->straight[slot] = hit;
    cache->parent[slot] = parent;
    cache->valid[slot] = true;
  }
  if (near_wobble) {
    // Beyond a wobbled furrow the point belongs to the cell on the other side (first such wall
    // in wall order). Parent walls were settled on the parent's level.
    for (int k = 0; k < cell->wall_count; ++k) {
      const PackedWall& wall = walls[k];
      const double outside = projection[k] - wall.centre_distance;
      if (wall.neighbour < 0 || outside <= -wall.wobble_extent) continue;
      double wobble = 0.0;
      const double u = wall.centre_u + (qx * wall.tangent_x + qy * wall.tangent_y);
      if (wall.first_segment >= 0 && u > 0.0 && u < 1.0) {
        const double position = u * level.segment_count;
        const int segment = std::min(static_cast<int>(position), level.segment_count - 1);
        const PackedSegment& piece = level.segments[static_cast<std::size_t>(wall.first_segment + segment)];
        wobble = piece.offset + (position - segment) * piece.step;
      }
      if (outside > wobble) {
        FastHit across;
        across.cell = wall.neighbour;
        across.offset_x = hit.offset_x - wall.neighbour_offset_x;
        across.offset_y = hit.offset_y - wall.neighbour_offset_y;
        enter(across);
        break;
      }
    }
  }
  out.hit = hit;

  // Where the ray centre -> centre + q meets a wall: s = 1 / (ray parameter at the hit) and its
  // gradient; on each segment of the wobbled polyline the hit condition is linear, with the
  // segment's numerator, 1 / numerator and gradient precomputed.
  const int segments = level.segment_count;
  const double inverse_segments = segments > 0 ? 1.0 / segments : 0.0;
  const auto rayHit = [&](const PackedWall& wall, double along_normal, double& s, double& gradient_x, double& gradient_y) {
    s = along_normal * wall.inverse_distance;
    gradient_x = wall.normal_x * wall.inverse_distance;
    gradient_y = wall.normal_y * wall.inverse_distance;
    if (wall.first_segment < 0 || !(wall.wobble_extent > 0.0)) return;
    const double along_tangent = qx * wall.tangent_x + qy * wall.tangent_y;
    double u = wall.centre_u + along_tangent / s;
    // A straight hit just past an end can still meet the wobbled polyline near that end.
    if (!(u > -inverse_segments && u < 1.0 + inverse_segments)) return;
    const PackedSegment* pieces = level.segments.data() + wall.first_segment;
    // floor(u * segments) for u * segments in (-1, segments + 1), without a libm call (the
    // portable build has no SSE4.1 rounding instruction).
    const double position = u * segments;
    int segment = static_cast<int>(position);
    if (position < segment) --segment;
    segment = std::clamp(segment, 0, segments - 1);
    constexpr double tolerance = 1e-12;
    for (int step = 0; step <= segments; ++step) {
      const PackedSegment& piece = pieces[segment];
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
  };
  double s = 0.0, gradient_x = 0.0, gradient_y = 0.0;
  if (roundness_exponent_ == 0) {
    // Max over walls; the wobble keeps each wall's s between the two bounds below, so only
    // walls that can still win get the exact polyline hit.
    // Both passes without data-dependent branches (those mispredicted most); walls behind the
    // centre (q . n <= 0) count 0 -- a negative product could stem from a negative 1 / (d + e).
    double best_lower = 0.0;
    for (int k = 0; k < cell->wall_count; ++k) best_lower = std::max(best_lower, std::max(projection[k], 0.0) * walls[k].inverse_outer);
    std::uint64_t candidates = 0;
    for (int k = 0; k < cell->wall_count; ++k) {
      const bool towards = projection[k] > 0.0;
      const bool can_win = !(projection[k] * walls[k].inverse_inner < best_lower);
      candidates |= static_cast<std::uint64_t>(towards & can_win) << k;
    }
    while (candidates != 0) {
      const int k = __builtin_ctzll(candidates);
      candidates &= candidates - 1;
      const double along_normal = projection[k];
      double wall_s, wall_gradient_x, wall_gradient_y;
      rayHit(walls[k], along_normal, wall_s, wall_gradient_x, wall_gradient_y);
      if (wall_s > s) {
        s = wall_s;
        gradient_x = wall_gradient_x;
        gradient_y = wall_gradient_y;
      }
    }
  } else {
    double power_sum = 0.0, weighted_x = 0.0, weighted_y = 0.0;
    for (int k = 0; k < cell->wall_count; ++k) {
      const double along_normal = projection[k];
      if (along_normal <= 0.0) continue;
      double wall_s, wall_gradient_x, wall_gradient_y;
      rayHit(walls[k], along_normal, wall_s, wall_gradient_x, wall_gradient_y);
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

ReliefSample SkinRelief::evaluateFast(double x, double y, int first_level, int end_level, FastCache* cache, int* cells_out) const {
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

ReliefSample SkinRelief::sample(const Eigen::Vector2d& point, int level_limit) const {
  const int end = level_limit < 0 ? levelCount() : std::min(level_limit, levelCount());
  if (max_wall_count_ > kMaxPackedWalls) return evaluate(point, 0, end, false);
  const Eigen::Vector2d wrapped = point - point.array().floor().matrix();
  return evaluateFast(wrapped.x(), wrapped.y(), 0, end, nullptr);
}

ReliefSample SkinRelief::sampleLevel(const Eigen::Vector2d& point, int level) const {
  levelAt(level);
  if (max_wall_count_ > kMaxPackedWalls) return evaluate(point, level, level + 1, false);
  const Eigen::Vector2d wrapped = point - point.array().floor().matrix();
  return evaluateFast(wrapped.x(), wrapped.y(), level, level + 1, nullptr);
}

std::vector<int> SkinRelief::cellsAt(const Eigen::Vector2d& point) const {
  const Eigen::Vector2d wrapped = point - point.array().floor().matrix();
  std::vector<int> cells;
  if (max_wall_count_ > kMaxPackedWalls) {
    Hit hit = applyWobble(0, findLevelZero(wrapped, false), wrapped);
    cells.push_back(hit.cell);
    for (int level = 1; level < levelCount(); ++level) {
      hit = applyWobble(level, findChild(level, hit, wrapped, false), wrapped);
      cells.push_back(hit.cell);
    }
    return cells;
  }
  int found[3] = {-1, -1, -1};
  evaluateFast(wrapped.x(), wrapped.y(), levelCount(), levelCount(), nullptr, found);
  cells.assign(found, found + levelCount());
  return cells;
}

ReliefMap SkinRelief::renderWith(int width, int height, int only_level, bool brute_force) const {
  ReliefMap map(width, height);
  if (only_level >= 0) levelAt(only_level);
  const int first = only_level >= 0 ? only_level : 0;
  const int end = only_level >= 0 ? only_level + 1 : levelCount();
  const bool fast = !brute_force && max_wall_count_ <= kMaxPackedWalls;
  for (int row = 0; row < height; ++row) {
    const double v = (row + 0.5) / height;
    RowCache cache;  // the brute-force reference must search every pixel
    FastCache fast_cache;
    for (int column = 0; column < width; ++column) {
      const double u = (column + 0.5) / width;
      const ReliefSample sample = fast ? evaluateFast(u, v, first, end, &fast_cache)
                                       : evaluate(Eigen::Vector2d(u, v), first, end, brute_force, brute_force ? nullptr : &cache);
      const std::size_t at = map.index(column, row);
      map.heights[at] = static_cast<float>(sample.height);
      map.slope_u[at] = static_cast<float>(sample.slope.x());
      map.slope_v[at] = static_cast<float>(sample.slope.y());
    }
  }
  return map;
}

ReliefMap SkinRelief::render(int width, int height, int only_level) const {
  if (only_level >= 0) levelAt(only_level);
  if (raster_ready_ && max_wall_count_ <= kMaxPackedWalls) return renderRaster(width, height, only_level);
  return renderWith(width, height, only_level, false);
}

ReliefMap SkinRelief::renderBruteForce(int width, int height) const {
  return renderWith(width, height, -1, true);
}

}  // namespace dressed_human
