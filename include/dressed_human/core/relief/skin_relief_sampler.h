// Point evaluation of the skin relief (SkinRelief, skin_relief.h): height and slope at a point,
// the cells that hold it, and per-pixel maps -- the path for roundness > 0, for the pixels the
// rasteriser (skin_relief_rasterizer.h) leaves unclaimed, and the brute-force reference.
//
// Two evaluators of one model, both here:
//  * the reference (skin_relief_reference.cpp): find the point's cell level by level (bucket grid
//    or every seed, children lists, wobble test), then cast the ray to its walls;
//  * the fast path (skin_relief_sampler.cpp): the reference's decisions in the same order, with
//    per-level wall data packed contiguously, reciprocals and per-segment wobble constants
//    precomputed, and the wall projections q . n computed once per point and level and shared
//    by the straight-cell test, the wobble test and the ray hit.
#pragma once

#include "dressed_human/core/relief/relief_map.h"
#include "dressed_human/core/relief/relief_sample.h"
#include "dressed_human/core/relief/skin_cell_hierarchy.h"

#include <memory>
#include <vector>

namespace dressed_human {

class SkinReliefSampler {
 public:
  SkinReliefSampler(std::shared_ptr<const SkinCellHierarchy> hierarchy, const SkinReliefParameters& parameters);

  /// Height and gradient at tile point p (any real coordinates; wrapped into the tile), summed
  /// over levels [first_level, end_level); the cells are found through every level above.
  ReliefSample sample(const Eigen::Vector2d& point, int first_level, int end_level) const;
  /// Cell index per level containing the point (after the wobble).
  std::vector<int> cellsAt(const Eigen::Vector2d& point) const;
  /// Pixel by pixel at pixel centres; brute_force: the reference with every seed scanned.
  ReliefMap render(int width, int height, int only_level, bool brute_force) const;

  // What the rasteriser needs of the point evaluation.
  /// The fast path serves every cell (else the reference path does, cells of many walls).
  bool packed() const { return max_wall_count_ <= kMaxPackedWalls; }
  int maxWallCount() const { return max_wall_count_; }
  int roundnessExponent() const { return roundness_exponent_; }  ///< 0 = max over walls (polygonal)
  const BezierProfileTable& profileTable() const { return profile_table_; }
  /// One wall's ray hit as the reference computes it (s and its gradient at centre + q, q . n > 0).
  static void wallRayHit(const skin_detail::CellLevel& level, const skin_detail::Wall& wall, const Eigen::Vector2d& q,
                         double& s, Eigen::Vector2d& gradient);

  struct FastHit {
    int cell = -1;
    int offset_x = 0, offset_y = 0;
  };
  // Straight (pre-wobble) hits of the previous point, reused while the point stays inside the
  // same cell's bisector half-planes -- consecutive pixels mostly share cells. Answers do not
  // depend on it.
  struct FastCache {
    FastHit straight[3];
    FastHit parent[3];
    bool valid[3] = {false, false, false};
  };
  /// The fast path at a wrapped point (x, y in [0, 1)); cells_out, if given, gets each level's cell.
  ReliefSample evaluateFast(double x, double y, int first_level, int end_level, FastCache* cache,
                            int* cells_out = nullptr) const;

 private:
  // Cells of more walls than this take the reference path (a Voronoi cell of a jittered
  // triangular lattice, even clipped by its parent, has far fewer).
  static constexpr int kMaxPackedWalls = 64;

  // Reference path (skin_relief_reference.cpp).
  struct Hit {
    int cell = -1;
    Eigen::Vector2i offset = Eigen::Vector2i::Zero();
  };
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

  // Fast path (skin_relief_sampler.cpp).
  struct PackedSegment {
    double numerator = 0.0;                     // ray parameter at the hit = numerator / denominator
    double inverse_numerator = 0.0;             // 0 when numerator <= 0 (the reference keeps the straight hit)
    double slope = 0.0;                         // outward wobble per unit u
    double start_u = 0.0;                       // segment start in u
    double offset = 0.0;                        // outward wobble at start_u
    double step = 0.0;                          // outward wobble change over the segment
    double gradient_x = 0.0, gradient_y = 0.0;  // gradient of s on this segment
  };
  struct PackedWall {
    double normal_x, normal_y;
    double centre_distance;
    double inverse_distance;  // 1 / centre_distance
    double inverse_outer;     // 1 / (centre_distance + wobble_extent)
    double inverse_inner;     // 1 / (centre_distance - wobble_extent), +inf when that is <= 0
    double wobble_extent;
    double wobble_threshold;      // q . n above this: the wobble test must look at this wall
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
  // The point's cell on one level and the point seen from its centre.
  struct EnteredCell {
    FastHit hit;
    const PackedCell* cell = nullptr;
    const PackedWall* walls = nullptr;
    double qx = 0.0, qy = 0.0;
    bool near_wobble = false;            // some wall's wobble test can move the point
    double projection[kMaxPackedWalls];  // q . n per wall
  };
  struct LevelResult {
    FastHit hit;
    double s = 0.0, gradient_x = 0.0, gradient_y = 0.0;
  };
  void buildPackedLevels();
  void locateCell(int level, double x, double y, const FastHit& parent, FastCache* cache, EnteredCell& entered) const;
  void rayParameter(const PackedLevel& level, const EnteredCell& entered, LevelResult& out) const;
  void evaluateLevel(int level, double x, double y, const FastHit& parent, FastCache* cache, LevelResult& out) const;

  static double integerPower(double base, int exponent) {
    double result = 1.0;
    while (exponent > 0) {
      if (exponent & 1) result *= base;
      base *= base;
      exponent >>= 1;
    }
    return result;
  }

  std::shared_ptr<const SkinCellHierarchy> hierarchy_;
  std::vector<PackedLevel> packed_;
  int max_wall_count_ = 0;
  BezierProfileTable profile_table_;
  int roundness_exponent_ = 0;  // 0 = max (polygonal)
};

}  // namespace dressed_human
