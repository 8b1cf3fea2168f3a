#include "dressed_human/core/surfaces/tessellation.h"

#include "dressed_human/core/surfaces/patch_keyed_cache.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

// How fine a patch must be tessellated: the a-priori error bound of a level and the level a
// geometric or screen-space error asks for.
namespace dressed_human {

namespace {

// Curvature constant K of the bound K / n^2 (see geometricErrorBound).
double errorBoundConstant(const BezierPatch& patch) {
  // Maxima of squared norms, one square root each at the end, on the packed coordinates (row j
  // of the net is p[12 j .. 12 j + 11], point i of it at 3 i): this runs for every patch every
  // frame under automatic level of detail, so the loops have fixed bounds and unroll.
  const double* p = patch.controlPoints().front().data();
  const auto squared = [](double x, double y, double z) { return x * x + y * y + z * z; };
  double second_u = 0.0;
  double second_v = 0.0;
  double twist = 0.0;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 2; ++i) {
      const double* q = p + 12 * j + 3 * i;
      second_u =
          std::max(second_u, squared(q[6] - 2.0 * q[3] + q[0], q[7] - 2.0 * q[4] + q[1], q[8] - 2.0 * q[5] + q[2]));
    }
  }
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 4; ++i) {
      const double* q = p + 12 * j + 3 * i;
      second_v = std::max(second_v,
                          squared(q[24] - 2.0 * q[12] + q[0], q[25] - 2.0 * q[13] + q[1], q[26] - 2.0 * q[14] + q[2]));
    }
  }
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      const double* q = p + 12 * j + 3 * i;
      twist = std::max(twist,
                       squared(q[15] - q[12] - q[3] + q[0], q[16] - q[13] - q[4] + q[1], q[17] - q[14] - q[5] + q[2]));
    }
  }
  const double bound_uu = 6.0 * std::sqrt(second_u);  // sup |F_uu|: F_uu is a Bezier patch on 6 * second differences
  const double bound_vv = 6.0 * std::sqrt(second_v);
  const double bound_uv = 9.0 * std::sqrt(twist);  // sup |F_uv|: F_uv is a Bezier patch on 9 * twists
  return (bound_uu + 2.0 * bound_uv + bound_vv) / 8.0;
}

int smallestLevelFor(double constant, double allowed, int max_level) {
  if (!(allowed > 0.0)) return max_level;
  const double exact = std::sqrt(constant / allowed);
  if (!(exact < max_level)) return max_level;
  int level = std::max(1, static_cast<int>(std::ceil(exact)));
  while (level < max_level && constant / (static_cast<double>(level) * level) > allowed) ++level;
  return level;
}

void requireLevelLimit(int max_level) {
  if (max_level < 1 || max_level > Tessellator::kMaxLevel) {
    throw std::invalid_argument("tessellation max_level must be in [1, " + std::to_string(Tessellator::kMaxLevel) +
                                "], got " + std::to_string(max_level));
  }
}

}  // namespace

// M_uu <= 6 max |second u-differences of P|, M_vv likewise, M_uv <= 9 max |twists of P|
// (the derivative patches are Bezier patches on those differences: convex hull property).
double geometricErrorBound(const BezierPatch& patch, int level) {
  if (level < 1) throw std::invalid_argument("geometricErrorBound: level must be >= 1");
  return errorBoundConstant(patch) / (static_cast<double>(level) * level);
}

int levelForGeometricError(const BezierPatch& patch, double max_error, int max_level) {
  requireLevelLimit(max_level);
  if (!(max_error > 0.0) || !std::isfinite(max_error)) {
    throw std::invalid_argument("levelForGeometricError: max_error must be finite and > 0");
  }
  return smallestLevelFor(errorBoundConstant(patch), max_error, max_level);
}

// Projection uses the distance to the nearest point of the control net's bounding box, which
// holds the patch (convex hull property): an error e there covers at most e * f / d pixels at
// the centre of the view, f = height / (2 tan(fov / 2)) being the focal length in pixels. Off
// the view axis the true size is up to 1 / cos^2 of the off-axis angle larger; the camera's
// orientation is not part of the query, so that factor is left to the caller's pixel budget.
namespace {

// Pixels per metre of error at distance 1 (the focal length in pixels), after checking the query.
double focalPixels(const CameraView& camera, double max_error_pixels, int max_level) {
  requireLevelLimit(max_level);
  if (!camera.position.allFinite() || !(camera.vertical_fov_radians > 0.0) || !(camera.vertical_fov_radians < M_PI) ||
      !(camera.viewport_height_pixels > 0.0) || !std::isfinite(camera.viewport_height_pixels)) {
    throw std::invalid_argument(
        "levelForScreenError: camera needs a finite position, 0 < fov < pi and a viewport "
        "height > 0");
  }
  if (!(max_error_pixels > 0.0) || !std::isfinite(max_error_pixels)) {
    throw std::invalid_argument("levelForScreenError: max_error_pixels must be finite and > 0");
  }
  return pixelsPerMetre(camera, 1.0);
}

int screenErrorLevel(const BezierPatch& patch, const Eigen::Vector3d& camera_position, double error_per_distance,
                     int max_level) {
  const double distance = distanceToPatchBounds(patch, camera_position);
  if (!(distance > 0.0)) return max_level;
  return smallestLevelFor(errorBoundConstant(patch), error_per_distance * distance, max_level);
}

}  // namespace

double pixelsPerMetre(const CameraView& camera, double distance) {
  return camera.viewport_height_pixels / (2.0 * std::tan(0.5 * camera.vertical_fov_radians) * std::max(distance, 1e-3));
}

double distanceToPatchBounds(const BezierPatch& patch, const Eigen::Vector3d& eye) {
  return (eye.cwiseMax(patch.boundingBoxMin()).cwiseMin(patch.boundingBoxMax()) - eye).norm();
}

int levelForScreenError(const BezierPatch& patch, const CameraView& camera, double max_error_pixels, int max_level) {
  const double focal = focalPixels(camera, max_error_pixels, max_level);
  return screenErrorLevel(patch, camera.position, max_error_pixels / focal, max_level);
}

void levelsForScreenError(const std::vector<BezierPatch>& patches, const CameraView& camera, double max_error_pixels,
                          int max_level, std::vector<int>& levels) {
  const double error_per_distance = max_error_pixels / focalPixels(camera, max_error_pixels, max_level);
  levels.resize(patches.size());
  for (std::size_t p = 0; p < patches.size(); ++p) {
    levels[p] = screenErrorLevel(patches[p], camera.position, error_per_distance, max_level);
  }
}

// ------------------------------------------------------------------------- measured, calibrated

double measuredTessellationError(const BezierPatch& patch, int level) {
  if (level < 1) throw std::invalid_argument("measuredTessellationError: level must be >= 1");
  constexpr int kSub = 4;  // samples per cell side: every triangle's points at barycentric steps of 1/4
  const int samples = kSub * level + 1;
  std::vector<Eigen::Vector3d> grid(static_cast<std::size_t>(samples) * samples);
  for (int j = 0; j < samples; ++j) {
    for (int i = 0; i < samples; ++i) {
      grid[static_cast<std::size_t>(j) * samples + i] =
          patch.position(static_cast<double>(i) / (samples - 1), static_cast<double>(j) / (samples - 1));
    }
  }
  const auto at = [&](int i, int j) -> const Eigen::Vector3d& {
    return grid[static_cast<std::size_t>(j) * samples + i];
  };
  double worst = 0.0;
  for (int cj = 0; cj < level; ++cj) {
    for (int ci = 0; ci < level; ++ci) {
      const Eigen::Vector3d& f00 = at(kSub * ci, kSub * cj);
      const Eigen::Vector3d& f10 = at(kSub * (ci + 1), kSub * cj);
      const Eigen::Vector3d& f01 = at(kSub * ci, kSub * (cj + 1));
      const Eigen::Vector3d& f11 = at(kSub * (ci + 1), kSub * (cj + 1));
      for (int t = 0; t <= kSub; ++t) {
        for (int s = 0; s <= kSub; ++s) {
          const double a = static_cast<double>(s) / kSub, b = static_cast<double>(t) / kSub;
          const Eigen::Vector3d& f = at(kSub * ci + s, kSub * cj + t);
          // Split along (0,0)-(1,1), as the tessellator's inner grid, and along (1,0)-(0,1).
          const Eigen::Vector3d main = a >= b ? Eigen::Vector3d(f00 + a * (f10 - f00) + b * (f11 - f10))
                                              : Eigen::Vector3d(f00 + b * (f01 - f00) + a * (f11 - f01));
          const Eigen::Vector3d other = a + b <= 1.0
                                            ? Eigen::Vector3d(f00 + a * (f10 - f00) + b * (f01 - f00))
                                            : Eigen::Vector3d(f11 + (1.0 - a) * (f01 - f11) + (1.0 - b) * (f10 - f11));
          worst = std::max({worst, (f - main).norm(), (f - other).norm()});
        }
      }
    }
  }
  return worst;
}

CalibratedErrorBound::CalibratedErrorBound(const std::vector<BezierPatch>& reference,
                                           const std::vector<std::vector<BezierPatch>>& posed)
    : scale_(reference.size(), std::array<double, kCalibratedLevels>{}),
      margin_(posed.empty() ? kRestMargin : kPosedMargin) {
  calibrateAgainst(reference, {kFineReferenceLevels.begin(), kFineReferenceLevels.end()});
  for (std::size_t k = 0; k < posed.size(); ++k) {
    if (posed[k].size() != reference.size()) {
      throw std::invalid_argument("CalibratedErrorBound: posed reference " + std::to_string(k) + " has " +
                                  std::to_string(posed[k].size()) + " patches, the rest reference " +
                                  std::to_string(reference.size()));
    }
    // Level 16 alone costs 70 % of a pose's measurement; level 8 follows the pose as well.
    calibrateAgainst(posed[k], {kFineReferenceLevels.front()});
  }
}

void CalibratedErrorBound::calibrateAgainst(const std::vector<BezierPatch>& patches,
                                            const std::vector<int>& fine_levels) {
  for (std::size_t p = 0; p < patches.size(); ++p) {
    const double constant = errorBoundConstant(patches[p]);
    const auto scaleAt = [&](int level) {
      const double bound = constant / (static_cast<double>(level) * level);
      // A flat patch has neither error nor bound.
      return bound > 0.0 ? std::min(1.0, measuredTessellationError(patches[p], level) / bound) : 1.0;
    };
    std::array<double, kCalibratedLevels>& scale = scale_[p];
    for (int level = 1; level < kCalibratedLevels; ++level) {
      scale[level - 1] = std::max(scale[level - 1], scaleAt(level));
    }
    // Finer levels: error * n^2 still changes from 4 to 8 and on to 16 (the default max_level) on
    // some patches (the skirt's, by 5 %: with 4 and 8 only, the bound was below the drawn error at
    // levels 11..16); the largest holds.
    double finer = std::max(scale[kCalibratedLevels - 1], scale[kCalibratedLevels - 2]);  // level 4's
    for (const int level : fine_levels) finer = std::max(finer, scaleAt(level));
    scale[kCalibratedLevels - 1] = finer;
  }
}

std::shared_ptr<const CalibratedErrorBound> CalibratedErrorBound::shared(
    const std::vector<BezierPatch>& reference, const std::vector<std::vector<BezierPatch>>& posed) {
  // A crowd's bodies and outfits (9 statures x the skin and 4 garments in crowd.launch), kept
  // through a rebuild of every human: calibrating one skin in the walk takes ~100 ms.
  static PatchKeyedCache<CalibratedErrorBound> cache(64);
  std::vector<const std::vector<BezierPatch>*> key{&reference};
  for (const std::vector<BezierPatch>& patches : posed) key.push_back(&patches);
  return cache.obtain(key, [&] { return std::make_shared<const CalibratedErrorBound>(reference, posed); });
}

double CalibratedErrorBound::bound(std::size_t index, const BezierPatch& live, int level) const {
  if (level < 1) throw std::invalid_argument("CalibratedErrorBound: level must be >= 1");
  const double scale = scale_.at(index)[static_cast<std::size_t>(std::min(level, kCalibratedLevels) - 1)];
  return std::min(1.0, margin_ * scale) * errorBoundConstant(live) / (static_cast<double>(level) * level);
}

int CalibratedErrorBound::smallestLevel(std::size_t index, double constant, double allowed, int max_level) const {
  if (!(allowed > 0.0)) return max_level;
  const std::array<double, kCalibratedLevels>& scale = scale_[index];
  for (int level = 1; level <= std::min(kCalibratedLevels, max_level); ++level) {
    const double factor = std::min(1.0, margin_ * scale[static_cast<std::size_t>(level - 1)]);
    if (factor * constant / (static_cast<double>(level) * level) <= allowed) return level;
  }
  if (max_level <= kCalibratedLevels) return max_level;
  const double finest = std::min(1.0, margin_ * scale[kCalibratedLevels - 1]);
  return std::max(kCalibratedLevels + 1, smallestLevelFor(finest * constant, allowed, max_level));
}

void CalibratedErrorBound::levelsForScreenError(const std::vector<BezierPatch>& patches, const CameraView& camera,
                                                double max_error_pixels, int max_level,
                                                std::vector<int>& levels) const {
  if (patches.size() != scale_.size()) {
    throw std::invalid_argument("CalibratedErrorBound: calibrated on " + std::to_string(scale_.size()) +
                                " patches, asked for " + std::to_string(patches.size()));
  }
  const double error_per_distance = max_error_pixels / focalPixels(camera, max_error_pixels, max_level);
  levels.resize(patches.size());
  for (std::size_t p = 0; p < patches.size(); ++p) {
    const double distance = distanceToPatchBounds(patches[p], camera.position);
    levels[p] = distance > 0.0
                    ? smallestLevel(p, errorBoundConstant(patches[p]), error_per_distance * distance, max_level)
                    : max_level;
  }
}

}  // namespace dressed_human
