#include "dressed_human/core/relief/skin_cell_hierarchy.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace dressed_human {
namespace skin_detail {
namespace {

constexpr int kBoxTag = INT_MIN;

void fail(const char* field, const std::string& rule, double value) {
  std::ostringstream message;
  message << "SkinReliefParameters." << field << " " << rule << ", got " << value;
  throw std::invalid_argument(message.str());
}

double metricDistanceSquared(const Eigen::Matrix2d& metric, const Eigen::Vector2d& difference) {
  return difference.dot(metric * difference);
}

// Sutherland-Hodgman clip of a convex polygon by {x : normal . x <= bound}; tags[i] names the
// source of edge (i, i+1) and survives on the clipped pieces, the new edge gets `tag`.
void clipPolygon(std::vector<Eigen::Vector2d>& polygon, std::vector<int>& tags, const Eigen::Vector2d& normal,
                 double bound, int tag, std::vector<Eigen::Vector2d>& scratch_polygon, std::vector<int>& scratch_tags) {
  scratch_polygon.clear();
  scratch_tags.clear();
  const std::size_t count = polygon.size();
  for (std::size_t index = 0; index < count; ++index) {
    const Eigen::Vector2d& current = polygon[index];
    const Eigen::Vector2d& next = polygon[(index + 1) % count];
    const double current_side = normal.dot(current) - bound;
    const double next_side = normal.dot(next) - bound;
    const bool current_inside = current_side <= 0.0;
    const bool next_inside = next_side <= 0.0;
    if (current_inside) {
      scratch_polygon.push_back(current);
      scratch_tags.push_back(tags[index]);
    }
    if (current_inside != next_inside) {
      const double t = current_side / (current_side - next_side);
      scratch_polygon.push_back(current + t * (next - current));
      scratch_tags.push_back(current_inside ? tag : tags[index]);
    }
  }
  polygon.swap(scratch_polygon);
  tags.swap(scratch_tags);
}

struct Lattice {
  int columns = 1, rows = 2;
};

Lattice latticeFor(double spacing, double angle, double stretch) {
  // Seed spacing of a triangular lattice whose cells, seen through the stretch, are regular.
  const double c = std::cos(angle), s = std::sin(angle);
  const double spacing_x = spacing * std::sqrt(stretch * stretch * c * c + s * s);
  const double spacing_y = 0.5 * std::sqrt(3.0) * spacing * std::sqrt(stretch * stretch * s * s + c * c);
  Lattice lattice;
  lattice.columns = std::max(1, static_cast<int>(std::lround(1.0 / spacing_x)));
  // Even row count: odd rows are shifted by half a column, which must repeat across the seam.
  lattice.rows = std::max(2, 2 * static_cast<int>(std::lround(0.5 / spacing_y)));
  return lattice;
}

std::vector<Eigen::Vector2d> latticeSeeds(const Lattice& lattice, double jitter, std::mt19937& random) {
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  std::vector<Eigen::Vector2d> seeds;
  seeds.reserve(static_cast<std::size_t>(lattice.columns) * static_cast<std::size_t>(lattice.rows));
  for (int row = 0; row < lattice.rows; ++row) {
    for (int column = 0; column < lattice.columns; ++column) {
      const double jitter_x = jitter * noise(random);
      const double jitter_y = jitter * noise(random);
      seeds.emplace_back((column + 0.5 * (row % 2) + 0.25 + jitter_x) / lattice.columns,
                         (row + 0.5 + jitter_y) / lattice.rows);
    }
  }
  return seeds;
}

int floorDivide(int value, int divisor) { return value >= 0 ? value / divisor : -((-value + divisor - 1) / divisor); }

// Midpoint displacement of a wall of `length`: 2^subdivisions segments, zero at both ends.
// The profile is scaled so it never comes closer than half way to either seed (`clearance` is the
// smaller seed-to-wall distance): the ray from a centre then meets its wobbled wall once, and the
// height stays continuous across the furrow.
int addWobbleProfile(CellLevel& level, const SkinReliefParameters& parameters, double length, double clearance,
                     std::mt19937& random) {
  const int segments = 1 << level.subdivisions;
  const std::size_t first = level.wobble_samples.size();
  level.wobble_samples.resize(first + static_cast<std::size_t>(segments) + 1, 0.0);
  double* samples = level.wobble_samples.data() + first;
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  double amplitude = parameters.wobble * length;
  for (int step = segments; step > 1; step /= 2) {
    for (int middle = step / 2; middle < segments; middle += step) {
      samples[middle] = 0.5 * (samples[middle - step / 2] + samples[middle + step / 2]) + amplitude * noise(random);
    }
    amplitude *= parameters.wobble_roughness;
  }
  double extent = 0.0;
  for (int k = 0; k <= segments; ++k) extent = std::max(extent, std::abs(samples[k]));
  if (extent > 0.5 * clearance) {
    const double scale = 0.5 * clearance / extent;
    for (int k = 0; k <= segments; ++k) samples[k] *= scale;
  }
  return static_cast<int>(first / (static_cast<std::size_t>(segments) + 1));
}

// Canonical identity of a wall shared by two cells, so both sides use one wobble polyline.
using WallKey = std::tuple<int, int, int, int>;

Wall makeWall(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const Eigen::Vector2d& outward_normal,
              bool owner_is_canonical) {
  Wall wall;
  const Eigen::Vector2d canonical_normal = owner_is_canonical ? outward_normal : Eigen::Vector2d(-outward_normal);
  wall.tangent = Eigen::Vector2d(-canonical_normal.y(), canonical_normal.x());
  wall.normal = outward_normal;
  wall.start = wall.tangent.dot(from) <= wall.tangent.dot(to) ? from : to;
  wall.length = (to - from).norm();
  wall.wobble_sign = owner_is_canonical ? 1.0 : -1.0;
  return wall;
}

void finishWall(Wall& wall, const Eigen::Vector2d& centre) {
  wall.centre_distance = (wall.start - centre).dot(wall.normal);
  wall.centre_u = wall.length > 0.0 ? (centre - wall.start).dot(wall.tangent) / wall.length : 0.0;
}

double maximumWobble(const CellLevel& level, const Wall& wall) {
  if (wall.wobble < 0) return 0.0;
  const std::size_t samples = (static_cast<std::size_t>(1) << level.subdivisions) + 1;
  const auto begin =
      level.wobble_samples.begin() + static_cast<std::ptrdiff_t>(samples * static_cast<std::size_t>(wall.wobble));
  double largest = 0.0;
  for (auto it = begin; it != begin + static_cast<std::ptrdiff_t>(samples); ++it)
    largest = std::max(largest, std::abs(*it));
  return largest;
}

// Bucket grid: each cell's polygon (padded by its wobble), in all 9 periodic images.
// Buckets of a third of a seed spacing: few candidates each (measured: 3x3 per lattice cell is
// the sweet spot between candidate count and bucket-list size).
void buildBuckets(CellLevel& level, const Lattice& lattice) {
  level.buckets_x = 3 * lattice.columns;
  level.buckets_y = 3 * lattice.rows;
  const std::size_t bucket_count =
      static_cast<std::size_t>(level.buckets_x) * static_cast<std::size_t>(level.buckets_y);
  std::vector<std::vector<std::pair<int, Eigen::Vector2i>>> buckets(bucket_count);
  for (std::size_t index = 0; index < level.cells.size(); ++index) {
    const Cell& cell = level.cells[index];
    Eigen::Vector2d low = cell.polygon.front(), high = cell.polygon.front();
    for (const auto& vertex : cell.polygon) {
      low = low.cwiseMin(vertex);
      high = high.cwiseMax(vertex);
    }
    const double pad = cell.wobble_margin + 1e-9;
    for (int oy = -1; oy <= 1; ++oy) {
      for (int ox = -1; ox <= 1; ++ox) {
        const Eigen::Vector2d shift(ox, oy);
        const Eigen::Vector2d a = low + shift - Eigen::Vector2d::Constant(pad);
        const Eigen::Vector2d b = high + shift + Eigen::Vector2d::Constant(pad);
        if (b.x() < 0.0 || b.y() < 0.0 || a.x() >= 1.0 || a.y() >= 1.0) continue;
        const int x0 = std::max(0, static_cast<int>(std::floor(a.x() * level.buckets_x)));
        const int x1 = std::min(level.buckets_x - 1, static_cast<int>(std::floor(b.x() * level.buckets_x)));
        const int y0 = std::max(0, static_cast<int>(std::floor(a.y() * level.buckets_y)));
        const int y1 = std::min(level.buckets_y - 1, static_cast<int>(std::floor(b.y() * level.buckets_y)));
        for (int by = y0; by <= y1; ++by)
          for (int bx = x0; bx <= x1; ++bx)
            buckets[static_cast<std::size_t>(by) * static_cast<std::size_t>(level.buckets_x) +
                    static_cast<std::size_t>(bx)]
                .emplace_back(static_cast<int>(index), Eigen::Vector2i(-ox, -oy));
      }
    }
  }
  level.bucket_start.assign(bucket_count + 1, 0);
  for (std::size_t bucket = 0; bucket < bucket_count; ++bucket) {
    level.bucket_start[bucket + 1] = level.bucket_start[bucket] + static_cast<int>(buckets[bucket].size());
    for (const auto& entry : buckets[bucket]) {
      level.bucket_cell.push_back(entry.first);
      level.bucket_offset.push_back(entry.second);
    }
  }
}

// One level's wall profiles, one per wall however many cells meet it: the first cell to reach a
// wall makes its profile, the neighbour across it finds that one by the wall's key.
class WallWobbles {
 public:
  WallWobbles(CellLevel& level, const SkinReliefParameters& parameters, std::mt19937& random)
      : level_(level), parameters_(parameters), random_(random) {}

  // `wall` (makeWall's) between the seeds `centre` and `other` gets its profile and extent.
  void assign(const WallKey& key, const Eigen::Vector2d& centre, const Eigen::Vector2d& other, Wall& wall) {
    auto found = profiles_.find(key);
    if (found == profiles_.end()) {
      const double clearance =
          std::min(std::abs((wall.start - centre).dot(wall.normal)), std::abs((wall.start - other).dot(wall.normal)));
      found = profiles_.emplace(key, addWobbleProfile(level_, parameters_, wall.length, clearance, random_)).first;
    }
    wall.wobble = found->second;
    wall.wobble_extent = maximumWobble(level_, wall);
  }

 private:
  CellLevel& level_;
  const SkinReliefParameters& parameters_;
  std::mt19937& random_;
  std::map<WallKey, int> profiles_;
};

void buildTopLevel(CellLevel& level, const SkinReliefParameters& parameters, double stretch, std::mt19937& random,
                   std::mt19937& wobble_random) {
  const Lattice lattice = latticeFor(level.spacing, parameters.direction_angle, stretch);
  const std::vector<Eigen::Vector2d> seeds = latticeSeeds(lattice, parameters.jitter, random);
  level.cells.resize(seeds.size());
  for (std::size_t index = 0; index < seeds.size(); ++index) level.cells[index].centre = seeds[index];

  WallWobbles wobbles(level, parameters, wobble_random);
  std::vector<Eigen::Vector2d> polygon, scratch_polygon;
  std::vector<int> tags, scratch_tags;
  struct Candidate {
    int cell;
    Eigen::Vector2i offset;
  };
  std::vector<Candidate> candidates;
  const double cell_width = 1.0 / lattice.columns, cell_height = 1.0 / lattice.rows;
  for (int row = 0; row < lattice.rows; ++row) {
    for (int column = 0; column < lattice.columns; ++column) {
      const int self = row * lattice.columns + column;
      Cell& cell = level.cells[static_cast<std::size_t>(self)];
      const Eigen::Vector2d centre = cell.centre;
      for (int window = 2;; ++window) {
        candidates.clear();
        for (int dr = -window; dr <= window; ++dr) {
          for (int dc = -window; dc <= window; ++dc) {
            if (dr == 0 && dc == 0) continue;
            const int r = row + dr, c = column + dc;
            Candidate candidate;
            candidate.cell = (r - floorDivide(r, lattice.rows) * lattice.rows) * lattice.columns +
                             (c - floorDivide(c, lattice.columns) * lattice.columns);
            candidate.offset = {floorDivide(c, lattice.columns), floorDivide(r, lattice.rows)};
            candidates.push_back(candidate);
          }
        }
        const double box = (window + 1.0) * std::max(cell_width, cell_height);
        polygon = {centre + Eigen::Vector2d(-box, -box), centre + Eigen::Vector2d(box, -box),
                   centre + Eigen::Vector2d(box, box), centre + Eigen::Vector2d(-box, box)};
        tags.assign(4, kBoxTag);
        for (std::size_t k = 0; k < candidates.size(); ++k) {
          const Eigen::Vector2d other =
              seeds[static_cast<std::size_t>(candidates[k].cell)] + candidates[k].offset.cast<double>();
          const Eigen::Vector2d normal = level.metric * (other - centre);
          clipPolygon(polygon, tags, normal, normal.dot(0.5 * (other + centre)), static_cast<int>(k), scratch_polygon,
                      scratch_tags);
        }
        // Every seed outside the window is at least this far (metric) from the centre; the
        // smallest metric eigenvalue is 1 / stretch^2.
        const double outside = std::min((window + 0.5 - 2.0 * parameters.jitter) * cell_width,
                                        (window + 1.0 - 2.0 * parameters.jitter) * cell_height) /
                               stretch;
        double radius_squared = 0.0;
        for (const auto& vertex : polygon)
          radius_squared = std::max(radius_squared, metricDistanceSquared(level.metric, vertex - centre));
        const bool box_left = std::find(tags.begin(), tags.end(), kBoxTag) != tags.end();
        if (!box_left && outside * outside > 4.0 * radius_squared) break;
        if (window > 64) throw std::logic_error("SkinRelief: Voronoi neighbour window did not converge");
      }
      cell.polygon = polygon;
      cell.first_wall = static_cast<int>(level.walls.size());
      cell.wall_count = static_cast<int>(polygon.size());
      for (std::size_t edge = 0; edge < polygon.size(); ++edge) {
        const Candidate& candidate = candidates[static_cast<std::size_t>(tags[edge])];
        const WallKey mine{self, candidate.cell, candidate.offset.x(), candidate.offset.y()};
        const WallKey theirs{candidate.cell, self, -candidate.offset.x(), -candidate.offset.y()};
        const bool canonical = mine < theirs;
        const Eigen::Vector2d other = seeds[static_cast<std::size_t>(candidate.cell)] + candidate.offset.cast<double>();
        Wall wall = makeWall(polygon[edge], polygon[(edge + 1) % polygon.size()],
                             (level.metric * (other - centre)).normalized(), canonical);
        wall.neighbour = candidate.cell;
        wall.neighbour_offset = candidate.offset;
        wobbles.assign(canonical ? mine : theirs, centre, other, wall);
        finishWall(wall, centre);
        cell.wobble_margin = std::max(cell.wobble_margin, wall.wobble_extent);
        level.walls.push_back(wall);
      }
    }
  }
  buildBuckets(level, lattice);
}

// Nearest seed without wobble, level by level (used to hand child seeds to parents).
std::pair<int, Eigen::Vector2i> straightCellAt(const std::vector<CellLevel>& levels, std::size_t level_index,
                                               const Eigen::Vector2d& point) {
  const CellLevel& top = levels.front();
  const int bx = std::clamp(static_cast<int>(point.x() * top.buckets_x), 0, top.buckets_x - 1);
  const int by = std::clamp(static_cast<int>(point.y() * top.buckets_y), 0, top.buckets_y - 1);
  const std::size_t bucket =
      static_cast<std::size_t>(by) * static_cast<std::size_t>(top.buckets_x) + static_cast<std::size_t>(bx);
  int best = -1;
  Eigen::Vector2i best_offset = Eigen::Vector2i::Zero();
  double best_distance = INFINITY;
  for (int k = top.bucket_start[bucket]; k < top.bucket_start[bucket + 1]; ++k) {
    const auto at = static_cast<std::size_t>(k);
    const Eigen::Vector2d local = point + top.bucket_offset[at].cast<double>();
    const double distance =
        metricDistanceSquared(top.metric, local - top.cells[static_cast<std::size_t>(top.bucket_cell[at])].centre);
    if (distance < best_distance) {
      best_distance = distance;
      best = top.bucket_cell[at];
      best_offset = top.bucket_offset[at];
    }
  }
  for (std::size_t level = 1; level <= level_index; ++level) {
    const Cell& parent = levels[level - 1].cells[static_cast<std::size_t>(best)];
    const Eigen::Vector2d local = point + best_offset.cast<double>();
    best_distance = INFINITY;
    int child_best = -1;
    for (int child : parent.children) {
      const double distance = metricDistanceSquared(
          levels[level].metric, local - levels[level].cells[static_cast<std::size_t>(child)].centre);
      if (distance < best_distance) {
        best_distance = distance;
        child_best = child;
      }
    }
    best = child_best;
  }
  return {best, best_offset};
}

// A child seed must keep clear of its parent's wobbled walls by `margin` beyond their wobble,
// or the parent's furrow could pass between the child's centre and its own pixels. Seeds too
// close are moved inward; a parent too small for that gets its child at its own centre.
Eigen::Vector2d pushedAwayFromWalls(const CellLevel& parents, const Cell& parent, Eigen::Vector2d seed, double margin) {
  const auto violation = [&](const Eigen::Vector2d& point, const Wall& wall) {
    return wall.wobble_extent + margin - (wall.start - point).dot(wall.normal);
  };
  for (int pass = 0; pass < 3; ++pass) {
    for (int k = 0; k < parent.wall_count; ++k) {
      const Wall& wall = parents.walls[static_cast<std::size_t>(parent.first_wall + k)];
      const double excess = violation(seed, wall);
      if (excess > 0.0) seed -= excess * wall.normal;
    }
  }
  for (int k = 0; k < parent.wall_count; ++k) {
    if (violation(seed, parents.walls[static_cast<std::size_t>(parent.first_wall + k)]) > 1e-12) return parent.centre;
  }
  return seed;
}

void buildChildLevel(std::vector<CellLevel>& levels, std::size_t level_index, const SkinReliefParameters& parameters,
                     double stretch, std::mt19937& random, std::mt19937& wobble_random) {
  CellLevel& level = levels[level_index];
  CellLevel& parents = levels[level_index - 1];
  const Lattice lattice = latticeFor(level.spacing, parameters.direction_angle, stretch);
  // Child seeds cover the whole tile; each goes to the parent whose (straight) cell holds it,
  // written in that parent's frame.
  for (Eigen::Vector2d seed : latticeSeeds(lattice, parameters.jitter, random)) {
    seed -= seed.array().floor().matrix();
    const auto [parent, offset] = straightCellAt(levels, level_index - 1, seed);
    Cell child;
    child.centre = pushedAwayFromWalls(parents, parents.cells[static_cast<std::size_t>(parent)],
                                       seed + offset.cast<double>(), 0.15 * level.spacing);
    // Two seeds of a parent too small to push them clear both land on its centre. Coincident
    // seeds have no bisector: both would get the whole polygon and each its own (different)
    // wobbled walls to the same neighbours, and the nearest-seed tie would leave the second one
    // only the pixels that the neighbours' furrows flip to it. Keep one.
    const std::vector<int>& siblings = parents.cells[static_cast<std::size_t>(parent)].children;
    if (std::any_of(siblings.begin(), siblings.end(),
                    [&](int sibling) { return level.cells[static_cast<std::size_t>(sibling)].centre == child.centre; }))
      continue;
    child.parent = parent;
    parents.cells[static_cast<std::size_t>(parent)].children.push_back(static_cast<int>(level.cells.size()));
    level.cells.push_back(child);
  }
  for (std::size_t index = 0; index < parents.cells.size(); ++index) {
    Cell& parent = parents.cells[index];
    if (!parent.children.empty()) continue;
    Cell only_child;
    only_child.centre = parent.centre;
    only_child.parent = static_cast<int>(index);
    parent.children.push_back(static_cast<int>(level.cells.size()));
    level.cells.push_back(only_child);
  }

  std::vector<Eigen::Vector2d> polygon, scratch_polygon;
  std::vector<int> tags, scratch_tags;
  WallWobbles wobbles(level, parameters, wobble_random);
  std::map<int, int> inherited_wobble;  // parent-level profile index -> this level's copy
  for (std::size_t parent_index = 0; parent_index < parents.cells.size(); ++parent_index) {
    const Cell& parent = parents.cells[parent_index];
    for (int self : parent.children) {
      Cell& cell = level.cells[static_cast<std::size_t>(self)];
      polygon = parent.polygon;
      tags.resize(polygon.size());
      for (std::size_t edge = 0; edge < polygon.size(); ++edge) tags[edge] = -1 - static_cast<int>(edge);
      for (int sibling : parent.children) {
        if (sibling == self) continue;
        const Eigen::Vector2d& other = level.cells[static_cast<std::size_t>(sibling)].centre;
        const Eigen::Vector2d normal = level.metric * (other - cell.centre);
        clipPolygon(polygon, tags, normal, normal.dot(0.5 * (other + cell.centre)), sibling, scratch_polygon,
                    scratch_tags);
      }
      cell.polygon = polygon;
      cell.first_wall = static_cast<int>(level.walls.size());
      cell.wall_count = static_cast<int>(polygon.size());
      for (std::size_t edge = 0; edge < polygon.size(); ++edge) {
        Wall wall;
        if (tags[edge] < 0) {
          // A piece of the parent's wall: keep the parent's whole wall, wobble included, so the
          // child's furrow follows the parent's exactly.
          wall = parents.walls[static_cast<std::size_t>(parent.first_wall + (-1 - tags[edge]))];
          wall.neighbour = -1;
          wall.neighbour_offset.setZero();
          if (wall.wobble >= 0) {
            // Profiles are stored per level: copy the parent's once into this level.
            auto copied = inherited_wobble.find(wall.wobble);
            if (copied == inherited_wobble.end()) {
              const std::size_t samples = (static_cast<std::size_t>(1) << level.subdivisions) + 1;
              const auto begin = parents.wobble_samples.begin() +
                                 static_cast<std::ptrdiff_t>(samples * static_cast<std::size_t>(wall.wobble));
              const int index = static_cast<int>(level.wobble_samples.size() / samples);
              level.wobble_samples.insert(level.wobble_samples.end(), begin,
                                          begin + static_cast<std::ptrdiff_t>(samples));
              copied = inherited_wobble.emplace(wall.wobble, index).first;
            }
            wall.wobble = copied->second;
          }
        } else {
          const int sibling = tags[edge];
          const bool canonical = self < sibling;
          const Eigen::Vector2d& other = level.cells[static_cast<std::size_t>(sibling)].centre;
          wall = makeWall(polygon[edge], polygon[(edge + 1) % polygon.size()],
                          (level.metric * (other - cell.centre)).normalized(), canonical);
          wall.neighbour = sibling;
          wobbles.assign(WallKey{std::min(self, sibling), std::max(self, sibling), 0, 0}, cell.centre, other, wall);
        }
        finishWall(wall, cell.centre);
        level.walls.push_back(wall);
      }
    }
  }
}

}  // namespace

void validateParameters(const SkinReliefParameters& p) {
  if (!(p.cell_size > 0.0 && p.cell_size <= 1.0)) fail("cell_size", "must be in (0, 1] (tile units)", p.cell_size);
  if (p.levels < 1 || p.levels > 3) fail("levels", "must be 1, 2 or 3", p.levels);
  if (!(p.child_cell_ratio >= 0.1 && p.child_cell_ratio <= 0.8))
    fail("child_cell_ratio", "must be in [0.1, 0.8]", p.child_cell_ratio);
  if (!(p.jitter >= 0.0 && p.jitter <= 0.5))
    fail("jitter", "must be in [0, 0.5] (fraction of the seed spacing)", p.jitter);
  if (!(p.wobble >= 0.0 && p.wobble <= 0.3))
    fail("wobble", "must be in [0, 0.3] (fraction of the wall length)", p.wobble);
  if (p.wobble_subdivisions < 0 || p.wobble_subdivisions > 6)
    fail("wobble_subdivisions", "must be in 0..6", p.wobble_subdivisions);
  if (!(p.wobble_roughness >= 0.0 && p.wobble_roughness <= 1.0))
    fail("wobble_roughness", "must be in [0, 1]", p.wobble_roughness);
  if (!(p.roundness >= 0.0 && p.roundness <= 1.0)) fail("roundness", "must be in [0, 1]", p.roundness);
  if (!std::isfinite(p.direction_angle)) fail("direction_angle", "must be finite", p.direction_angle);
  if (!(p.direction_stretch >= 1.0 && p.direction_stretch <= 10.0))
    fail("direction_stretch", "must be in [1, 10]", p.direction_stretch);
  if (p.directional_levels < 0 || p.directional_levels > 3)
    fail("directional_levels", "must be in 0..3", p.directional_levels);
  for (double depth : p.level_depth) {
    if (!(depth >= 0.0) || !std::isfinite(depth)) fail("level_depth", "entries must be finite and >= 0", depth);
  }
  // Level 3 spacing must still span a few pixels of a sensible map and a tractable cell count.
  const double finest = p.cell_size * std::pow(p.child_cell_ratio, p.levels - 1);
  if (finest < 1.0 / 512.0)
    fail("cell_size", "times child_cell_ratio^(levels-1) must be >= 1/512 (too many cells)", finest);
  BezierProfileTable check(p.profile, 16);  // throws with the profile's own message
  (void)check;
}

std::vector<CellLevel> buildCellHierarchy(const SkinReliefParameters& parameters) {
  validateParameters(parameters);
  std::vector<CellLevel> levels(static_cast<std::size_t>(parameters.levels));
  std::mt19937 seed_random(parameters.seed);
  std::mt19937 wobble_random(parameters.seed ^ 0x9E3779B9u);
  const Eigen::Vector2d along(std::cos(parameters.direction_angle), std::sin(parameters.direction_angle));
  const Eigen::Vector2d across(-along.y(), along.x());
  for (std::size_t index = 0; index < levels.size(); ++index) {
    CellLevel& level = levels[index];
    const bool directional = static_cast<int>(index) < parameters.directional_levels;
    const double stretch = directional ? parameters.direction_stretch : 1.0;
    level.spacing = parameters.cell_size * std::pow(parameters.child_cell_ratio, static_cast<double>(index));
    level.depth = parameters.level_depth[index] * level.spacing;
    level.metric = along * along.transpose() / (stretch * stretch) + across * across.transpose();
    level.subdivisions = parameters.wobble > 0.0 ? parameters.wobble_subdivisions : 0;
    if (index == 0) {
      buildTopLevel(level, parameters, stretch, seed_random, wobble_random);
    } else {
      buildChildLevel(levels, index, parameters, stretch, seed_random, wobble_random);
    }
  }
  return levels;
}

}  // namespace skin_detail

SkinCellHierarchy::SkinCellHierarchy(const SkinReliefParameters& parameters)
    : levels_(skin_detail::buildCellHierarchy(parameters)) {}

// The messages name SkinRelief: callers meet the hierarchy through it.
const skin_detail::CellLevel& SkinCellHierarchy::levelAt(int level) const {
  if (level < 0 || level >= levelCount()) {
    std::ostringstream message;
    message << "SkinRelief: level must be in 0.." << levelCount() - 1 << ", got " << level;
    throw std::out_of_range(message.str());
  }
  return levels_[static_cast<std::size_t>(level)];
}

int SkinCellHierarchy::parentOf(int level, int cell) const {
  const skin_detail::CellLevel& cells = levelAt(level);
  if (cell < 0 || static_cast<std::size_t>(cell) >= cells.cells.size())
    throw std::out_of_range("SkinRelief::parentOf: cell index out of range");
  return cells.cells[static_cast<std::size_t>(cell)].parent;
}

const std::vector<int>& SkinCellHierarchy::childrenOf(int level, int cell) const {
  const skin_detail::CellLevel& cells = levelAt(level);
  if (cell < 0 || static_cast<std::size_t>(cell) >= cells.cells.size())
    throw std::out_of_range("SkinRelief::childrenOf: cell index out of range");
  return cells.cells[static_cast<std::size_t>(cell)].children;
}

}  // namespace dressed_human
