// Skin relief from a hierarchical Voronoi division (SPEC §5, paper 004): ridge cells (皮野)
// bounded by furrows (皮溝), as a tileable height + normal map.
//
// Tile: the unit square [0,1)^2, periodic in both directions so the map wraps around a limb and
// repeats without seams. Heights are in tile units (multiply by the physical tile size).
// Pipeline per level (paper 004 §4):
//  * seeds on a triangular lattice, each moved by uniform noise (jitter) -- §5.2, Fig. 14;
//  * Voronoi cells of the seeds; level > 1 divides every parent cell again (children clipped to the
//    parent polygon, parent -> child links kept) -- §4.3, Figs. 8-9;
//  * cell walls wobbled by midpoint displacement, one shared polyline per wall -- Fig. 3, 15;
//  * height: cast the ray centre -> p to the (wobbled) wall, s = |p - c| / |hit - c|, and read the
//    Bezier cross-section at x = 1 - s (0 at the edge, 1 at the centre) -- §4.1, Figs. 4-7;
//  * roundness: the ray parameter is combined over walls by a q-norm instead of a max, which
//    stretches the profile away from the polygon corners and rounds the contours (Figs. 12-13);
//  * directionality: distances in a metric stretched by `direction_stretch` along
//    `direction_angle`, which elongates the cells like scaling their vertices (§4.2, Fig. 17);
//  * height and gradient summed over levels (§4.3, Fig. 10).
// Normals come from the exact gradient of the summed height field, so the normal map and the
// height map describe the same surface (the paper uses the radial slope only, which ignores the
// along-wall component where the ray meets a wall obliquely).
//
// The pieces, each with its own header in relief/ (SkinRelief composes them):
//  * skin_relief_parameters.h -- the parameters;
//  * skin_cell_hierarchy.h -- the cells, walls and levels built from them;
//  * skin_relief_sampler.h -- point evaluation: sample(), cellsAt(), render() with roundness > 0
//    (per pixel: find the pixel's cell level by level, then cast the ray to its walls), and the
//    brute-force reference;
//  * skin_relief_rasterizer.h -- render() with roundness 0: with max over walls, s is the ray
//    ratio to one wall segment and so linear inside each angular sector seen from the centre. At
//    construction every cell gets its boundary polygon (skin_cell_boundary.h: wobbled walls; on
//    child levels the parent's wobbled wall pieces) and its sectors with the reference's gradient
//    of s (from the directions where a wall's ray-hit decision can change and the ties between
//    walls, no sampling); render fills each cell's pixels row by row, stepping through the
//    sectors, masked by the parent level's owners. Pixels no cell claims go through the
//    per-pixel path. It differs from the reference only in which cell owns a few pixels along
//    furrows (kReference* below).
#pragma once

#include "dressed_human/core/relief/relief_map.h"
#include "dressed_human/core/relief/relief_sample.h"
#include "dressed_human/core/relief/skin_cell_hierarchy.h"
#include "dressed_human/core/relief/skin_relief_parameters.h"
#include "dressed_human/core/relief/skin_relief_rasterizer.h"
#include "dressed_human/core/relief/skin_relief_sampler.h"

#include <memory>
#include <vector>

namespace dressed_human {

class SkinRelief {
 public:
  /// Builds the cell hierarchy. Throws std::invalid_argument naming a bad parameter.
  explicit SkinRelief(const SkinReliefParameters& parameters);

  const SkinReliefParameters& parameters() const { return parameters_; }
  int levelCount() const { return hierarchy_->levelCount(); }
  std::size_t cellCount(int level) const { return levelAt(level).cells.size(); }
  /// Parent index on level - 1 (-1 on level 0). Levels are numbered from 0 here.
  int parentOf(int level, int cell) const { return hierarchy_->parentOf(level, cell); }
  const std::vector<int>& childrenOf(int level, int cell) const { return hierarchy_->childrenOf(level, cell); }
  const skin_detail::CellLevel& levelAt(int level) const { return hierarchy_->levelAt(level); }

  /// Height and gradient at tile point p (any real coordinates; wrapped into the tile), summed
  /// over levels [0, level_limit) (level_limit < 0 = all).
  ReliefSample sample(const Eigen::Vector2d& point, int level_limit = -1) const;
  /// Only one level's contribution (the cells are still found through their parents).
  ReliefSample sampleLevel(const Eigen::Vector2d& point, int level) const;
  /// Cell index per level containing the point (after the wobble).
  std::vector<int> cellsAt(const Eigen::Vector2d& point) const;

  /// Agreement with the reference (renderBruteForce(), the original per-pixel evaluation with
  /// every seed scanned), checked in test_skin_relief.cpp at 256^2.
  /// sample(), sampleLevel(), cellsAt() and render() with roundness > 0 take the per-pixel fast
  /// path: the reference's decisions in the same order with precomputed reciprocals, so only
  /// rounding differs -- |height difference| <= kReferenceHeightTolerance (1e-9 tile units, far
  /// below float resolution of the stored map) at every pixel, slopes within
  /// kReferenceSlopeTolerance.
  /// render() with roundness 0 rasterises cells (skin_relief_rasterizer.h). Its s is the
  /// reference's own (same wall, same segment, same gradient per angular sector), but which cell
  /// owns a pixel follows the cell's boundary polygon, and near corners, where two walls' wobbled
  /// polylines cross, that differs from the reference's nearest-seed-then-one-wobble-flip rule
  /// (two cells' polygons overlap, or leave a sliver the per-pixel path fills). So a few pixels
  /// next to a cell border take the neighbouring cell's height. Measured at 256^2 (after
  /// coincident child seeds were merged, skin_cell_hierarchy.cpp): 0.0092 % of pixels at the
  /// benchmark's parameters, 0.0122 % stretched (2.2), 0.0854 % with the strongest wobble (0.3,
  /// 16 segments, roughness 0.8), none with straight walls; largest height difference 0.035,
  /// 0.017 and 0.334 of the deepest level's depth. The bounds below are those worst cases
  /// rounded up (0.1 %, 0.35); a map shifted by one pixel or with another seed's cells on one
  /// level differs at > 90 % of pixels. Slopes of the pixels whose height agrees are within
  /// kReferenceSlopeTolerance (measured: equal -- both sum the levels in double, round once).
  static constexpr double kReferenceHeightTolerance = 1e-9;
  static constexpr double kReferenceSlopeTolerance = 1e-5;
  static constexpr double kReferenceDifferingFraction = 0.001;  ///< raster render(): pixels beyond 1e-9
  /// raster render(): largest |height difference|, as a fraction of the deepest level's depth
  /// (level_depth[l] * level spacing).
  static constexpr double kReferenceLargestHeightDifference = 0.35;

  /// Render the tile at pixel centres ((column + 0.5) / width, (row + 0.5) / height).
  /// only_level >= 0 renders that level alone (the levels above still decide ownership).
  /// Roundness 0: the cell rasteriser; roundness > 0 (q-norm over walls, not piecewise linear)
  /// and cells wider than the tile: the per-pixel fast path, level-1 cells from the bucket grid.
  ReliefMap render(int width, int height, int only_level = -1) const;
  /// Same map with level-1 cells found by scanning every seed and its 9 periodic images, and
  /// children by scanning every seed of the level (keeping those of the pixel's parent): the
  /// brute-force nearest-seed reference for tests and the benchmark.
  ReliefMap renderBruteForce(int width, int height) const;

 private:
  SkinReliefParameters parameters_;
  // Shared, immutable: a copy of the SkinRelief shares it with the sampler.
  std::shared_ptr<const SkinCellHierarchy> hierarchy_;
  SkinReliefSampler sampler_;
  SkinReliefRasterizer rasterizer_;
};

}  // namespace dressed_human
