#include "dressed_human/core/relief/mesh_displacement.h"

#include <algorithm>
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

ReliefSample sampleReliefLevels(const std::vector<ReliefMap>& levels, double tile_u, double tile_v,
                                double texels_per_sample) {
  if (levels.empty()) throw std::invalid_argument("sampleReliefLevels: an empty mip chain");
  const double last = static_cast<double>(levels.size() - 1);
  const double level = std::clamp(std::log2(std::max(texels_per_sample, 1.0)), 0.0, last);
  const std::size_t fine = static_cast<std::size_t>(std::floor(level));
  const double t = level - static_cast<double>(fine);
  const ReliefSample a = sampleReliefMap(levels[fine], tile_u, tile_v);
  if (t <= 0.0) return a;
  const ReliefSample b = sampleReliefMap(levels[fine + 1], tile_u, tile_v);
  ReliefSample blended;
  blended.height = (1.0 - t) * a.height + t * b.height;
  blended.slope = (1.0 - t) * a.slope + t * b.slope;
  return blended;
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
  if (displacement.patch_tiles != nullptr) {
    if (displacement.folds != nullptr) {
      throw std::invalid_argument("relief displacement: fold tiles are laid out per patch; no tiles per patch");
    }
    for (const Eigen::Vector2f& tiles : *displacement.patch_tiles) {
      if (!(tiles.minCoeff() > 0.0f) || !tiles.allFinite()) {
        throw std::invalid_argument("relief displacement: tiles per patch must be finite and > 0");
      }
    }
  }
  const bool mips = displacement.map_mips != nullptr || displacement.fold_mips != nullptr;
  if (mips && displacement.patch_levels == nullptr) {
    throw std::invalid_argument("relief displacement: mip chains need the patches' tessellation levels");
  }
  if (displacement.map_mips != nullptr &&
      (displacement.map_mips->empty() || displacement.map_mips->front().width != map->width ||
       displacement.map_mips->front().height != map->height)) {
    throw std::invalid_argument("relief displacement: the mip chain is not of the relief map");
  }
  if (displacement.fold_mips != nullptr &&
      (displacement.folds == nullptr || displacement.fold_mips->slight.empty() ||
       displacement.fold_mips->slight.size() != displacement.fold_mips->strong.size() ||
       displacement.fold_mips->slight.front().width != displacement.folds->slight.width)) {
    throw std::invalid_argument("relief displacement: the fold tiles' mip chains are not of its fold tiles");
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
  if ((displacement.fold_tiles != nullptr) != (displacement.fold_directions != nullptr) ||
      (displacement.fold_tiles != nullptr &&
       (displacement.fold_tiles->size() != n || displacement.fold_directions->size() != n))) {
    throw std::invalid_argument("relief displacement: " +
                                std::to_string(displacement.fold_tiles ? displacement.fold_tiles->size() : 0) +
                                " fold tile coordinates and " +
                                std::to_string(displacement.fold_directions ? displacement.fold_directions->size() : 0) +
                                " fold directions for a mesh of " + std::to_string(n) + " vertices");
  }
  if (displacement.fold_axes != nullptr && displacement.fold_axes->size() != n) {
    throw std::invalid_argument("relief displacement: " + std::to_string(displacement.fold_axes->size()) +
                                " fold axes for " + std::to_string(n) + " vertices");
  }
  if (displacement.patch_levels != nullptr && base.vertex_patch.size() != n) {
    throw std::invalid_argument("relief displacement: " + std::to_string(base.vertex_patch.size()) +
                                " vertex patches for " + std::to_string(n) + " vertices");
  }
  if (displacement.patch_tiles != nullptr) {
    if (base.vertex_patch.size() != n) {
      throw std::invalid_argument("relief displacement: " + std::to_string(base.vertex_patch.size()) +
                                  " vertex patches for " + std::to_string(n) + " vertices");
    }
    for (const std::uint32_t patch : base.vertex_patch) {
      if (patch >= displacement.patch_tiles->size()) {
        throw std::invalid_argument("relief displacement: vertex on patch " + std::to_string(patch) + " of " +
                                    std::to_string(displacement.patch_tiles->size()) + " with tiles");
      }
    }
  }
  out.positions.resize(n);
  out.normals.resize(n);
  out.tangents_u = base.tangents_u;
  out.tangents_v = base.tangents_v;
  out.uv = base.uv;
  out.vertex_patch = base.vertex_patch;
  out.indices = base.indices;
  out.triangle_patch = base.triangle_patch;
  const std::vector<int>* patch_levels = displacement.patch_levels;
  for (std::size_t i = 0; i < n; ++i) {
    double uv_spacing = 0.0;  // between this vertex and the next, in patch coordinates
    if (patch_levels != nullptr) {
      const std::size_t patch = base.vertex_patch[i];
      if (patch >= patch_levels->size() || (*patch_levels)[patch] < 1) {
        throw std::invalid_argument("relief displacement: vertex " + std::to_string(i) + "'s patch " +
                                    std::to_string(patch) + " has no tessellation level (" +
                                    std::to_string(patch_levels->size()) + " given)");
      }
      uv_spacing = 1.0 / (*patch_levels)[patch];
    }
    const float weight = displacement.weights ? (*displacement.weights)[i] : 1.0f;
    const Eigen::Vector3d normal = base.normals[i].cast<double>();
    const Eigen::Vector3d fu = base.tangents_u[i].cast<double>(), fv = base.tangents_v[i].cast<double>();
    // Fold tiles take the weight as the wrinkle strength (their pattern and amplitude).
    const double amplitude = displacement.amplitude * (displacement.folds ? 1.0f : weight);
    const Eigen::Vector2f axis = displacement.fold_axes ? (*displacement.fold_axes)[i] : Eigen::Vector2f::Zero();
    const Eigen::Vector2d uv = base.uv[i].cast<double>();
    const Eigen::Vector2d tiles =
        displacement.patch_tiles != nullptr
            ? Eigen::Vector2d((*displacement.patch_tiles)[base.vertex_patch[i]].cast<double>())
            : Eigen::Vector2d::Constant(displacement.tiling);
    ReliefSample relief;
    if (displacement.folds && displacement.fold_tiles) {
      const Eigen::Vector2d tile = (*displacement.fold_tiles)[i].cast<double>();
      const Eigen::Vector2f& along = (*displacement.fold_directions)[i];
      relief = displacement.fold_mips ? foldCoordinateRelief(*displacement.fold_mips, tile, along, weight, uv_spacing)
                                      : foldCoordinateRelief(*displacement.folds, tile, along, weight);
    } else if (displacement.folds) {
      relief = displacement.fold_mips ? orientedFolds(*displacement.fold_mips, uv, axis, weight, uv_spacing)
                                      : orientedFolds(*displacement.folds, uv, axis, weight);
    } else {
      relief = displacement.map_mips
                   ? sampleReliefLevels(*displacement.map_mips, uv.x() * tiles.x(), uv.y() * tiles.y(),
                                        uv_spacing * tiles.maxCoeff() * map->width)
                   : sampleReliefMap(*map, uv.x() * tiles.x(), uv.y() * tiles.y());
    }
    const double lu = fu.norm(), lv = fv.norm();
    // At a pole one derivative vanishes: the tile has no size there and nothing moves.
    const double metres_per_tile = std::sqrt(lu * lv / tiles.prod());
    out.positions[i] = (base.positions[i].cast<double>() +
                        normal * (amplitude * displacement.height_to_tile * relief.height * metres_per_tile))
                           .cast<float>();
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
    if (lu > 1e-12 && lv > 1e-12) {
      // The map's slopes per tile, turned into per patch parameter by the tiles along each.
      const double scale = amplitude * metres_per_tile;
      gradient =
          scale * (relief.slope.x() * tiles.x() * fu / (lu * lu) + relief.slope.y() * tiles.y() * fv / (lv * lv));
      gradient -= gradient.dot(normal) * normal;
    }
    out.normals[i] = (normal - gradient).normalized().cast<float>();
  }
}

}  // namespace dressed_human
