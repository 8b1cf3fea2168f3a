// A sampled relief (height field) with its exact gradient, for bump/normal mapping.
//
// Heights are in the physical units of the surface the map is laid on; slopes are the
// dimensionless gradient (dh/du, dh/dv) with respect to the same physical lengths along the map's
// u (column, left to right) and v (row, top to bottom) axes. Storing the gradient rather than
// differencing the height image keeps normals exact at creases and valid when pixels are not
// square in physical space (a compressed wrinkle row). Tangent-space normal:
//   n = normalize(-dh/du, -dh/dv, 1)   (tangent = +u, bitangent = +v, normal = out of the surface).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace dressed_human {

struct ReliefMap {
  int width = 0;
  int height = 0;
  std::vector<float> heights;  ///< row-major, width * height
  std::vector<float> slope_u;  ///< dh/du
  std::vector<float> slope_v;  ///< dh/dv

  ReliefMap() = default;
  /// Throws std::invalid_argument for a non-positive size.
  ReliefMap(int width_pixels, int height_pixels);

  std::size_t index(int column, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(column);
  }
  Eigen::Vector3f normalAt(int column, int row) const;
  float minimumHeight() const;
  float maximumHeight() const;
};

/// RMS of the height difference of two maps of one size (how far an approximation is from the
/// surface it stands for). Throws std::invalid_argument for maps of different sizes.
double rmsHeightDifference(const ReliefMap& a, const ReliefMap& b);

/// Mip chain: level 0 is `base`, each next level averages 2x2 blocks of height and gradient (the
/// gradient of the box-filtered height, so normals stay consistent with heights). Stops at 1x1,
/// at an odd dimension, or after max_levels levels (0 = no limit).
/// `base` by value: a map passed as a temporary (buildMipChain(relief.render(...))) is moved into
/// the chain, not copied (12 MB at 1024^2).
std::vector<ReliefMap> buildMipChain(ReliefMap base, int max_levels = 0);

/// 8-bit RGB tangent-space normal map, (n + 1) / 2 * 255 per channel, row-major RGBRGB...
std::vector<std::uint8_t> encodeNormalMapRgb(const ReliefMap& map);

/// A normal-map texture with the mip levels built for it. A GPU's own chain (glGenerateMipmap)
/// averages the encoded normals, and the slope an averaged normal decodes to is not the average
/// slope: a steep crease beside a flat run comes out about half as steep at the next level, so
/// folds seen from afar look flatter than their filtered surface. Here level k is the encoding of
/// buildMipChain's level k: the normals of the box-filtered height.
struct EncodedNormalMap {
  int width = 0;  ///< of level 0
  int height = 0;
  int channels = 3;
  /// level k: max(1, width >> k) x max(1, height >> k) pixels of `channels` bytes, row-major
  std::vector<std::vector<std::uint8_t>> levels;
};

/// encodeNormalMapRgb of every level of buildMipChain(map).
EncodedNormalMap encodeNormalMapMips(const ReliefMap& map);
/// 16-bit grey height map scaled from [minimumHeight, maximumHeight] to [0, 65535].
std::vector<std::uint16_t> encodeHeightMap16(const ReliefMap& map);

}  // namespace dressed_human
