#pragma once
// The skin relief at its true size on the body (issue 40). The skin map is one periodic tile of
// kSkinCellsPerTile cells (skin_relief.h); each skin patch repeats it a whole number of times
// along u and along v, so that a cell is as large in metres as the skin cells of the patch's body
// region, whatever the patch's size. Whole numbers keep the pattern running on across patch
// seams: the four quarters of a stack share its count along v, and the stacks of a segment share
// each quarter's count around, so the tile meets itself at every seam inside a segment (the tile
// wraps). Where two segments meet (a joint ring) the counts may differ and the cells are cut.
//
// The regions and their measured cell sizes are kSkinRegions (skin_relief_tiling.cpp, with the
// sources); a user scales all of them by one factor through the size of the forearm's cells.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "dressed_human/core/surfaces/skin.h"

namespace dressed_human {

// Level-1 cells across the skin map's tile (its SkinReliefParameters::cell_size is the inverse):
// the map's cell count before issue 40, so a cell keeps 43 pixels of the 512-pixel map and the map
// costs what it did. A patch narrower than a tile still takes a whole one (its cells smaller than
// its region's): a cell size larger than a twelfth of a patch gives the former look, 12 cells a patch.
constexpr int kSkinCellsPerTile = 12;

struct SkinRegion {
  std::string name;
  std::vector<std::string> bones;  // skin segments (bone names, "body" for the pelvis region)
  double cell_area_mm2;            // mean area of one skin cell (皮野) bounded by primary furrows
  std::string source;              // where the area comes from
};

// The body regions, the forearm first; a segment in none of them takes the last ("body").
const std::vector<SkinRegion>& skinRegions();

// Seed lattice spacing (m) of cells of `area_mm2` on the triangular lattice the skin relief uses
// (area = sqrt(3)/2 spacing^2).
double cellSpacingForArea(double area_mm2);

class SkinReliefTiling {
 public:
  // The measured forearm's level-1 seed spacing (m): cellSpacingForArea of its cell area.
  static double measuredForearmSpacing();

  // Lengths from `skin`'s patches as they are (build it at rest), tiled for the measured sizes.
  explicit SkinReliefTiling(const Skin& skin);
  // `forearm_cell_spacing`: level-1 seed spacing on the forearm (m); the other regions keep
  // their measured ratio to the forearm's. Throws std::invalid_argument for a spacing that is
  // not positive and finite.
  void setForearmCellSpacing(double forearm_cell_spacing);

  // Per skin patch: how many tiles it repeats along u and along v (whole numbers >= 1).
  const std::vector<Eigen::Vector2f>& tilesPerPatch() const { return tiles_; }
  // Per skin patch: its level-1 cell spacing in metres along u and along v, as tiled.
  Eigen::Vector2d cellSpacing(std::size_t patch) const;
  // The largest wanted cell spacing of any region (m): what decides whether the relief shows.
  double largestCellSpacing() const { return largest_spacing_; }
  // The region (index into skinRegions()) of each skin segment.
  int segmentRegion(std::size_t segment) const { return segment_region_.at(segment); }

 private:
  std::vector<SkinSegment> segments_;
  std::vector<Eigen::Vector2f> tiles_;
  std::vector<Eigen::Vector2d> lengths_;  // per patch: mid-line length along u and along v (m)
  std::vector<int> segment_region_;
  double largest_spacing_ = 0.0;
};

}  // namespace dressed_human
