#include "dressed_human/core/relief/lambert_shading.h"
#include "dressed_human/core/io/png_writer.h"
#include "dressed_human/core/relief/relief_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "temp_file_path.h"

namespace dressed_human {
namespace {

TEST(PngWriter, ChecksumsMatchKnownValues) {
  const std::string iend = "IEND";
  EXPECT_EQ(crc32OfBytes(reinterpret_cast<const std::uint8_t*>(iend.data()), iend.size()), 0xAE426082u);
  const std::string wiki = "Wikipedia";
  EXPECT_EQ(adler32OfBytes(reinterpret_cast<const std::uint8_t*>(wiki.data()), wiki.size()), 0x11E60398u);
}

TEST(PngWriter, WritesAValidLookingFile) {
  const std::string path = tempFilePath("relief_test.png");
  std::vector<std::uint8_t> pixels(300 * 250 * 3);  // > 65535 bytes: several stored blocks
  for (std::size_t at = 0; at < pixels.size(); ++at) pixels[at] = static_cast<std::uint8_t>(at * 7);
  writePng8(path, 300, 250, 3, pixels);
  std::ifstream stream(path, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), pixels.size());
  EXPECT_EQ(bytes[1], 'P');
  EXPECT_EQ(bytes[12], 'I');
  EXPECT_EQ(bytes[16 + 3], 300 % 256);  // width, big-endian
  EXPECT_EQ(std::string(bytes.end() - 8, bytes.end() - 4), "IEND");
  std::remove(path.c_str());
  EXPECT_THROW(writePng8(path, 3, 3, 3, pixels), std::invalid_argument);
  EXPECT_THROW(writePng8(path, 300, 250, 5, pixels), std::invalid_argument);
}

TEST(ReliefMap, MipChainAveragesHeightAndGradient) {
  ReliefMap map(8, 4);
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 8; ++column) {
      map.heights[map.index(column, row)] = static_cast<float>(column + 10 * row);
      map.slope_u[map.index(column, row)] = 1.0f;
      map.slope_v[map.index(column, row)] = static_cast<float>(row);
    }
  }
  const std::vector<ReliefMap> chain = buildMipChain(map);
  ASSERT_EQ(chain.size(), 3u);  // 8x4, 4x2, 2x1 (stops at the odd height)
  EXPECT_EQ(chain[1].width, 4);
  EXPECT_EQ(chain[1].height, 2);
  EXPECT_FLOAT_EQ(chain[1].heights[chain[1].index(0, 0)], 0.25f * (0 + 1 + 10 + 11));
  EXPECT_FLOAT_EQ(chain[1].slope_v[chain[1].index(1, 1)], 2.5f);
  for (const ReliefMap& level : chain) {
    for (int row = 0; row < level.height; ++row)
      for (int column = 0; column < level.width; ++column) EXPECT_NEAR(level.normalAt(column, row).norm(), 1.0f, 1e-6f);
  }
  EXPECT_EQ(buildMipChain(map, 2).size(), 2u);
  EXPECT_THROW(ReliefMap(0, 3), std::invalid_argument);
}

// The slope an encoded normal (n + 1) / 2 * 255 stands for: -n_xy / n_z.
Eigen::Vector2f decodedSlope(const std::uint8_t* rgb) {
  const Eigen::Vector3f n(rgb[0] / 127.5f - 1.0f, rgb[1] / 127.5f - 1.0f, rgb[2] / 127.5f - 1.0f);
  return Eigen::Vector2f(-n.x() / n.z(), -n.y() / n.z());
}

// A crease one pixel wide (slope 2) beside three flat pixels, every 4 pixels along u.
ReliefMap creasedMap() {
  ReliefMap map(64, 64);
  for (int row = 0; row < map.height; ++row) {
    for (int column = 0; column < map.width; ++column)
      map.slope_u[map.index(column, row)] = column % 4 == 0 ? 2.0f : 0.0f;
  }
  return map;
}

TEST(EncodedNormalMap, EachLevelIsTheNormalOfTheFilteredSurface) {
  const ReliefMap map = creasedMap();
  const EncodedNormalMap encoded = encodeNormalMapMips(map);
  const std::vector<ReliefMap> chain = buildMipChain(map);
  ASSERT_EQ(encoded.levels.size(), 7u);  // 64 down to 1 x 1: a complete chain for the GPU
  ASSERT_EQ(chain.size(), encoded.levels.size());
  EXPECT_EQ(encoded.width, 64);
  EXPECT_EQ(encoded.channels, 3);
  EXPECT_EQ(encoded.levels[0], encodeNormalMapRgb(map));
  for (std::size_t level = 0; level < chain.size(); ++level) {
    ASSERT_EQ(encoded.levels[level].size(), static_cast<std::size_t>(chain[level].width * chain[level].height * 3));
    for (std::size_t at = 0; at < chain[level].heights.size(); ++at) {
      const Eigen::Vector2f slope = decodedSlope(&encoded.levels[level][3 * at]);
      EXPECT_NEAR(slope.x(), chain[level].slope_u[at], 0.03f) << "level " << level;  // 8-bit steps at slope 2
      EXPECT_NEAR(slope.y(), chain[level].slope_v[at], 0.03f) << "level " << level;
    }
  }
  // The 1 x 1 level: a quarter of the pixels at slope 2, the mean slope 0.5.
  EXPECT_NEAR(decodedSlope(encoded.levels.back().data()).x(), 0.5f, 0.01f);
}

TEST(EncodedNormalMap, AveragingTheEncodedNormalsWouldFlattenTheFolds) {
  // What a GPU's own chain does (glGenerateMipmap: 2 x 2 averages of the bytes), for contrast:
  // at the level where each texel spans a crease and its flat run, the mean slope 0.5 decodes as
  // about half of it. EachLevelIsTheNormalOfTheFilteredSurface holds the chain we upload to 0.01.
  std::vector<std::uint8_t> level = encodeNormalMapRgb(creasedMap());
  int width = 64;
  for (int step = 0; step < 2; ++step, width /= 2) {
    std::vector<std::uint8_t> coarse(static_cast<std::size_t>(width / 2) * static_cast<std::size_t>(width / 2) * 3);
    for (int row = 0; row < width / 2; ++row)
      for (int column = 0; column < width / 2; ++column)
        for (int channel = 0; channel < 3; ++channel) {
          int sum = 0;
          for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) sum += level[((2 * row + dy) * width + 2 * column + dx) * 3 + channel];
          coarse[(row * (width / 2) + column) * 3 + channel] = static_cast<std::uint8_t>((sum + 2) / 4);
        }
    level = coarse;
  }
  const float averaged = decodedSlope(level.data()).x();
  EXPECT_LT(averaged, 0.35f);
  EXPECT_GT(averaged, 0.15f);
  const EncodedNormalMap ours = encodeNormalMapMips(creasedMap());
  EXPECT_NEAR(decodedSlope(ours.levels[2].data()).x(), 0.5f, 0.01f);
}

TEST(LambertShading, Equation12) {
  EXPECT_DOUBLE_EQ(lambertIntensity({0, 0, 2}, {0, 0, 5}, 0.8, 0.5), 0.4);
  EXPECT_NEAR(lambertIntensity({1, 0, 1}, {0, 0, 1}), std::sqrt(0.5), 1e-15);
  EXPECT_DOUBLE_EQ(lambertIntensity({0, 0, -1}, {0, 0, 1}), 0.0);
  EXPECT_THROW(lambertIntensity({0, 0, 0}, {0, 0, 1}), std::invalid_argument);
  ReliefMap flat(2, 2);
  const std::vector<std::uint8_t> grey = shadeReliefMap(flat, {0, 0, 1});
  EXPECT_EQ(grey[0], 255);
}

}  // namespace
}  // namespace dressed_human
