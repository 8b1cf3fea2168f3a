#include "dressed_human/core/relief/relief_map.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace dressed_human {

ReliefMap::ReliefMap(int width_pixels, int height_pixels) : width(width_pixels), height(height_pixels) {
  if (width_pixels <= 0 || height_pixels <= 0) {
    std::ostringstream message;
    message << "ReliefMap: width and height must be > 0, got " << width_pixels << " x " << height_pixels;
    throw std::invalid_argument(message.str());
  }
  const std::size_t count = static_cast<std::size_t>(width_pixels) * static_cast<std::size_t>(height_pixels);
  heights.assign(count, 0.0f);
  slope_u.assign(count, 0.0f);
  slope_v.assign(count, 0.0f);
}

Eigen::Vector3f ReliefMap::normalAt(int column, int row) const {
  const std::size_t at = index(column, row);
  return Eigen::Vector3f(-slope_u[at], -slope_v[at], 1.0f).normalized();
}

float ReliefMap::minimumHeight() const {
  return heights.empty() ? 0.0f : *std::min_element(heights.begin(), heights.end());
}

float ReliefMap::maximumHeight() const {
  return heights.empty() ? 0.0f : *std::max_element(heights.begin(), heights.end());
}

double rmsHeightDifference(const ReliefMap& a, const ReliefMap& b) {
  if (a.width != b.width || a.height != b.height) {
    throw std::invalid_argument("rmsHeightDifference: maps of " + std::to_string(a.width) + " x " +
                                std::to_string(a.height) + " and " + std::to_string(b.width) + " x " +
                                std::to_string(b.height) + " pixels");
  }
  double squares = 0.0;
  for (std::size_t i = 0; i < a.heights.size(); ++i) {
    const double d = static_cast<double>(a.heights[i]) - static_cast<double>(b.heights[i]);
    squares += d * d;
  }
  return a.heights.empty() ? 0.0 : std::sqrt(squares / static_cast<double>(a.heights.size()));
}

std::vector<ReliefMap> buildMipChain(ReliefMap base, int max_levels) {
  if (max_levels < 0) {
    std::ostringstream message;
    message << "buildMipChain: max_levels must be >= 0 (0 = no limit), got " << max_levels;
    throw std::invalid_argument(message.str());
  }
  std::vector<ReliefMap> chain;
  chain.push_back(std::move(base));
  while ((max_levels == 0 || static_cast<int>(chain.size()) < max_levels)) {
    const ReliefMap& fine = chain.back();
    if (fine.width < 2 || fine.height < 2 || fine.width % 2 != 0 || fine.height % 2 != 0) break;
    ReliefMap coarse(fine.width / 2, fine.height / 2);
    for (int row = 0; row < coarse.height; ++row) {
      for (int column = 0; column < coarse.width; ++column) {
        const std::size_t a = fine.index(2 * column, 2 * row);
        const std::size_t b = fine.index(2 * column + 1, 2 * row);
        const std::size_t c = fine.index(2 * column, 2 * row + 1);
        const std::size_t d = fine.index(2 * column + 1, 2 * row + 1);
        const std::size_t out = coarse.index(column, row);
        coarse.heights[out] = 0.25f * (fine.heights[a] + fine.heights[b] + fine.heights[c] + fine.heights[d]);
        coarse.slope_u[out] = 0.25f * (fine.slope_u[a] + fine.slope_u[b] + fine.slope_u[c] + fine.slope_u[d]);
        coarse.slope_v[out] = 0.25f * (fine.slope_v[a] + fine.slope_v[b] + fine.slope_v[c] + fine.slope_v[d]);
      }
    }
    chain.push_back(std::move(coarse));
  }
  return chain;
}

std::vector<std::uint8_t> encodeNormalMapRgb(const ReliefMap& map) {
  std::vector<std::uint8_t> rgb(map.heights.size() * 3);
  for (int row = 0; row < map.height; ++row) {
    for (int column = 0; column < map.width; ++column) {
      const Eigen::Vector3f normal = map.normalAt(column, row);
      const std::size_t at = map.index(column, row) * 3;
      for (int channel = 0; channel < 3; ++channel) {
        const float encoded = std::round((normal[channel] * 0.5f + 0.5f) * 255.0f);
        rgb[at + static_cast<std::size_t>(channel)] = static_cast<std::uint8_t>(std::clamp(encoded, 0.0f, 255.0f));
      }
    }
  }
  return rgb;
}

EncodedNormalMap encodeNormalMapMips(const ReliefMap& map) {
  EncodedNormalMap encoded;
  encoded.width = map.width;
  encoded.height = map.height;
  encoded.channels = 3;
  for (const ReliefMap& level : buildMipChain(map)) encoded.levels.push_back(encodeNormalMapRgb(level));
  return encoded;
}

std::vector<std::uint16_t> encodeHeightMap16(const ReliefMap& map) {
  const float low = map.minimumHeight();
  const float range = map.maximumHeight() - low;
  const float scale = range > 0.0f ? 65535.0f / range : 0.0f;
  std::vector<std::uint16_t> grey(map.heights.size());
  for (std::size_t at = 0; at < grey.size(); ++at) {
    grey[at] = static_cast<std::uint16_t>(std::clamp(std::round((map.heights[at] - low) * scale), 0.0f, 65535.0f));
  }
  return grey;
}

}  // namespace dressed_human
