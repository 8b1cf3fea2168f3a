// SkinReliefRasterizer::render (skin_relief_rasterizer.h): the cells' pixels row by row through
// their sectors, in bands of rows, and the per-pixel path for what no cell claims.
#include "dressed_human/core/relief/skin_relief_rasterizer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dressed_human {

using skin_detail::RasterCell;
using skin_detail::RasterLevel;
using skin_detail::RasterSector;

namespace {

// The map is rendered in bands of rows, every level of a band before the next band. Level by
// level over the whole map, each level met its ~20 bytes per pixel of scratch and output long
// evicted from L2 by the level before, a few pixels per row per cell (at 1024^2 the bands took
// about 7 of 57 ms off). A band's scratch and output stay in L2.
// Each pixel still sees the same cells in the same order (levels in turn, cells in index
// order), so the map is the same. (A cell across the tile's top edge now walks its rows from
// the wrapped part on; the row walk ends in the one sector holding the row's first pixel
// whichever sector it starts from -- unless that pixel is exactly the centre, as before.)
constexpr int kBandRows = 16;

// One row of one cell (the band loop): its pixels' sectors as runs, and 1 at each column (from
// the row's first) where a run ends.
struct RowRun {
  double gradient_x, gradient_y, gradient_dy;  // s = gradient_x * qx + gradient_dy
  double boundary_x, boundary_dy;              // inside the boundary: boundary_x * qx + boundary_dy < 1
};

// Per level and cell: its rows (unwrapped) and where their column ranges start in `spans`;
// `sector` carries the row walk's sector from one band to the next.
struct CellRows {
  int row_first = 0, row_last = -1;
  std::size_t first_span = 0;
  int sector = 0;
};

struct LevelRows {
  std::vector<CellRows> cells;
  std::vector<int> spans;       // first and last column per row; first > last: no pixel centre
  std::vector<int> band_start;  // band b's cells: band_cells[band_start[b] .. band_start[b + 1])
  std::vector<int> band_cells;  // in index order within each band
};

// Scratch kept per thread between calls (fresh pages cost page faults and zeroing).
struct RenderScratch {
  // The band's height and slopes, summed in double like the reference and rounded once into the
  // map at the band's end (summed in the map's floats, each band's slopes came back from L3 --
  // the map is 12 MB at 1024^2 -- and were rounded at every level).
  std::vector<double> heights, slopes_u, slopes_v;
  // One owner per pixel of the band, overwritten level by level: cell + code_base of its level,
  // so a child claims a pixel exactly when it still holds its parent's code (-1: nobody's yet).
  std::vector<int> owner;
  std::vector<double> span_low, span_high, vertex_rows;
  std::vector<RowRun> run_buffer;
  std::vector<int> run_end_buffer;
  std::vector<LevelRows> level_rows;
  std::vector<int> cell_bands, band_fill;
};

// Integer ceil / floor: the same integers as std::ceil / std::floor (finite values within a few
// tiles' rows) without the rounding sequences those compile to on baseline x86-64 (SSE2 has no
// roundsd); most edges cross no row, so this runs for nearly every edge of every cell.
inline int ceilToInt(double value) {
  const int truncated = static_cast<int>(value);
  return truncated + (truncated < value ? 1 : 0);
}
inline int floorToInt(double value) {
  const int truncated = static_cast<int>(value);
  return truncated - (truncated > value ? 1 : 0);
}

// Per row of the cell the first and last column of the pixel centres between the boundary's
// outermost crossings, appended to `spans`.
void appendCellSpans(const RasterLevel& level, const RasterCell& cell, int width, int height, const CellRows& cell_rows,
                     std::vector<int>& spans, RenderScratch& scratch) {
  const int row_first = cell_rows.row_first, row_last = cell_rows.row_last;
  const std::size_t rows = static_cast<std::size_t>(row_last - row_first + 1);
  scratch.span_low.assign(rows, INFINITY);
  scratch.span_high.assign(rows, -INFINITY);
  std::vector<double>& span_low = scratch.span_low;
  std::vector<double>& span_high = scratch.span_high;
  std::vector<double>& vertex_rows = scratch.vertex_rows;
  const Eigen::Vector2d* vertices = level.vertices.data() + cell.first_vertex;
  // Each vertex's pixel-space row coordinate once, not once per edge it ends.
  vertex_rows.resize(static_cast<std::size_t>(cell.vertex_count));
  for (int k = 0; k < cell.vertex_count; ++k)
    vertex_rows[static_cast<std::size_t>(k)] = (cell.centre_y + vertices[k].y()) * height - 0.5;
  for (int k = 0; k < cell.vertex_count; ++k) {
    const int k_next = k + 1 == cell.vertex_count ? 0 : k + 1;
    const Eigen::Vector2d& a = vertices[k];
    const Eigen::Vector2d& b = vertices[k_next];
    // Pixel-space rows (y * height - 0.5) crossed by the edge, as in the row loop.
    const double ya = vertex_rows[static_cast<std::size_t>(k)], yb = vertex_rows[static_cast<std::size_t>(k_next)];
    const double y_low = std::min(ya, yb), y_high = std::max(ya, yb);
    const int edge_first = std::max(row_first, ceilToInt(y_low));
    const int edge_last = std::min(row_last, floorToInt(y_high));
    if (edge_last < edge_first) continue;
    const double xa = (cell.centre_x + a.x()) * width - 0.5, xb = (cell.centre_x + b.x()) * width - 0.5;
    const double slope = (xb - xa) / (yb - ya);
    for (int row = edge_first; row <= edge_last; ++row) {
      const double x = xa + (row - ya) * slope;
      const auto slot = static_cast<std::size_t>(row - row_first);
      span_low[slot] = std::min(span_low[slot], x);
      span_high[slot] = std::max(span_high[slot], x);
    }
  }
  spans.resize(cell_rows.first_span + 2 * rows);
  int* span = spans.data() + cell_rows.first_span;
  for (std::size_t slot = 0; slot < rows; ++slot, span += 2) {
    if (!(span_low[slot] <= span_high[slot])) {
      // No boundary crossing, so no pixel of this cell: the row loop skips it.
      span[0] = std::numeric_limits<int>::max();
      span[1] = std::numeric_limits<int>::min();
      continue;
    }
    // A pixel centre rounded the other way from the ownership test is claimed by no cell here
    // and so takes the per-pixel path.
    span[0] = ceilToInt(span_low[slot]);
    span[1] = floorToInt(span_high[slot]);
  }
}

// The level's cells' rows and spans, and per band the cells that have rows in it.
void planLevelRows(const RasterLevel& level, int width, int height, int band_count, LevelRows& rows_out,
                   RenderScratch& scratch) {
  rows_out.cells.assign(level.cells.size(), CellRows());
  rows_out.spans.clear();
  rows_out.band_start.assign(static_cast<std::size_t>(band_count) + 1, 0);
  std::vector<int>& cell_bands = scratch.cell_bands;
  cell_bands.clear();  // (band, cell) pairs in cell order
  for (std::size_t cell_index = 0; cell_index < level.cells.size(); ++cell_index) {
    const RasterCell& cell = level.cells[cell_index];
    if (cell.sector_count == 0) continue;
    // Rows of pixel centres (row + 0.5) / height inside the boundary's extent, unwrapped (the
    // cell's frame).
    const int row_first = static_cast<int>(std::ceil(cell.low_y * height - 0.5));
    const int row_last = static_cast<int>(std::floor(cell.high_y * height - 0.5));
    if (row_last < row_first) continue;
    CellRows& cell_rows = rows_out.cells[cell_index];
    cell_rows.row_first = row_first;
    cell_rows.row_last = row_last;
    cell_rows.first_span = rows_out.spans.size();
    appendCellSpans(level, cell, width, height, cell_rows, rows_out.spans, scratch);
    // The bands the cell's rows fall in, wrapped into the tile (rows are fewer than the
    // tile's, so each wrapped row comes from one unwrapped row).
    const std::size_t pairs_before = cell_bands.size();
    for (int wrap = -1; wrap <= 1; ++wrap) {
      const int low = std::max(row_first, wrap * height), high = std::min(row_last, wrap * height + height - 1);
      if (low > high) continue;
      for (int band = (low - wrap * height) / kBandRows; band <= (high - wrap * height) / kBandRows; ++band) {
        bool seen = false;
        for (std::size_t at = pairs_before; at < cell_bands.size(); at += 2) seen = seen || cell_bands[at] == band;
        if (seen) continue;
        cell_bands.push_back(band);
        cell_bands.push_back(static_cast<int>(cell_index));
        ++rows_out.band_start[static_cast<std::size_t>(band) + 1];
      }
    }
  }
  for (int band = 0; band < band_count; ++band)
    rows_out.band_start[static_cast<std::size_t>(band) + 1] += rows_out.band_start[static_cast<std::size_t>(band)];
  rows_out.band_cells.resize(cell_bands.size() / 2);
  scratch.band_fill.assign(rows_out.band_start.begin(), rows_out.band_start.end() - 1);
  for (std::size_t at = 0; at < cell_bands.size(); at += 2)
    rows_out.band_cells[static_cast<std::size_t>(scratch.band_fill[static_cast<std::size_t>(cell_bands[at])]++)] =
        cell_bands[at + 1];
}

// Where one band's pixels of one level go, and what the level needs to know of the others.
struct BandLevel {
  int band_first, band_last;
  int width, height;
  int code_base, parent_code_base;  // owner codes of this level's and the parent level's cells
  bool masked;                      // a child level: a cell claims only its parent's pixels
  bool accumulate;                  // the level's heights count (else it only decides ownership)
  double depth;
  double inverse_width, inverse_height;
  double profile_last;
  const double* profile_lines;
  double* sums;
  double* slope_u;
  double* slope_v;
  int* owners;
  RowRun* runs;
  int* run_ends;
};

// The sector holding the point (qx, dy) from the centre, walked to from `sector` (the previous
// row's: usually the same or a neighbour).
inline int sectorHolding(const RasterSector* sectors, int sector_count, int sector, double qx, double dy) {
  for (int step = 0; step < 2 * sector_count; ++step) {
    const RasterSector& a = sectors[sector];
    const RasterSector& b = sectors[sector + 1 == sector_count ? 0 : sector + 1];
    if (a.direction_x * dy - a.direction_y * qx < 0.0) {
      sector = sector == 0 ? sector_count - 1 : sector - 1;
    } else if (b.direction_x * dy - b.direction_y * qx >= 0.0) {
      sector = sector + 1 == sector_count ? 0 : sector + 1;
    } else {
      break;
    }
  }
  return sector;
}

// column modulo width. Cells lie within a tile's width of the tile, so mostly no integer
// division is needed.
inline int wrappedColumn(int column, int width) {
  int wrapped = column;
  if (wrapped < 0) wrapped += width;
  if (wrapped >= width) wrapped -= width;
  if (wrapped < 0 || wrapped >= width) wrapped = ((column % width) + width) % width;
  return wrapped;
}

// The level's cells' pixels in the band. The hot loops of the renderer, kept together.
void rasteriseBandLevel(const RasterLevel& level, LevelRows& rows_in, int band, const BandLevel& target) {
  const int band_first = target.band_first, band_last = target.band_last;
  const int width = target.width, height = target.height;
  const double inverse_width = target.inverse_width, inverse_height = target.inverse_height;
  const bool accumulate = target.accumulate;
  const double depth = target.depth;
  const double profile_last = target.profile_last;
  const double* profile_lines = target.profile_lines;
  double* slope_u = target.slope_u;
  double* slope_v = target.slope_v;
  int* owners = target.owners;
  double* sums = target.sums;
  RowRun* const runs = target.runs;
  int* const run_ends = target.run_ends;
  const int* band_cells = rows_in.band_cells.data();
  for (int listed = rows_in.band_start[static_cast<std::size_t>(band)];
       listed < rows_in.band_start[static_cast<std::size_t>(band) + 1]; ++listed) {
    const auto cell_index = static_cast<std::size_t>(band_cells[listed]);
    const RasterCell& cell = level.cells[cell_index];
    CellRows& cell_rows = rows_in.cells[cell_index];
    const int sector_count = cell.sector_count;
    const RasterSector* sectors = level.sectors.data() + cell.first_sector;
    const int code = static_cast<int>(cell_index) + target.code_base;
    const int expected = target.masked ? cell.parent + target.parent_code_base : -1;
    int sector = cell_rows.sector;
    for (int wrap = -1; wrap <= 1; ++wrap) {
      const int row_low = std::max(cell_rows.row_first, band_first + wrap * height);
      const int row_high = std::min(cell_rows.row_last, band_last + wrap * height);
      for (int row = row_low; row <= row_high; ++row) {
        const int* span =
            rows_in.spans.data() + cell_rows.first_span + 2 * static_cast<std::size_t>(row - cell_rows.row_first);
        if (span[0] == std::numeric_limits<int>::max()) continue;
        const int column_first = span[0];
        const int column_last = span[1];
        const std::size_t row_base =
            static_cast<std::size_t>(row - wrap * height - band_first) * static_cast<std::size_t>(width);
        const double dy = (row + 0.5) * inverse_height - cell.centre_y;
        sector = sectorHolding(sectors, sector_count, sector, (column_first + 0.5) * inverse_width - cell.centre_x, dy);
        // Unwrapped columns map to row_base + column + shift; the shift drops by width from
        // wrap_column on, where the row crosses the tile's right edge (rows are narrower than
        // the tile).
        const int column_wrapped_first = wrappedColumn(column_first, width);
        const int wrap_column = column_first + (width - column_wrapped_first);
        const double column_offset = cell.centre_x * width - 0.5;
        // Two passes over the row, so that no branch depends on how many of its pixels a
        // sector holds (at 1024^2 a third of the finest level's sectors hold none of a row's
        // and most of the rest one or two; loops per sector mispredicted about once a sector).
        // 1. Walk the sectors the row crosses, in order (it leaves each through one ray),
        //    keeping one run per sector that holds a pixel -- written unconditionally, the
        //    count advanced by a comparison -- and marking the column after each run's last.
        //    The column where the row leaves a sector is clamped and floored without looking
        //    at the previous sector's, so from one sector to the next only an integer max
        //    depends on the last (not a chain of double <-> int conversions).
        const bool above = dy >= 0.0;
        const double dy_columns = dy * width;
        const double before_row = column_first - 1.0;
        int k = sector, column = column_first, run_count = 0;
        for (int visited = 0; visited < sector_count; ++visited) {
          const RasterSector& here = sectors[k];
          // Column where the row leaves the sector (NaN: it never does).
          const double edge = dy_columns * (above ? here.crossing_above : here.crossing_below) + column_offset;
          const double bounded = std::max(edge < column_last ? edge : static_cast<double>(column_last), before_row);
          const int truncated = static_cast<int>(bounded);
          const int last = std::max(truncated - (bounded < truncated ? 1 : 0), column - 1);
          RowRun& run = runs[run_count];
          run.gradient_x = here.gradient_x;
          run.gradient_y = here.gradient_y;
          run.gradient_dy = here.gradient_y * dy;
          run.boundary_x = here.boundary_x;
          run.boundary_dy = here.boundary_y * dy;
          run_count += last >= column ? 1 : 0;
          run_ends[last + 1 - column_first] = 1;
          column = last + 1;
          if (column > column_last) break;
          // Moving right turns the direction clockwise above the centre (out through the
          // sector's start ray) and counter-clockwise below it (through the next start ray).
          k = above ? (k == 0 ? sector_count : k) - 1 : (k + 1 == sector_count ? 0 : k + 1);
        }
        // Pixels past the last sector visited (a row the walk could not finish): nobody's.
        runs[run_count] = {0.0, 0.0, 0.0, 0.0, INFINITY};
        // 2. The pixels, each in the run the marks before it count to.
        const std::ptrdiff_t shift = static_cast<std::ptrdiff_t>(row_base) + (column_wrapped_first - column_first);
        const int span_width = column_last - column_first + 1;
        run_ends[0] = 0;  // an empty first sector's mark
        int run_index = 0;
        for (int at_column = 0; at_column < span_width; ++at_column) {
          run_index += run_ends[at_column];
          run_ends[at_column] = 0;
          const RowRun& run = runs[run_index];
          const int pixel_column = column_first + at_column;
          const double qx = (pixel_column + 0.5) * inverse_width - cell.centre_x;
          const std::ptrdiff_t at = shift + pixel_column - (pixel_column >= wrap_column ? width : 0);
          // The usual sector has the winning wall's own segment as its boundary: then
          // boundary == gradient and this is s, with the same operations.
          if (!(run.boundary_x * qx + run.boundary_dy < 1.0) || owners[at] != expected)
            continue;  // outside, taken, another parent's
          owners[at] = code;
          const double s = run.gradient_x * qx + run.gradient_dy;
          if (!accumulate || !(s < 1.0)) continue;  // on or past the furrow line: height 0, flat
          // BezierProfileTable::evaluate(1 - s) with s < 1 (so the position is in (0, last]).
          const double position = std::min(1.0 - s, 1.0) * profile_last;
          const double* line = profile_lines + 4 * static_cast<int>(position);
          sums[at] += depth * (line[0] + position * line[1]);
          const double factor = depth * (line[2] + position * line[3]);
          slope_u[at] -= factor * run.gradient_x;
          slope_v[at] -= factor * run.gradient_y;
        }
        run_ends[span_width] = 0;
      }
    }
    cell_rows.sector = sector;
  }
}

// What no cell claimed goes through the per-pixel path (same model as the reference).
void fillUnclaimedPixels(const SkinReliefSampler& sampler, int level_index, std::size_t band_pixels,
                         std::size_t band_base, const BandLevel& target,
                         SkinReliefSampler::FastCache& unclaimed_cache) {
  int* owners = target.owners;
  const int code_base = target.code_base;
  const int width = target.width;
  int cells_out[3] = {-1, -1, -1};
  // Unclaimed pixels come in short runs (slivers along a junction, a fold's pocket): the
  // per-pixel path's cache of the last straight cells finds most of them without a search
  // (its answers do not depend on it).
  for (std::size_t block = 0; block < band_pixels; block += 64) {
    // Blocks of 64 owners, tested with a vectorisable "any below": nearly all are claimed.
    const std::size_t block_end = std::min(block + 64, band_pixels);
    int unclaimed = 0;
    for (std::size_t at = block; at < block_end; ++at) unclaimed |= static_cast<int>(owners[at] < code_base);
    if (unclaimed == 0) continue;
    for (std::size_t at = block; at < block_end; ++at) {
      if (owners[at] >= code_base) continue;
      const std::size_t pixel = band_base + at;
      const int row = static_cast<int>(pixel / static_cast<std::size_t>(width));
      const int column = static_cast<int>(pixel - static_cast<std::size_t>(row) * static_cast<std::size_t>(width));
      const ReliefSample sample = sampler.evaluateFast(
          (column + 0.5) * target.inverse_width, (row + 0.5) * target.inverse_height,
          target.accumulate ? level_index : level_index + 1, level_index + 1, &unclaimed_cache, cells_out);
      owners[at] = cells_out[level_index] + code_base;
      target.sums[at] += sample.height;
      target.slope_u[at] += sample.slope.x();
      target.slope_v[at] += sample.slope.y();
    }
  }
}

}  // namespace

ReliefMap SkinReliefRasterizer::render(const SkinReliefSampler& sampler, int width, int height, int only_level) const {
  ReliefMap map(width, height);  // first: it names a bad size
  const int first = only_level >= 0 ? only_level : 0;
  const int end = only_level >= 0 ? only_level + 1 : static_cast<int>(levels_.size());
  const int band_count = (height + kBandRows - 1) / kBandRows;
  const std::size_t band_capacity = static_cast<std::size_t>(kBandRows) * static_cast<std::size_t>(width);
  thread_local RenderScratch scratch;
  if (scratch.level_rows.size() < static_cast<std::size_t>(end))
    scratch.level_rows.resize(static_cast<std::size_t>(end));
  for (int level_index = 0; level_index < end; ++level_index)
    planLevelRows(levels_[static_cast<std::size_t>(level_index)], width, height, band_count,
                  scratch.level_rows[static_cast<std::size_t>(level_index)], scratch);
  if (scratch.heights.size() < band_capacity) scratch.heights.resize(band_capacity);
  if (scratch.slopes_u.size() < band_capacity) scratch.slopes_u.resize(band_capacity);
  if (scratch.slopes_v.size() < band_capacity) scratch.slopes_v.resize(band_capacity);
  if (scratch.owner.size() < band_capacity) scratch.owner.resize(band_capacity);
  std::size_t most_sectors = 0;
  for (int level_index = 0; level_index < end; ++level_index)
    most_sectors =
        std::max(most_sectors, static_cast<std::size_t>(levels_[static_cast<std::size_t>(level_index)].most_sectors));
  if (scratch.run_buffer.size() < most_sectors + 1) scratch.run_buffer.resize(most_sectors + 1);
  // Rows are narrower than the tile; zero between rows (each row clears what it marked).
  scratch.run_end_buffer.assign(static_cast<std::size_t>(width) + 2, 0);
  BandLevel target;
  target.width = width;
  target.height = height;
  target.inverse_width = 1.0 / width;
  target.inverse_height = 1.0 / height;
  target.profile_last = profile_last_;
  target.profile_lines = profile_lines_.data();
  target.sums = scratch.heights.data();
  target.slope_u = scratch.slopes_u.data();
  target.slope_v = scratch.slopes_v.data();
  target.owners = scratch.owner.data();
  target.runs = scratch.run_buffer.data();
  target.run_ends = scratch.run_end_buffer.data();
  SkinReliefSampler::FastCache unclaimed_cache;
  for (int band = 0; band < band_count; ++band) {
    target.band_first = band * kBandRows;
    target.band_last = std::min(height, target.band_first + kBandRows) - 1;
    const std::size_t band_base = static_cast<std::size_t>(target.band_first) * static_cast<std::size_t>(width);
    const std::size_t band_pixels =
        static_cast<std::size_t>(target.band_last - target.band_first + 1) * static_cast<std::size_t>(width);
    std::fill(scratch.heights.begin(), scratch.heights.begin() + static_cast<std::ptrdiff_t>(band_pixels), 0.0);
    std::fill(scratch.slopes_u.begin(), scratch.slopes_u.begin() + static_cast<std::ptrdiff_t>(band_pixels), 0.0);
    std::fill(scratch.slopes_v.begin(), scratch.slopes_v.begin() + static_cast<std::ptrdiff_t>(band_pixels), 0.0);
    std::fill(scratch.owner.begin(), scratch.owner.begin() + static_cast<std::ptrdiff_t>(band_pixels), -1);
    target.code_base = 0;
    target.parent_code_base = -1;
    for (int level_index = 0; level_index < end; ++level_index) {
      const RasterLevel& level = levels_[static_cast<std::size_t>(level_index)];
      target.masked = level_index > 0;
      target.accumulate = level_index >= first;
      target.depth = level.depth;
      rasteriseBandLevel(level, scratch.level_rows[static_cast<std::size_t>(level_index)], band, target);
      fillUnclaimedPixels(sampler, level_index, band_pixels, band_base, target, unclaimed_cache);
      target.parent_code_base = target.code_base;
      target.code_base += static_cast<int>(level.cells.size());
    }
    for (std::size_t at = 0; at < band_pixels; ++at) {
      map.heights[band_base + at] = static_cast<float>(scratch.heights[at]);
      map.slope_u[band_base + at] = static_cast<float>(scratch.slopes_u[at]);
      map.slope_v[band_base + at] = static_cast<float>(scratch.slopes_v[at]);
    }
  }
  return map;
}

}  // namespace dressed_human
