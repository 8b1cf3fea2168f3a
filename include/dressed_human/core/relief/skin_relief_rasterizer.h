// The skin relief's map renderer for polygonal contours (roundness 0): each cell rasterised from
// its centre as angular sectors instead of searching the cell of every pixel (SkinRelief::render,
// skin_relief.h; why this gives the reference's heights: skin_relief_rasterizer.cpp).
//
// Construction (skin_relief_rasterizer.cpp): per cell the fan of its wobbled boundary
// (skin_cell_boundary.h) seen from the centre, as angular sectors in counter-clockwise order;
// inside a sector s = gradient . (p - centre), and the pixel is the cell's if
// boundary . (p - centre) < 1. Rendering (skin_relief_raster_render.cpp): each cell's pixels row by
// row, stepping through the sectors, masked by the parent level's owners; the pixels no cell
// claims go through the sampler's per-pixel path.
#pragma once

#include "dressed_human/core/relief/relief_map.h"
#include "dressed_human/core/relief/skin_cell_hierarchy.h"
#include "dressed_human/core/relief/skin_relief_sampler.h"

#include <vector>

namespace dressed_human {
namespace skin_detail {

struct RasterSector {
  double direction_x, direction_y;        // start ray of the sector, from the centre
  double gradient_x, gradient_y;          // of the reference's s (its ray hit, max over walls)
  double boundary_x, boundary_y;          // of the ray ratio to the boundary polygon: < 1 inside
  double crossing_above, crossing_below;  // qx / dy where a pixel row leaves the sector, NaN never
};

struct RasterCell {
  double centre_x = 0.0, centre_y = 0.0;
  double low_x = 0.0, low_y = 0.0, high_x = 0.0, high_y = 0.0;  // boundary's bounding box
  int first_sector = 0, sector_count = 0;                       // 0: left to the per-pixel path
  int first_vertex = 0, vertex_count = 0;                       // boundary polygon, relative to the centre
  int parent = -1;
};

struct RasterLevel {
  std::vector<RasterCell> cells;
  std::vector<RasterSector> sectors;
  std::vector<Eigen::Vector2d> vertices;
  double depth = 0.0;
  int most_sectors = 0;  // largest sector_count of its cells (sizes render's per-row runs)
};

}  // namespace skin_detail

class SkinReliefRasterizer {
 public:
  /// Builds every cell's sectors from the hierarchy the sampler evaluates.
  SkinReliefRasterizer(const SkinCellHierarchy& hierarchy, const SkinReliefSampler& sampler);

  /// Whether render() serves these parameters: roundness 0 and every cell narrower than the tile.
  bool ready() const { return ready_; }
  /// The map at pixel centres, as SkinRelief::render; `sampler` is the one given at construction
  /// (it fills the pixels no cell claims).
  ReliefMap render(const SkinReliefSampler& sampler, int width, int height, int only_level) const;

 private:
  std::vector<skin_detail::RasterLevel> levels_;
  // The sampler's profile table repacked for the inner loop: per interval the height and slope
  // lines {height offset, height step, slope offset, slope step}.
  std::vector<double> profile_lines_;
  double profile_last_ = 0.0;
  bool ready_ = false;
};

}  // namespace dressed_human
