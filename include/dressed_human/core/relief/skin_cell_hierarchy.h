// The cell structure behind SkinRelief (paper 004 §3-4): Voronoi ridge cells (皮野) on a torus,
// wobbled furrow walls, and nested levels with parent -> child links. Built once per parameter
// set; SkinReliefSampler and SkinReliefRasterizer evaluate heights from it.
//
// Why half-plane clipping instead of Boost.Polygon's voronoi_builder: each level-1 cell is the
// intersection of the bisector half-planes of the ~30 seeds in its lattice window (exact in double
// precision, O(cells)), and the same clipper gives the hierarchy what it really needs -- child
// cells restricted to their parent polygon -- as well as the periodic images and the anisotropic
// (stretched) metric of the directionality, none of which Boost's integer-input sweepline builds.
// The test suite checks level-1 cells against Boost.Polygon's diagram of the same seeds.
#pragma once

#include "dressed_human/core/relief/skin_relief_parameters.h"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace dressed_human {
namespace skin_detail {

/// One straight furrow segment bounding a cell, seen from that cell, plus its midpoint-displaced
/// wobble. Everything is in the owning cell's frame (its periodic image at offset 0).
struct Wall {
  Eigen::Vector2d start;    ///< segment start in the shared (canonical) direction
  Eigen::Vector2d tangent;  ///< unit, shared direction for both cells of the wall
  Eigen::Vector2d normal;   ///< unit, out of the owning cell
  double length = 0.0;
  double centre_distance = 0.0;  ///< (start - centre) . normal, > 0
  double centre_u = 0.0;         ///< (centre - start) . tangent / length
  int wobble = -1;               ///< profile index into CellLevel::wobble_samples, -1 straight
  double wobble_sign = 1.0;      ///< +1 when a positive profile sample moves the wall along `normal`
  double wobble_extent = 0.0;    ///< max |profile sample|: the wall stays within +-extent of the line
  int neighbour = -1;            ///< cell across the wall on this level; -1 for an inherited parent wall
  Eigen::Vector2i neighbour_offset = Eigen::Vector2i::Zero();  ///< neighbour's periodic image
};

struct Cell {
  Eigen::Vector2d centre;                ///< seed, in the cell's frame (level 1: inside [0,1)^2)
  std::vector<Eigen::Vector2d> polygon;  ///< straight cell polygon, counter-clockwise
  int first_wall = 0, wall_count = 0;
  int parent = -1;             ///< index on the previous level (-1 on level 1)
  std::vector<int> children;   ///< indices on the next level
  double wobble_margin = 0.0;  ///< max |wobble| of its walls (bounding-box padding)
};

struct CellLevel {
  double spacing = 0.0;                                  ///< lattice spacing of the seeds (before stretching)
  double depth = 0.0;                                    ///< relief depth in tile units
  Eigen::Matrix2d metric = Eigen::Matrix2d::Identity();  ///< G: |d|^2 = d^T G d (stretch)
  int subdivisions = 0;                                  ///< wobble profile has 2^subdivisions segments
  std::vector<Cell> cells;
  std::vector<Wall> walls;
  std::vector<double> wobble_samples;  ///< (2^subdivisions + 1) samples per profile
  // Level-1 acceleration grid: bucket -> candidate (cell, periodic offset) whose padded
  // polygon overlaps the bucket, in CSR form.
  int buckets_x = 0, buckets_y = 0;
  std::vector<int> bucket_start;
  std::vector<int> bucket_cell;
  std::vector<Eigen::Vector2i> bucket_offset;
};

/// Build all levels. Throws std::invalid_argument for bad parameters (named).
std::vector<CellLevel> buildCellHierarchy(const SkinReliefParameters& parameters);

/// Validates parameters, throwing std::invalid_argument naming the first bad field.
void validateParameters(const SkinReliefParameters& parameters);

/// Wobble displacement of a wall at parameter u along it, outward from the owning cell (0
/// outside (0, 1)): the per-pixel path and the rasteriser's boundary polygons share it. Inline:
/// the per-pixel path calls it for every wall of every pixel.
inline double outwardWobble(const CellLevel& level, const Wall& wall, double u) {
  if (wall.wobble < 0 || level.subdivisions == 0 || !(u > 0.0 && u < 1.0)) return 0.0;
  const int segments = 1 << level.subdivisions;
  const double position = u * segments;
  const int segment = std::min(static_cast<int>(position), segments - 1);
  const double* samples =
      level.wobble_samples.data() + static_cast<std::size_t>(wall.wobble) * static_cast<std::size_t>(segments + 1);
  const double fraction = position - segment;
  return wall.wobble_sign * (samples[segment] + fraction * (samples[segment + 1] - samples[segment]));
}

}  // namespace skin_detail

/// The levels of one parameter set. Levels are numbered from 0; access by index is checked.
class SkinCellHierarchy {
 public:
  /// Throws std::invalid_argument naming a bad parameter.
  explicit SkinCellHierarchy(const SkinReliefParameters& parameters);

  int levelCount() const { return static_cast<int>(levels_.size()); }
  /// Throws std::out_of_range for a level outside 0..levelCount() - 1.
  const skin_detail::CellLevel& levelAt(int level) const;
  /// Parent index on level - 1 (-1 on level 0).
  int parentOf(int level, int cell) const;
  const std::vector<int>& childrenOf(int level, int cell) const;
  /// Unchecked, for the evaluators' inner loops.
  const std::vector<skin_detail::CellLevel>& levels() const { return levels_; }

 private:
  std::vector<skin_detail::CellLevel> levels_;
};

}  // namespace dressed_human
