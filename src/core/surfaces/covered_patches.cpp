#include "dressed_human/core/surfaces/covered_patches.h"

#include <array>
#include <cmath>

#include <Eigen/Geometry>

namespace dressed_human {
namespace {

// Each covering patch is cut into a grid this fine for the ray tests: its chords then lie within
// about a millimetre of the patch, far inside the garments' centimetres of ease.
constexpr int kCoverGrid = 8;

struct CoverPatch {
  Eigen::AlignedBox3d box;
  std::vector<Eigen::Vector3d> grid;  // (kCoverGrid + 1)^2, u fastest
};

std::vector<CoverPatch> coverPatches(const std::vector<const std::vector<BezierPatch>*>& covers) {
  std::vector<CoverPatch> result;
  for (const std::vector<BezierPatch>* patches : covers) {
    for (const BezierPatch& patch : *patches) {
      CoverPatch cover;
      for (int j = 0; j <= kCoverGrid; ++j) {
        for (int i = 0; i <= kCoverGrid; ++i) {
          cover.grid.push_back(
              patch.position(static_cast<double>(i) / kCoverGrid, static_cast<double>(j) / kCoverGrid));
          cover.box.extend(cover.grid.back());
        }
      }
      // Rays graze the box's faces where a patch is flat along an axis.
      cover.box.min().array() -= 1e-6;
      cover.box.max().array() += 1e-6;
      result.push_back(std::move(cover));
    }
  }
  return result;
}

bool rayMeetsBox(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, const Eigen::AlignedBox3d& box) {
  double near = 0.0, far = kMaxCoverGap;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(direction[k]) < 1e-12) {
      if (origin[k] < box.min()[k] || origin[k] > box.max()[k]) return false;
      continue;
    }
    double t0 = (box.min()[k] - origin[k]) / direction[k], t1 = (box.max()[k] - origin[k]) / direction[k];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
    if (near > far) return false;
  }
  return true;
}

// Moller-Trumbore, either side of the triangle, 0 <= t <= kMaxCoverGap. Edges count (with a
// hair to spare): a sight line through the seam of two cover patches meets one of them.
bool rayMeetsTriangle(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, const Eigen::Vector3d& a,
                      const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a;
  const Eigen::Vector3d p = direction.cross(ac);
  const double det = ab.dot(p);
  if (std::abs(det) < 1e-18) return false;
  const Eigen::Vector3d s = origin - a;
  const double u = s.dot(p) / det;
  constexpr double kEdge = 1e-9;
  if (u < -kEdge || u > 1.0 + kEdge) return false;
  const Eigen::Vector3d q = s.cross(ab);
  const double v = direction.dot(q) / det;
  if (v < -kEdge || u + v > 1.0 + kEdge) return false;
  const double t = ac.dot(q) / det;
  return t >= 0.0 && t <= kMaxCoverGap;
}

bool rayMeetsCover(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                   const std::vector<CoverPatch>& covers) {
  constexpr int n = kCoverGrid + 1;
  for (const CoverPatch& cover : covers) {
    if (!rayMeetsBox(origin, direction, cover.box)) continue;
    for (int j = 0; j < kCoverGrid; ++j) {
      for (int i = 0; i < kCoverGrid; ++i) {
        const Eigen::Vector3d& p00 = cover.grid[j * n + i];
        const Eigen::Vector3d& p10 = cover.grid[j * n + i + 1];
        const Eigen::Vector3d& p01 = cover.grid[(j + 1) * n + i];
        const Eigen::Vector3d& p11 = cover.grid[(j + 1) * n + i + 1];
        if (rayMeetsTriangle(origin, direction, p00, p10, p11) || rayMeetsTriangle(origin, direction, p00, p11, p01)) {
          return true;
        }
      }
    }
  }
  return false;
}

// The outward normal and the four directions tilted from it towards +-u and +-v.
std::array<Eigen::Vector3d, 5> sightLines(const BezierPatch& patch, double u, double v) {
  const Eigen::Vector3d normal = patch.normal(u, v);
  const PatchDerivatives derivatives = patch.derivatives(u, v);
  Eigen::Vector3d along = derivatives.d_du - derivatives.d_du.dot(normal) * normal;
  if (along.squaredNorm() < 1e-20) along = derivatives.d_dv - derivatives.d_dv.dot(normal) * normal;
  if (along.squaredNorm() < 1e-20) along = normal.unitOrthogonal();
  along.normalize();
  const Eigen::Vector3d across = normal.cross(along);
  const double tilt = std::tan(kCoverTiltDegrees * M_PI / 180.0);
  return {normal, (normal + tilt * along).normalized(), (normal - tilt * along).normalized(),
          (normal + tilt * across).normalized(), (normal - tilt * across).normalized()};
}

bool covered(const BezierPatch& patch, const std::vector<CoverPatch>& covers) {
  for (int j = 0; j < kCoverSamplesPerSide; ++j) {
    for (int i = 0; i < kCoverSamplesPerSide; ++i) {
      const double u = static_cast<double>(i) / (kCoverSamplesPerSide - 1);
      const double v = static_cast<double>(j) / (kCoverSamplesPerSide - 1);
      const Eigen::Vector3d origin = patch.position(u, v);
      for (const Eigen::Vector3d& direction : sightLines(patch, u, v)) {
        if (!rayMeetsCover(origin, direction, covers)) return false;
      }
    }
  }
  return true;
}

}  // namespace

std::vector<bool> patchesCoveredBy(const std::vector<BezierPatch>& inner,
                                   const std::vector<const std::vector<BezierPatch>*>& covers) {
  const std::vector<CoverPatch> cover_patches = coverPatches(covers);
  std::vector<bool> result(inner.size(), false);
  if (cover_patches.empty()) return result;
  for (std::size_t p = 0; p < inner.size(); ++p) result[p] = covered(inner[p], cover_patches);
  return result;
}

}  // namespace dressed_human
