#include "dressed_human/core/relief/mesh_displacement.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dressed_human {
namespace {

// Index of a pixel in a periodic axis of `size` pixels.
int wrapped(int index, int size) {
  const int r = index % size;
  return r < 0 ? r + size : r;
}

}  // namespace

ReliefSample sampleReliefMap(const ReliefMap& map, double tile_u, double tile_v) {
  // Pixel centres sit at (column + 0.5) / width, as every map renderer here writes them.
  const double x = tile_u * map.width - 0.5;
  const double y = tile_v * map.height - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const double fx = x - x0, fy = y - y0;
  const int c0 = wrapped(static_cast<int>(x0), map.width), c1 = wrapped(c0 + 1, map.width);
  const int r0 = wrapped(static_cast<int>(y0), map.height), r1 = wrapped(r0 + 1, map.height);
  const std::size_t i00 = map.index(c0, r0), i10 = map.index(c1, r0), i01 = map.index(c0, r1), i11 = map.index(c1, r1);
  const auto blend = [&](const std::vector<float>& v) {
    return (1.0 - fy) * ((1.0 - fx) * v[i00] + fx * v[i10]) + fy * ((1.0 - fx) * v[i01] + fx * v[i11]);
  };
  ReliefSample sample;
  sample.height = blend(map.heights);
  sample.slope = {blend(map.slope_u), blend(map.slope_v)};
  return sample;
}

void checkReliefDisplacement(const ReliefDisplacement& displacement) {
  const ReliefMap* map = displacement.map;
  if (map == nullptr || map->width <= 0 || map->height <= 0 ||
      map->heights.size() != static_cast<std::size_t>(map->width) * static_cast<std::size_t>(map->height)) {
    throw std::invalid_argument("relief displacement: no relief map, or an empty one");
  }
  if (!(displacement.tiling > 0.0f) || !std::isfinite(displacement.tiling)) {
    throw std::invalid_argument("relief displacement: tiling " + std::to_string(displacement.tiling) + " must be > 0");
  }
  if (!(displacement.height_to_tile > 0.0f) || !std::isfinite(displacement.height_to_tile)) {
    throw std::invalid_argument("relief displacement: height_to_tile " + std::to_string(displacement.height_to_tile) +
                                " must be > 0");
  }
  if (displacement.folds != nullptr && displacement.tiling != 1.0f) {
    throw std::invalid_argument("relief displacement: fold tiles are laid out per patch; tiling " +
                                std::to_string(displacement.tiling) + " must be 1");
  }
  if (!(displacement.amplitude >= 0.0f) || !std::isfinite(displacement.amplitude)) {
    throw std::invalid_argument("relief displacement: amplitude " + std::to_string(displacement.amplitude) +
                                " must be finite and >= 0");
  }
}

void displaceMesh(const TriangleMesh& base, const ReliefDisplacement& displacement, TriangleMesh& out) {
  checkReliefDisplacement(displacement);
  const ReliefMap* map = displacement.map;
  const std::size_t n = base.vertexCount();
  if (displacement.weights != nullptr && displacement.weights->size() != n) {
    throw std::invalid_argument("relief displacement: " + std::to_string(displacement.weights->size()) +
                                " vertex weights for " + std::to_string(n) + " vertices");
  }
  if (displacement.fold_axes != nullptr && displacement.fold_axes->size() != n) {
    throw std::invalid_argument("relief displacement: " + std::to_string(displacement.fold_axes->size()) +
                                " fold axes for " + std::to_string(n) + " vertices");
  }
  out.positions.resize(n);
  out.normals.resize(n);
  out.tangents_u = base.tangents_u;
  out.tangents_v = base.tangents_v;
  out.uv = base.uv;
  out.vertex_patch = base.vertex_patch;
  out.indices = base.indices;
  out.triangle_patch = base.triangle_patch;
  const double tiling = displacement.tiling;
  for (std::size_t i = 0; i < n; ++i) {
    const float weight = displacement.weights ? (*displacement.weights)[i] : 1.0f;
    const Eigen::Vector3d normal = base.normals[i].cast<double>();
    const Eigen::Vector3d fu = base.tangents_u[i].cast<double>(), fv = base.tangents_v[i].cast<double>();
    // Fold tiles take the weight as the wrinkle strength (their pattern and amplitude).
    const double amplitude = displacement.amplitude * (displacement.folds ? 1.0f : weight);
    const ReliefSample relief =
        displacement.folds
            ? orientedFolds(*displacement.folds, base.uv[i].cast<double>(),
                            displacement.fold_axes ? (*displacement.fold_axes)[i] : Eigen::Vector2f::Zero(), weight)
            : sampleReliefMap(*map, base.uv[i].x() * tiling, base.uv[i].y() * tiling);
    const double lu = fu.norm(), lv = fv.norm();
    // At a pole one derivative vanishes: the tile has no size there and nothing moves.
    const double metres_per_tile = std::sqrt(lu * lv) / tiling;
    out.positions[i] =
        (base.positions[i].cast<double>() + normal * (amplitude * displacement.height_to_tile * relief.height * metres_per_tile))
            .cast<float>();
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
    if (lu > 1e-12 && lv > 1e-12) {
      const double scale = amplitude * std::sqrt(lu * lv);
      gradient = scale * (relief.slope.x() * fu / (lu * lu) + relief.slope.y() * fv / (lv * lv));
      gradient -= gradient.dot(normal) * normal;
    }
    out.normals[i] = (normal - gradient).normalized().cast<float>();
  }
}

}  // namespace dressed_human
