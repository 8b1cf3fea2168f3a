#include "dressed_human/core/relief/wrinkle_map.h"

#include "dressed_human/core/relief/buckling_chain.h"
#include "dressed_human/core/relief/fourier_low_pass.h"
#include "dressed_human/core/relief/gaussian_fold_fit.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace dressed_human {
namespace {

double rmsAboutMean(const std::vector<float>& values) {
  double sum = 0.0, squares = 0.0;
  for (const float value : values) {
    sum += value;
    squares += static_cast<double>(value) * value;
  }
  const double n = static_cast<double>(values.size());
  return n > 0.0 ? std::sqrt(std::max(0.0, squares / n - (sum / n) * (sum / n))) : 0.0;
}

void requirePositive(int value, const char* name) {
  if (value <= 0) {
    std::ostringstream message;
    message << "WrinkleMapSpec." << name << " must be > 0, got " << value;
    throw std::invalid_argument(message.str());
  }
}

double alphaOfCell(const WrinkleMapSpec& spec, int row, int column) {
  const std::size_t count = spec.alpha.size();
  if (count == 1) return spec.alpha[0];
  if (count == static_cast<std::size_t>(spec.rows)) return spec.alpha[static_cast<std::size_t>(row)];
  return spec.alpha[static_cast<std::size_t>(row) * static_cast<std::size_t>(spec.cells_around) +
                    static_cast<std::size_t>(column)];
}

// A cell's surface, built once per distinct (pattern, orientation, alpha).
struct CellSurface {
  std::unique_ptr<BucklingPattern> pattern;
  std::shared_ptr<const GaussianFoldApproximation> gaussians;
  ReliefSample sample(double x, double y) const {
    return gaussians ? gaussians->sample(x, y) : pattern->sampleFootprint(x, y);
  }
};

// Gaussian fits outlive one map: a fit costs tens of milliseconds and depends only on the
// pattern (kind, orientation, alpha, cell, out-of-domain policy) and the term count, and a pose
// sequence keeps returning to the same alphas. Keyed by the exact alpha, so a cached fit is the
// fit that would be computed. Bounded: emptied when full, as alphas from continuous compression
// need not repeat.
// One cell's pattern within a map: its kind, the side a Y splits to, its compression.
struct CellPatternKey {
  PatternKind kind;
  bool split_on_right;
  double alpha;
  auto tied() const { return std::tie(kind, split_on_right, alpha); }
  bool operator<(const CellPatternKey& other) const { return tied() < other.tied(); }
};

// A pattern across maps: the cell's, in a cell of that size, fitted with that many terms.
struct FitKey {
  CellPatternKey cell;
  double half_width_x, half_length_y;
  OutOfDomainPolicy out_of_domain;
  int terms;
  auto tied() const {
    return std::tie(cell.kind, cell.split_on_right, cell.alpha, half_width_x, half_length_y, out_of_domain, terms);
  }
  bool operator<(const FitKey& other) const { return tied() < other.tied(); }
};

std::shared_ptr<const GaussianFoldApproximation> cachedGaussianFit(const BucklingPattern& pattern, const FitKey& key) {
  constexpr std::size_t kMaximumFits = 256;
  static std::mutex mutex;
  static std::map<FitKey, std::shared_ptr<const GaussianFoldApproximation>> fits;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    const auto found = fits.find(key);
    if (found != fits.end()) return found->second;
  }
  auto fit = std::make_shared<const GaussianFoldApproximation>(fitGaussians(pattern, key.terms));  // outside the lock
  const std::lock_guard<std::mutex> lock(mutex);
  if (fits.size() >= kMaximumFits) fits.clear();
  fits.emplace(key, fit);
  return fit;
}

// exp(-2 pi^2 sigma^2 k^2) = 1/1000 at k = kBlurTimesHarmonics / sigma (fourier_low_pass.cpp's taper).
const double kBlurTimesHarmonics = std::sqrt(std::log(1000.0) / (2.0 * M_PI * M_PI));
}  // namespace

int smoothHarmonicsForBlur(double blur_cells) {
  if (!(blur_cells > 0.0) || !std::isfinite(blur_cells)) {
    std::ostringstream message;
    message << "fold blur must be finite and > 0 cells, got " << blur_cells;
    throw std::invalid_argument(message.str());
  }
  return std::max(1, static_cast<int>(std::ceil(kBlurTimesHarmonics / blur_cells - 1e-9)));
}

double smoothFoldBlur(int harmonics_per_cell) { return kBlurTimesHarmonics / harmonics_per_cell; }

ReliefMap makeWrinkleMap(const WrinkleMapSpec& spec) {
  requirePositive(spec.width_pixels, "width_pixels");
  requirePositive(spec.height_pixels, "height_pixels");
  requirePositive(spec.cells_around, "cells_around");
  requirePositive(spec.rows, "rows");
  const std::size_t cell_count = static_cast<std::size_t>(spec.rows) * static_cast<std::size_t>(spec.cells_around);
  if (spec.alpha.size() != 1 && spec.alpha.size() != static_cast<std::size_t>(spec.rows) &&
      spec.alpha.size() != cell_count) {
    std::ostringstream message;
    message << "WrinkleMapSpec.alpha must hold 1, rows (" << spec.rows << ") or rows*cells_around (" << cell_count
            << ") values, got " << spec.alpha.size();
    throw std::invalid_argument(message.str());
  }
  for (double alpha : spec.alpha) {
    if (!(alpha > 0.0 && alpha <= 1.0)) {
      std::ostringstream message;
      message << "WrinkleMapSpec.alpha values must be in (0, 1], got " << alpha;
      throw std::invalid_argument(message.str());
    }
  }
  if (!(spec.amplitude >= 0.0) || !std::isfinite(spec.amplitude)) {
    std::ostringstream message;
    message << "WrinkleMapSpec.amplitude must be finite and >= 0, got " << spec.amplitude;
    throw std::invalid_argument(message.str());
  }
  if (spec.surface == WrinkleSurface::gaussianApproximation) requirePositive(spec.gaussian_terms, "gaussian_terms");
  if (spec.surface == WrinkleSurface::smoothFolds) {
    requirePositive(spec.smooth_harmonics_per_cell, "smooth_harmonics_per_cell");
    if (spec.smooth_harmonics_along_folds < 0) {
      std::ostringstream message;
      message << "WrinkleMapSpec.smooth_harmonics_along_folds must be >= 0 (0: as smooth_harmonics_per_cell), got "
              << spec.smooth_harmonics_along_folds;
      throw std::invalid_argument(message.str());
    }
  }

  std::string around;
  for (int column = 0; column < spec.cells_around; ++column)
    around += spec.chain[static_cast<std::size_t>(column) % spec.chain.size()];
  const std::vector<ChainCell> oriented = orientChain(around, true);

  // Build each distinct cell surface once: fits cost milliseconds, pixels must not.
  std::map<CellPatternKey, CellSurface> surfaces;
  std::vector<const CellSurface*> cell_surfaces(cell_count);
  for (int row = 0; row < spec.rows; ++row) {
    for (int column = 0; column < spec.cells_around; ++column) {
      const ChainCell& entry = oriented[static_cast<std::size_t>(column)];
      const bool split_on_right = entry.kind == PatternKind::Y && entry.split_right;
      const double alpha = alphaOfCell(spec, row, column);
      const CellPatternKey key{entry.kind, split_on_right, alpha};
      auto found = surfaces.find(key);
      if (found == surfaces.end()) {
        CellSurface surface;
        surface.pattern =
            std::make_unique<BucklingPattern>(entry.kind, alpha, spec.cell, spec.out_of_domain, split_on_right);
        if (spec.surface == WrinkleSurface::gaussianApproximation) {
          const FitKey fit_key{key, spec.cell.half_width_x, spec.cell.half_length_y, spec.out_of_domain,
                               spec.gaussian_terms};
          surface.gaussians = cachedGaussianFit(*surface.pattern, fit_key);
        }
        found = surfaces.emplace(key, std::move(surface)).first;
      }
      cell_surfaces[static_cast<std::size_t>(row) * static_cast<std::size_t>(spec.cells_around) +
                    static_cast<std::size_t>(column)] = &found->second;
    }
  }

  ReliefMap map(spec.width_pixels, spec.height_pixels);
  const double lx = spec.cell.half_width_x;
  const double ly = spec.cell.half_length_y;
  const double cells_per_pixel_u = static_cast<double>(spec.cells_around) / spec.width_pixels;
  const double cells_per_pixel_v = static_cast<double>(spec.rows) / spec.height_pixels;
  for (int pixel_row = 0; pixel_row < spec.height_pixels; ++pixel_row) {
    const double v = (pixel_row + 0.5) * cells_per_pixel_v;
    const int row = std::min(static_cast<int>(v), spec.rows - 1);
    const double rest_y = (v - row - 0.5) * 2.0 * ly;
    for (int pixel_column = 0; pixel_column < spec.width_pixels; ++pixel_column) {
      const double u = (pixel_column + 0.5) * cells_per_pixel_u;
      const int column = std::min(static_cast<int>(u), spec.cells_around - 1);
      const CellSurface& surface =
          *cell_surfaces[static_cast<std::size_t>(row) * static_cast<std::size_t>(spec.cells_around) +
                         static_cast<std::size_t>(column)];
      const double x = (u - column - 0.5) * 2.0 * lx;
      const double y = rest_y * surface.pattern->solution().alpha;
      const ReliefSample sample = surface.sample(x, y);
      const std::size_t at = map.index(pixel_column, pixel_row);
      map.heights[at] = static_cast<float>(spec.amplitude * sample.height);
      map.slope_u[at] = static_cast<float>(spec.amplitude * sample.slope.x());
      map.slope_v[at] = static_cast<float>(spec.amplitude * sample.slope.y());
    }
  }
  if (spec.surface != WrinkleSurface::smoothFolds) return map;
  // A pixel row of a cell row compressed to alpha spans 2 alpha L_y / (pixels per cell row).
  std::vector<double> metres_per_pixel_v(map.heights.size());
  for (int pixel_row = 0; pixel_row < spec.height_pixels; ++pixel_row) {
    const int row = std::min(static_cast<int>((pixel_row + 0.5) * cells_per_pixel_v), spec.rows - 1);
    for (int pixel_column = 0; pixel_column < spec.width_pixels; ++pixel_column) {
      const int column = std::min(static_cast<int>((pixel_column + 0.5) * cells_per_pixel_u), spec.cells_around - 1);
      metres_per_pixel_v[map.index(pixel_column, pixel_row)] =
          2.0 * ly *
          cell_surfaces[static_cast<std::size_t>(row * spec.cells_around + column)]->pattern->solution().alpha *
          cells_per_pixel_v;
    }
  }
  const int along_folds = spec.smooth_harmonics_along_folds > 0
                              ? std::min(spec.smooth_harmonics_along_folds, spec.smooth_harmonics_per_cell)
                              : spec.smooth_harmonics_per_cell;
  ReliefMap smooth = lowPassRelief(map, along_folds * spec.cells_around, spec.smooth_harmonics_per_cell * spec.rows,
                                   2.0 * lx * cells_per_pixel_u, metres_per_pixel_v);
  if (spec.keep_depth) {
    const double exact = rmsAboutMean(map.heights), blurred = rmsAboutMean(smooth.heights);
    const float gain = blurred > 0.0 ? static_cast<float>(exact / blurred) : 1.0f;
    for (std::vector<float>* values : {&smooth.heights, &smooth.slope_u, &smooth.slope_v}) {
      for (float& value : *values) value *= gain;
    }
  }
  return smooth;
}

}  // namespace dressed_human
