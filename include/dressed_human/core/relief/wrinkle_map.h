// Wrinkle relief map from buckling patterns (SPEC §4): a grid of buckling cells, `cells_around`
// across u (periodic: the map wraps around a limb) and `rows` along v (the compression axis,
// e.g. along the bone), each with its own compression alpha.
//
// This is the interface for the (not yet written) wrinkle placement: measure compression per
// garment region, turn it into alpha per cell, call makeWrinkleMap. Placement itself -- which
// regions, which chain -- is the caller's.
//
// Layout: every row of cells takes the same band of pixels whatever its alpha (the map lives in
// the garment's material/texture coordinates); inside a cell, footprint y = alpha * rest y, so a
// more compressed row shows the same number of wrinkles with higher relief. Heights and slopes are
// in the posed (compressed) physical frame of the cell (units of L_x, L_y), so the normal map is
// the true fold normal for the posed garment. Cells meet continuously when neighbours share alpha;
// between two cells of different alpha along u the fold heights differ (a step of |dh1| at the
// joint), so callers should vary alpha smoothly or per row. Rows always meet at height 0.
#pragma once

#include "dressed_human/core/relief/buckling_pattern.h"
#include "dressed_human/core/relief/relief_map.h"

#include <string>
#include <vector>

namespace dressed_human {

enum class WrinkleSurface {
  exactFolds,             ///< the piecewise-planar folds (creased normals)
  gaussianApproximation,  ///< the seed's smooth Gaussian approximation (fit per distinct alpha)
  smoothFolds,            ///< the exact tile blurred through its own Fourier series (fourier_low_pass.h)
};

struct WrinkleMapSpec {
  int width_pixels = 512;
  int height_pixels = 512;
  BucklingCell cell;        ///< rest L_x, L_y of every cell
  std::string chain = "X";  ///< pattern sequence repeated across u ("X", "YY", "YXY", "I", ...)
  int cells_around = 8;     ///< cells across u; the repeated chain must close periodically
  int rows = 4;             ///< cells along v
  /// Compression per cell, row-major (rows x cells_around); a single value applies to all cells,
  /// `rows` values apply per row. alpha = 1 flat, smaller = more compressed (buckling_solution.h).
  std::vector<double> alpha{0.7};
  OutOfDomainPolicy out_of_domain = OutOfDomainPolicy::clampToDomainEdge;
  WrinkleSurface surface = WrinkleSurface::exactFolds;
  int gaussian_terms = 8;
  /// smoothFolds: harmonics kept per cell, across u and along v, the last at 1/1000 of a Gaussian
  /// blur (of 0.59 / harmonics cells); 20 is the fewest even count that keeps the RMS error within
  /// 5 % of h1 for I, Y and X at alpha 0.6 and 0.8 (docs/relief/smooth_fold_rms_vs_harmonics.png).
  int smooth_harmonics_per_cell = 20;
  /// smoothFolds: harmonics kept per cell across u (along the folds, which run across the
  /// compression along v) if fewer than smooth_harmonics_per_cell: the folds blurred more along
  /// their length than across it (0: as smooth_harmonics_per_cell).
  int smooth_harmonics_along_folds = 0;
  /// smoothFolds: scaled back to the exact folds' RMS height (about its mean): softer fabric
  /// rounds its creases, it does not fold shallower.
  bool keep_depth = false;
  double amplitude = 1.0;  ///< scales relief (heights and slopes), >= 0
};

/// smoothFolds' harmonics per cell for a Gaussian blur of `blur_cells` standard deviation (in
/// cells, > 0): the fewest whose last is cut at 1/1000 of the blur's transfer, so the blur is
/// 0.59 / harmonics cells, at most `blur_cells`. Throws std::invalid_argument for a blur that is
/// not positive and finite.
int smoothHarmonicsForBlur(double blur_cells);
/// The blur (cells) `harmonics_per_cell` harmonics stand for.
double smoothFoldBlur(int harmonics_per_cell);

/// Throws std::invalid_argument naming the bad field (sizes, alpha count or range, chain that
/// does not close around u, amplitude).
ReliefMap makeWrinkleMap(const WrinkleMapSpec& spec);

}  // namespace dressed_human
