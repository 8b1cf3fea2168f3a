// The reference evaluation of SkinReliefSampler (skin_relief_sampler.h): the original per-point
// model, kept as written for the brute-force map the tests compare against, for cells of more
// walls than the fast path packs, and for the fast path's cell searches.
#include "dressed_human/core/relief/skin_relief_sampler.h"

#include <algorithm>
#include <cmath>

namespace dressed_human {

using skin_detail::Cell;
using skin_detail::CellLevel;
using skin_detail::outwardWobble;
using skin_detail::Wall;

namespace {

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
  const double* samples =
      level.wobble_samples.data() + static_cast<std::size_t>(wall.wobble) * static_cast<std::size_t>(segments + 1);
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

SkinReliefSampler::Hit SkinReliefSampler::findLevelZero(const Eigen::Vector2d& point, bool brute_force) const {
  const CellLevel& level = hierarchy_->levels().front();
  Hit best;
  double best_distance = INFINITY;
  if (brute_force) {
    for (std::size_t index = 0; index < level.cells.size(); ++index) {
      for (int oy = -1; oy <= 1; ++oy) {
        for (int ox = -1; ox <= 1; ++ox) {
          const Eigen::Vector2i offset(ox, oy);
          const double distance =
              metricDistanceSquared(level.metric, point + offset.cast<double>() - level.cells[index].centre);
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
  const std::size_t bucket =
      static_cast<std::size_t>(by) * static_cast<std::size_t>(level.buckets_x) + static_cast<std::size_t>(bx);
  for (int k = level.bucket_start[bucket]; k < level.bucket_start[bucket + 1]; ++k) {
    const auto at = static_cast<std::size_t>(k);
    const double distance =
        metricDistanceSquared(level.metric, point + level.bucket_offset[at].cast<double>() -
                                                level.cells[static_cast<std::size_t>(level.bucket_cell[at])].centre);
    if (distance < best_distance) {
      best_distance = distance;
      best.cell = level.bucket_cell[at];
      best.offset = level.bucket_offset[at];
    }
  }
  return best;
}

SkinReliefSampler::Hit SkinReliefSampler::findChild(int level_index, const Hit& parent, const Eigen::Vector2d& point,
                                                    bool brute_force) const {
  const CellLevel& level = hierarchy_->levels()[static_cast<std::size_t>(level_index)];
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
  for (int child : hierarchy_->levels()[static_cast<std::size_t>(level_index - 1)]
                       .cells[static_cast<std::size_t>(parent.cell)]
                       .children) {
    const double distance =
        metricDistanceSquared(level.metric, local - level.cells[static_cast<std::size_t>(child)].centre);
    if (distance < best_distance) {
      best_distance = distance;
      best.cell = child;
    }
  }
  return best;
}

SkinReliefSampler::Hit SkinReliefSampler::applyWobble(int level_index, Hit hit, const Eigen::Vector2d& point) const {
  const CellLevel& level = hierarchy_->levels()[static_cast<std::size_t>(level_index)];
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

void SkinReliefSampler::accumulate(int level_index, const Hit& hit, const Eigen::Vector2d& point,
                                   ReliefSample& sum) const {
  const CellLevel& level = hierarchy_->levels()[static_cast<std::size_t>(level_index)];
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
      if (along_normal > 0.0)
        best_lower = std::max(best_lower, along_normal / (walls[k].centre_distance + walls[k].wobble_extent));
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

void SkinReliefSampler::wallRayHit(const CellLevel& level, const Wall& wall, const Eigen::Vector2d& q, double& s,
                                   Eigen::Vector2d& gradient) {
  rayHit(level, wall, q, q.dot(wall.normal), s, gradient);
}

bool SkinReliefSampler::insideStraightCell(int level_index, const Hit& hit, const Eigen::Vector2d& point) const {
  const CellLevel& level = hierarchy_->levels()[static_cast<std::size_t>(level_index)];
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

ReliefSample SkinReliefSampler::evaluate(const Eigen::Vector2d& point, int first_level, int end_level, bool brute_force,
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
    if (cache && cache->valid[index] && cache->parent[index].cell == hit.cell &&
        cache->parent[index].offset == hit.offset && insideStraightCell(level, cache->straight[index], wrapped)) {
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

}  // namespace dressed_human
