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
// Two evaluators of that one model:
//  * per pixel (sample(), cellsAt(), render() with roundness > 0): find the pixel's cell level by
//    level (bucket grid, children lists, wobble test), then cast the ray to its walls;
//  * per cell (render() with roundness 0, skin_relief_raster.cpp): with max over walls, s is
//    the ray ratio to one wall segment and so linear inside each angular sector seen from the
//    centre. At construction every cell gets its boundary polygon (wobbled walls; on child levels
//    the parent's wobbled wall pieces) and its sectors with the reference's gradient of s (from
//    the directions where a wall's ray-hit decision can change and the ties between walls, no
//    sampling); render fills each cell's pixels row by row, stepping through the sectors, masked
//    by the parent level's owners. Pixels no cell claims go through the per-pixel path. It differs
//    from the reference only in which cell owns a few pixels along furrows (kReference* below).
#pragma once

#include "dressed_human/core/surfaces/bezier_profile.h"
#include "dressed_human/core/relief/relief_sample.h"
#include "dressed_human/core/relief/relief_map.h"
#include "dressed_human/core/relief/skin_cell_hierarchy.h"

#include <array>
#include <cstdint>
#include <vector>

namespace dressed_human {

struct SkinReliefParameters {
  double cell_size = 1.0 / 12.0;  ///< level-1 seed spacing in tile units, (0, 1]
  int levels = 1;                 ///< hierarchy depth, 1..3
  double child_cell_ratio = 0.4;  ///< child spacing / parent spacing, [0.1, 0.8]
  double jitter = 0.35;           ///< uniform seed displacement, fraction of spacing, [0, 0.5]
  double wobble = 0.12;           ///< midpoint displacement amplitude / wall length, [0, 0.3]
  int wobble_subdivisions = 3;    ///< midpoint-displacement depth, 0..6
  double wobble_roughness = 0.5;  ///< amplitude factor per subdivision, [0, 1]
  BezierProfile profile = BezierProfile::fromEdgeSlope(3.0);  ///< cross-section ("slope")
  double roundness = 0.0;         ///< 0 = polygonal contours, 1 = round, [0, 1]
  double direction_angle = 0.0;   ///< radians from +u, direction the cells are stretched along
  double direction_stretch = 1.0; ///< >= 1, 1 = no directionality
  int directional_levels = 3;     ///< the stretch applies to levels 1..directional_levels
  std::array<double, 3> level_depth{{0.08, 0.05, 0.035}};  ///< relief depth / level spacing, >= 0
  std::uint32_t seed = 1;         ///< RNG seed (std::mt19937): same seed -> same map
};

class SkinRelief {
 public:
  /// Builds the cell hierarchy. Throws std::invalid_argument naming a bad parameter.
  explicit SkinRelief(const SkinReliefParameters& parameters);

  const SkinReliefParameters& parameters() const { return parameters_; }
  int levelCount() const { return static_cast<int>(levels_.size()); }
  std::size_t cellCount(int level) const { return levelAt(level).cells.size(); }
  /// Parent index on level - 1 (-1 on level 0). Levels are numbered from 0 here.
  int parentOf(int level, int cell) const;
  const std::vector<int>& childrenOf(int level, int cell) const;
  const skin_detail::CellLevel& levelAt(int level) const;

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
  /// render() with roundness 0 rasterises cells (skin_relief_raster.cpp). Its s is the
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
  struct Hit {
    int cell = -1;
    Eigen::Vector2i offset = Eigen::Vector2i::Zero();
  };
  // Straight (pre-wobble) hits of the previous pixel, reused while the point stays inside the
  // same cell's bisector half-planes -- consecutive pixels mostly share cells.
  struct RowCache {
    Hit straight[3];
    Hit parent[3];
    bool valid[3] = {false, false, false};
  };
  bool insideStraightCell(int level, const Hit& hit, const Eigen::Vector2d& point) const;
  Hit findLevelZero(const Eigen::Vector2d& point, bool brute_force) const;
  Hit findChild(int level, const Hit& parent, const Eigen::Vector2d& point, bool brute_force) const;
  Hit applyWobble(int level, Hit hit, const Eigen::Vector2d& point) const;
  void accumulate(int level, const Hit& hit, const Eigen::Vector2d& point, ReliefSample& sum) const;
  ReliefSample evaluate(const Eigen::Vector2d& point, int first_level, int end_level, bool brute_force,
                        RowCache* cache = nullptr) const;
  ReliefMap renderWith(int width, int height, int only_level, bool brute_force) const;

  // Rasteriser (render() with roundness 0, skin_relief_raster.cpp): per cell the fan of its
  // wobbled boundary seen from the centre, as angular sectors in counter-clockwise order; inside a
  // sector s = gradient . (p - centre), and the pixel is the cell's if boundary . (p - centre) < 1.
  struct RasterSector {
    double direction_x, direction_y;  // start ray of the sector, from the centre
    double gradient_x, gradient_y;  // of the reference's s (its ray hit, max over walls)
    double boundary_x, boundary_y;  // of the ray ratio to the boundary polygon: < 1 inside
    double crossing_above, crossing_below;  // qx / dy where a pixel row leaves the sector, NaN never
  };
  struct RasterCell {
    double centre_x = 0.0, centre_y = 0.0;
    double low_x = 0.0, low_y = 0.0, high_x = 0.0, high_y = 0.0;  // boundary's bounding box
    int first_sector = 0, sector_count = 0;  // 0: left to the per-pixel path
    int first_vertex = 0, vertex_count = 0;  // boundary polygon, relative to the centre
    int parent = -1;
  };
  struct RasterLevel {
    std::vector<RasterCell> cells;
    std::vector<RasterSector> sectors;
    std::vector<Eigen::Vector2d> vertices;
    double depth = 0.0;
    int most_sectors = 0;  // largest sector_count of its cells (sizes render's per-row runs)
  };
  // One wall's ray hit as the reference computes it (s and its gradient at centre + q, q . n > 0).
  static void wallRayHit(const skin_detail::CellLevel& level, const skin_detail::Wall& wall, const Eigen::Vector2d& q, double& s,
                         Eigen::Vector2d& gradient);
  void buildRasterLevels();
  ReliefMap renderRaster(int width, int height, int only_level) const;

  // Per-pixel fast path (sample, cellsAt, render with roundness > 0, and the pixels the
  // rasteriser leaves unclaimed). Same model as the reference path above (which
  // renderBruteForce keeps), restructured for speed: per-level wall data packed contiguously with
  // the reciprocals and the per-segment wobble constants of the ray hit precomputed, and the
  // wall projections q . n computed once per pixel and level and shared by the straight-cell
  // test, the wobble test and the ray hit.
  struct PackedSegment {
    double numerator = 0.0;          // ray parameter at the hit = numerator / denominator
    double inverse_numerator = 0.0;  // 0 when numerator <= 0 (the reference keeps the straight hit)
    double slope = 0.0;              // outward wobble per unit u
    double start_u = 0.0;            // segment start in u
    double offset = 0.0;             // outward wobble at start_u
    double step = 0.0;               // outward wobble change over the segment
    double gradient_x = 0.0, gradient_y = 0.0;  // gradient of s on this segment
  };
  struct PackedWall {
    double normal_x, normal_y;
    double centre_distance;
    double inverse_distance;  // 1 / centre_distance
    double inverse_outer;     // 1 / (centre_distance + wobble_extent)
    double inverse_inner;     // 1 / (centre_distance - wobble_extent), +inf when that is <= 0
    double wobble_extent;
    double wobble_threshold;  // q . n above this: the wobble test must look at this wall
    double tangent_x, tangent_y;  // unit tangent / length: q . t gives u units
    double centre_u;
    int first_segment;  // into PackedLevel::segments, -1 straight
    int neighbour;
    int neighbour_offset_x, neighbour_offset_y;
  };
  struct PackedCell {
    double centre_x, centre_y;
    int first_wall, wall_count;
  };
  struct PackedLevel {
    std::vector<PackedCell> cells;
    std::vector<PackedWall> walls;
    std::vector<PackedSegment> segments;
    int segment_count = 0;  // per wobbled wall, 2^subdivisions
    double depth = 0.0;
  };
  struct FastHit {
    int cell = -1;
    int offset_x = 0, offset_y = 0;
  };
  struct FastCache {
    FastHit straight[3];
    FastHit parent[3];
    bool valid[3] = {false, false, false};
  };
  struct LevelResult {
    FastHit hit;
    double s = 0.0, gradient_x = 0.0, gradient_y = 0.0;
  };
  void buildPackedLevels();
  void evaluateLevel(int level, double x, double y, const FastHit& parent, FastCache* cache, LevelResult& out) const;
  ReliefSample evaluateFast(double x, double y, int first_level, int end_level, FastCache* cache, int* cells_out = nullptr) const;

  SkinReliefParameters parameters_;
  std::vector<skin_detail::CellLevel> levels_;
  std::vector<PackedLevel> packed_;
  int max_wall_count_ = 0;
  BezierProfileTable profile_table_;
  int roundness_exponent_ = 0;  // 0 = max (polygonal)
  std::vector<RasterLevel> raster_;
  // profile_table_ repacked for the rasteriser's inner loop (skin_relief.cpp): per interval the
  // height and slope lines {height offset, height step, slope offset, slope step}.
  std::vector<double> profile_lines_;
  bool raster_ready_ = false;  // render() rasterises (roundness 0, every cell narrower than the tile)
};

}  // namespace dressed_human
