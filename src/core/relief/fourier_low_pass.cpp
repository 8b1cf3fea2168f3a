#include "dressed_human/core/relief/fourier_low_pass.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

namespace dressed_human {
namespace {

using Complex = std::complex<double>;

// e^(-2 pi i k n / N) for n = 0..N-1 and k = -K..K: the transforms' only trigonometry.
std::vector<Complex> twiddles(int samples, int harmonics) {
  std::vector<Complex> table(static_cast<std::size_t>(samples) * static_cast<std::size_t>(2 * harmonics + 1));
  for (int k = -harmonics; k <= harmonics; ++k) {
    for (int n = 0; n < samples; ++n) {
      const double angle = -2.0 * M_PI * static_cast<double>(k) * static_cast<double>(n) / samples;
      table[static_cast<std::size_t>(k + harmonics) * static_cast<std::size_t>(samples) + static_cast<std::size_t>(n)] =
          Complex(std::cos(angle), std::sin(angle));
    }
  }
  return table;
}

// A Gaussian blur's transfer, down to 1/1000 at the last kept harmonic: the kernel is positive,
// so nothing rings, and what is cut off is below a thousandth.
double taper(int k, int harmonics) {
  const double x = static_cast<double>(k) / static_cast<double>(harmonics);
  return harmonics == 0 ? 1.0 : std::exp(-std::log(1000.0) * x * x);
}

}  // namespace

ReliefMap lowPassRelief(const ReliefMap& tile, int harmonics_u, int harmonics_v, double metres_per_pixel_u,
                        const std::vector<double>& metres_per_pixel_v) {
  const int width = tile.width;
  const int height = tile.height;
  if (harmonics_u < 0 || harmonics_v < 0 || 2 * harmonics_u >= width || 2 * harmonics_v >= height) {
    throw std::invalid_argument("lowPassRelief: harmonics " + std::to_string(harmonics_u) + " x " +
                                std::to_string(harmonics_v) + " must be >= 0 and below half the tile's " +
                                std::to_string(width) + " x " + std::to_string(height) + " pixels");
  }
  const auto physical = [](double size) { return size > 0.0 && std::isfinite(size); };
  if (!physical(metres_per_pixel_u) || metres_per_pixel_v.size() != tile.heights.size() ||
      !std::all_of(metres_per_pixel_v.begin(), metres_per_pixel_v.end(), physical)) {
    throw std::invalid_argument("lowPassRelief: the physical pixel sizes must be positive, one per pixel along v");
  }
  const int ku_count = 2 * harmonics_u + 1;
  const int kv_count = 2 * harmonics_v + 1;
  const std::vector<Complex> along_u = twiddles(width, harmonics_u);
  const std::vector<Complex> along_v = twiddles(height, harmonics_v);
  const auto u_twiddle = [&](int k, int n) { return along_u[static_cast<std::size_t>(k + harmonics_u) * width + n]; };
  const auto v_twiddle = [&](int k, int n) { return along_v[static_cast<std::size_t>(k + harmonics_v) * height + n]; };

  // Analysis, separably: each pixel row's harmonics across u, then those along v.
  std::vector<Complex> rows(static_cast<std::size_t>(height) * ku_count);
  for (int r = 0; r < height; ++r) {
    for (int k = -harmonics_u; k <= harmonics_u; ++k) {
      Complex sum = 0.0;
      for (int c = 0; c < width; ++c) sum += static_cast<double>(tile.heights[tile.index(c, r)]) * u_twiddle(k, c);
      rows[static_cast<std::size_t>(r) * ku_count + (k + harmonics_u)] = sum / static_cast<double>(width);
    }
  }
  std::vector<Complex> coefficients(static_cast<std::size_t>(kv_count) * ku_count);
  for (int kv = -harmonics_v; kv <= harmonics_v; ++kv) {
    for (int ku = 0; ku < ku_count; ++ku) {
      Complex sum = 0.0;
      for (int r = 0; r < height; ++r) sum += rows[static_cast<std::size_t>(r) * ku_count + ku] * v_twiddle(kv, r);
      // Tapered: a plain cut-off rings (Gibbs) around every crease (fourier_low_pass.h).
      coefficients[static_cast<std::size_t>(kv + harmonics_v) * ku_count + ku] =
          sum / static_cast<double>(height) * taper(ku - harmonics_u, harmonics_u) * taper(kv, harmonics_v);
    }
  }

  // Synthesis with the derivatives: d/dn e^(2 pi i k n / N) = (2 pi i k / N) e^(...).
  ReliefMap smooth(width, height);
  std::vector<Complex> row_value(ku_count), row_dv(ku_count);
  for (int r = 0; r < height; ++r) {
    for (int ku = 0; ku < ku_count; ++ku) {
      Complex value = 0.0, dv = 0.0;
      for (int kv = -harmonics_v; kv <= harmonics_v; ++kv) {
        const Complex term =
            coefficients[static_cast<std::size_t>(kv + harmonics_v) * ku_count + ku] * std::conj(v_twiddle(kv, r));
        value += term;
        dv += term * Complex(0.0, 2.0 * M_PI * kv / height);
      }
      row_value[static_cast<std::size_t>(ku)] = value;
      row_dv[static_cast<std::size_t>(ku)] = dv;
    }
    for (int c = 0; c < width; ++c) {
      double h = 0.0, dh_du = 0.0, dh_dv = 0.0;
      for (int k = -harmonics_u; k <= harmonics_u; ++k) {
        const Complex wave = std::conj(u_twiddle(k, c));
        const std::size_t ku = static_cast<std::size_t>(k + harmonics_u);
        h += (row_value[ku] * wave).real();
        dh_du += (row_value[ku] * wave * Complex(0.0, 2.0 * M_PI * k / width)).real();
        dh_dv += (row_dv[ku] * wave).real();
      }
      const std::size_t at = smooth.index(c, r);
      smooth.heights[at] = static_cast<float>(h);
      smooth.slope_u[at] = static_cast<float>(dh_du / metres_per_pixel_u);
      smooth.slope_v[at] = static_cast<float>(dh_dv / metres_per_pixel_v[at]);
    }
  }
  return smooth;
}

}  // namespace dressed_human
