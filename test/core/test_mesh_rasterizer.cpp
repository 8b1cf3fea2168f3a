// MeshRasterizer: coverage, depth order, shading, PNG output.
#include <gtest/gtest.h>

#include "dressed_human/core/render/mesh_rasterizer.h"

#include <cstdio>
#include <fstream>

#include "temp_file_path.h"

namespace dressed_human {
namespace {

TriangleMesh square(double x, const Eigen::Vector3f& normal) {
  TriangleMesh m;
  m.positions = {{static_cast<float>(x), -0.5f, -0.5f},
                 {static_cast<float>(x), 0.5f, -0.5f},
                 {static_cast<float>(x), 0.5f, 0.5f},
                 {static_cast<float>(x), -0.5f, 0.5f}};
  m.normals.assign(4, normal);
  m.indices = {0, 1, 2, 0, 2, 3};
  m.triangle_patch = {0, 0};
  return m;
}

TEST(MeshRasterizer, CoversTheProjectedAreaAndKeepsTheNearestSurface) {
  RasterCamera camera;
  camera.eye = Eigen::Vector3d(5, 0, 0);
  camera.ortho_height = 2.0;
  MeshRasterizer raster(100, 100, camera);
  RasterMaterial red, blue;
  red.colour = Eigen::Vector3d(1, 0, 0);
  blue.colour = Eigen::Vector3d(0, 0, 1);
  const Eigen::Vector3d light(1, 0, 0);
  raster.draw(square(0.5, Eigen::Vector3f(1, 0, 0)), red, light);           // nearer
  raster.draw(square(-0.5, Eigen::Vector3f(1, 0, 0)), blue, light);         // behind: hidden
  EXPECT_NEAR(static_cast<double>(raster.coveredPixels()), 2500.0, 150.0);  // 1 m x 1 m of 2 m x 2 m
  const std::vector<std::uint8_t> rgb = raster.rgb();
  const std::size_t centre = 3 * (50 * 100 + 50);
  EXPECT_EQ(rgb[centre], 255);  // lit head-on: Eq. 12 gives 1 (+ ambient, clamped)
  EXPECT_EQ(rgb[centre + 2], 0);
  EXPECT_EQ(rgb[0], 255);  // background white
  const std::string path = tempFilePath("raster.png");
  raster.writePng(path);
  std::ifstream file(path, std::ios::binary);
  char magic[4] = {};
  file.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  std::remove(path.c_str());
}

TEST(MeshRasterizer, ShadesByTheLambertCosineAndRejectsBadCameras) {
  RasterCamera camera;
  camera.eye = Eigen::Vector3d(5, 0, 0);
  MeshRasterizer raster(20, 20, camera);
  RasterMaterial white;
  white.colour = Eigen::Vector3d(1, 1, 1);
  white.ambient = 0.0;
  raster.draw(square(0.0, Eigen::Vector3f(1, 0, 0)), white, Eigen::Vector3d(1, 0, 1));  // 45 degrees
  EXPECT_NEAR(raster.rgb()[3 * (10 * 20 + 10)], 255.0 * std::sqrt(0.5), 1.0);
  camera.target = camera.eye;
  EXPECT_THROW(MeshRasterizer(10, 10, camera), std::invalid_argument);
  EXPECT_THROW(MeshRasterizer(0, 10, RasterCamera()), std::invalid_argument);
}

}  // namespace
}  // namespace dressed_human
