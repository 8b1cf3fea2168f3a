#pragma once
// A periodic relief tile blurred through its own Fourier series: its harmonics up to
// `harmonics_u` across u and `harmonics_v` along v (of the tile's period), weighted by a Gaussian
// blur's transfer that falls to 1/1000 at the last one, summed back with their exact derivatives.
// For the buckling folds this is the smooth surface the seed paper renders instead of the creased
// exact one (SPEC §4): the tile repeats and wraps, so the sum of its own periodic harmonics meets
// itself without seams; the Gaussian kernel is positive, so the creases soften without ringing
// (a plain cut-off, or a raised-cosine taper of the top harmonics, leaves ripples in the slopes
// that run across the whole tile and show in the shading).
//
// Heights keep the tile's units; slopes are per physical length: `metres_per_pixel_u` across u,
// and `metres_per_pixel_v` per pixel (row-major, like the heights), since a compressed row of
// cells is shorter in space than in pixels.

#include <vector>

#include "dressed_human/core/relief/relief_map.h"

namespace dressed_human {

/// Throws std::invalid_argument for negative harmonics, harmonics at or beyond half the tile's
/// pixels (they would alias), or physical pixel sizes that are not positive and finite.
ReliefMap lowPassRelief(const ReliefMap& tile, int harmonics_u, int harmonics_v, double metres_per_pixel_u,
                        const std::vector<double>& metres_per_pixel_v);

}  // namespace dressed_human
