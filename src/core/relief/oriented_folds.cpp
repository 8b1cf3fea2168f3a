#include "dressed_human/core/relief/oriented_folds.h"

#include "dressed_human/core/relief/mesh_displacement.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace dressed_human {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::uint8_t encodeUnit(double value) {
  return static_cast<std::uint8_t>(std::lround(std::clamp((value + 1.0) * 0.5, 0.0, 1.0) * 255.0));
}

}  // namespace

const std::array<FoldOrientation, kFoldOrientations>& foldOrientations() {
  static const std::array<FoldOrientation, kFoldOrientations> orientations = [] {
    std::array<FoldOrientation, kFoldOrientations> table{{{1, 0, 3, 0.0},
                                                          {3, 1, 1, 0.0},
                                                          {3, 2, 1, 0.0},
                                                          {1, 1, 2, 0.0},
                                                          {2, 3, 1, 0.0},
                                                          {1, 3, 1, 0.0},
                                                          {0, 1, 3, 0.0},
                                                          {-1, 3, 1, 0.0},
                                                          {-2, 3, 1, 0.0},
                                                          {-1, 1, 2, 0.0},
                                                          {-3, 2, 1, 0.0},
                                                          {-3, 1, 1, 0.0}}};
    for (FoldOrientation& o : table) o.degrees = std::atan2(o.q, o.p) * 180.0 / kPi;
    return table;
  }();
  return orientations;
}

double foldAngle(const Eigen::Vector2f& fold_axis) {
  const Eigen::Vector2f axis = fold_axis + Eigen::Vector2f(-kFoldAxisBias, 0.0f);
  return 0.5 * std::atan2(static_cast<double>(axis.y()), static_cast<double>(axis.x()));
}

FoldBlend foldOrientationBlend(const Eigen::Vector2f& fold_axis) {
  // The folds' angle in [0, 180).
  double degrees = foldAngle(fold_axis) * 180.0 / kPi;
  if (degrees < 0.0) degrees += 180.0;
  const auto& table = foldOrientations();
  int first = kFoldOrientations - 1;
  while (first > 0 && table[static_cast<std::size_t>(first)].degrees > degrees) --first;
  const int second = (first + 1) % kFoldOrientations;
  const double next = second == 0 ? 180.0 : table[static_cast<std::size_t>(second)].degrees;
  const double t = std::clamp((degrees - table[static_cast<std::size_t>(first)].degrees) /
                                  (next - table[static_cast<std::size_t>(first)].degrees),
                              0.0, 1.0);
  const float s = static_cast<float>(t * t * (3.0 - 2.0 * t));
  return {first, second, 1.0f - s, s};
}

Eigen::Vector2d foldTileCoordinate(int orientation, const Eigen::Vector2d& uv) {
  const FoldOrientation& o = foldOrientations()[static_cast<std::size_t>(orientation)];
  return o.scale * Eigen::Vector2d(o.q * uv.x() - o.p * uv.y(), o.p * uv.x() + o.q * uv.y());
}

double foldHeightScale(int orientation) {
  const FoldOrientation& o = foldOrientations()[static_cast<std::size_t>(orientation)];
  return 1.0 / (o.scale * std::hypot(o.p, o.q));
}

float strongPatternWeight(float strength) {
  const float t = std::clamp((strength - 0.4f) / 0.4f, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

FoldTiles::FoldTiles(ReliefMap slight_tile, ReliefMap strong_tile)
    : slight(std::move(slight_tile)), strong(std::move(strong_tile)) {
  if (slight.width <= 0 || slight.height <= 0 || slight.width != strong.width || slight.height != strong.height) {
    throw std::invalid_argument("fold tiles of " + std::to_string(slight.width) + " x " +
                                std::to_string(slight.height) + " and " + std::to_string(strong.width) + " x " +
                                std::to_string(strong.height) + " pixels: they must be one non-empty size");
  }
}

namespace {

// orientedFolds with the tiles' lookup `sample(k, at, &slight, &strong)` for orientation k at tile
// coordinate `at`.
template <typename Sample>
ReliefSample blendOrientations(const Eigen::Vector2d& uv, const Eigen::Vector2f& fold_axis, float strength,
                               const Sample& sample) {
  const FoldBlend blend = foldOrientationBlend(fold_axis);
  const double strong = strongPatternWeight(strength);
  ReliefSample sum;
  for (const auto& [k, weight] :
       {std::make_pair(blend.first, blend.first_weight), std::make_pair(blend.second, blend.second_weight)}) {
    if (weight <= 0.0f) continue;
    const Eigen::Vector2d at = foldTileCoordinate(k, uv);
    ReliefSample slight, strong_sample;
    sample(k, at, &slight, &strong_sample);
    const double height = (1.0 - strong) * slight.height + strong * strong_sample.height;
    const Eigen::Vector2d g = (1.0 - strong) * slight.slope + strong * strong_sample.slope;
    // h(A uv) c: gradient c A^T grad h, and c A^T = R^T, a rotation: the slope keeps its size.
    const FoldOrientation& o = foldOrientations()[static_cast<std::size_t>(k)];
    const double c = 1.0 / std::hypot(o.p, o.q);
    sum.height += weight * foldHeightScale(k) * height;
    sum.slope += weight * c * Eigen::Vector2d(o.q * g.x() + o.p * g.y(), -o.p * g.x() + o.q * g.y());
  }
  sum.height *= strength;
  sum.slope *= strength;
  return sum;
}

}  // namespace

ReliefSample orientedFolds(const FoldTiles& tiles, const Eigen::Vector2d& uv, const Eigen::Vector2f& fold_axis,
                           float strength) {
  return blendOrientations(uv, fold_axis, strength,
                           [&](int, const Eigen::Vector2d& at, ReliefSample* slight, ReliefSample* strong) {
                             *slight = sampleReliefMap(tiles.slight, at.x(), at.y());
                             *strong = sampleReliefMap(tiles.strong, at.x(), at.y());
                           });
}

namespace {

// foldCoordinateRelief from the two tiles' samples at the coordinate.
ReliefSample laidFolds(const ReliefSample& slight, const ReliefSample& strong_sample, const Eigen::Vector2f& direction,
                       float strength) {
  const double strong = strongPatternWeight(strength);
  const Eigen::Vector2d g = (1.0 - strong) * slight.slope + strong * strong_sample.slope;
  // The tile's x runs across the folds (along (d_v, -d_u)), its y along them (d), as orientation
  // (1, 0) lays it out: the slope turns back by that rotation and keeps its size.
  const Eigen::Vector2d d = direction.cast<double>().normalized();
  ReliefSample sample;
  sample.height = strength * ((1.0 - strong) * slight.height + strong * strong_sample.height) / kFoldTilesPerPatch;
  sample.slope = strength * (g.x() * Eigen::Vector2d(d.y(), -d.x()) + g.y() * d);
  return sample;
}

}  // namespace

ReliefSample foldCoordinateRelief(const FoldTiles& tiles, const Eigen::Vector2d& tile, const Eigen::Vector2f& direction,
                                  float strength) {
  return laidFolds(sampleReliefMap(tiles.slight, tile.x(), tile.y()), sampleReliefMap(tiles.strong, tile.x(), tile.y()),
                   direction, strength);
}

ReliefSample foldCoordinateRelief(const FoldTileMips& mips, const Eigen::Vector2d& tile, const Eigen::Vector2f& direction,
                                  float strength, double uv_spacing) {
  if (mips.slight.empty() || mips.slight.size() != mips.strong.size()) {
    throw std::invalid_argument("foldCoordinateRelief: fold tile mip chains of " + std::to_string(mips.slight.size()) +
                                " and " + std::to_string(mips.strong.size()) + " levels");
  }
  // The coordinates run kFoldTilesPerPatch tiles a patch.
  const double texels = uv_spacing * kFoldTilesPerPatch * mips.slight.front().width;
  return laidFolds(sampleReliefLevels(mips.slight, tile.x(), tile.y(), texels),
                   sampleReliefLevels(mips.strong, tile.x(), tile.y(), texels), direction, strength);
}

FoldTileMips buildFoldTileMips(const FoldTiles& tiles) {
  return FoldTileMips{buildMipChain(tiles.slight), buildMipChain(tiles.strong)};
}

ReliefSample orientedFolds(const FoldTileMips& mips, const Eigen::Vector2d& uv, const Eigen::Vector2f& fold_axis,
                           float strength, double uv_spacing) {
  if (mips.slight.empty() || mips.slight.size() != mips.strong.size()) {
    throw std::invalid_argument("orientedFolds: fold tile mip chains of " + std::to_string(mips.slight.size()) +
                                " and " + std::to_string(mips.strong.size()) + " levels");
  }
  return blendOrientations(
      uv, fold_axis, strength, [&](int k, const Eigen::Vector2d& at, ReliefSample* slight, ReliefSample* strong) {
        // The lookup scale * [[q, -p], [p, q]] stretches patch coordinates by scale * |(p, q)|.
        const FoldOrientation& o = foldOrientations()[static_cast<std::size_t>(k)];
        const double texels = uv_spacing * o.scale * std::hypot(o.p, o.q) * mips.slight.front().width;
        *slight = sampleReliefLevels(mips.slight, at.x(), at.y(), texels);
        *strong = sampleReliefLevels(mips.strong, at.x(), at.y(), texels);
      });
}

std::vector<std::uint8_t> encodeFoldTilesRgba(const FoldTiles& tiles) {
  std::vector<std::uint8_t> rgba;
  rgba.reserve(static_cast<std::size_t>(tiles.slight.width) * static_cast<std::size_t>(tiles.slight.height) * 4);
  for (int row = 0; row < tiles.slight.height; ++row) {
    for (int column = 0; column < tiles.slight.width; ++column) {
      for (const ReliefMap* map : {&tiles.slight, &tiles.strong}) {
        const Eigen::Vector3f n = map->normalAt(column, row);
        rgba.push_back(encodeUnit(n.x()));
        rgba.push_back(encodeUnit(n.y()));
      }
    }
  }
  return rgba;
}

EncodedNormalMap encodeFoldTilesMips(const FoldTiles& tiles) {
  EncodedNormalMap encoded;
  encoded.width = tiles.slight.width;
  encoded.height = tiles.slight.height;
  encoded.channels = 4;
  FoldTileMips mips = buildFoldTileMips(tiles);
  for (std::size_t level = 0; level < mips.slight.size(); ++level) {
    encoded.levels.push_back(
        encodeFoldTilesRgba(FoldTiles(std::move(mips.slight[level]), std::move(mips.strong[level]))));
  }
  return encoded;
}

}  // namespace dressed_human
