// A small CPU renderer for figures and tests: z-buffered triangles of TriangleMesh, Lambert
// shading (seed paper 000 Eq. 12, lambert_shading.h) with per-pixel interpolated normals, an
// orthographic or perspective camera, RGB output (png_writer.h). Reusable for skin pictures.
#pragma once

#include "dressed_human/core/surfaces/tessellation.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <string>
#include <vector>

namespace dressed_human {

struct RasterCamera {
  Eigen::Vector3d eye = Eigen::Vector3d(3.0, 0.0, 0.0);
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  double vertical_fov_radians = 0.0;  // > 0: perspective; 0: orthographic
  double ortho_height = 2.0;          // metres seen vertically (orthographic)
};

struct RasterMaterial {
  Eigen::Vector3d colour = Eigen::Vector3d(0.7, 0.7, 0.7);  // diffuse k_d per channel, [0, 1]
  double ambient = 0.18;                                    // added to Eq. 12's I (then clamped)
  double back_face_factor = 0.55;  // inside of open garments: darker, shaded with the flipped normal
};

class MeshRasterizer {
 public:
  // Throws std::invalid_argument for sizes < 1 or a degenerate camera.
  MeshRasterizer(int width, int height, const RasterCamera& camera);

  void clear(const Eigen::Vector3d& background);
  // Light: direction toward the light, world frame (need not be unit).
  void draw(const TriangleMesh& mesh, const RasterMaterial& material, const Eigen::Vector3d& light);

  int width() const { return width_; }
  int height() const { return height_; }
  // 8-bit RGB, rows top to bottom.
  std::vector<std::uint8_t> rgb() const;
  void writePng(const std::string& path) const;
  // Pixels covered by at least one triangle since the last clear().
  std::size_t coveredPixels() const;
  // Screen position (x right, y down, pixels) and camera depth of a world point.
  Eigen::Vector3d project(const Eigen::Vector3d& world) const;

 private:
  int width_;
  int height_;
  RasterCamera camera_;
  Eigen::Vector3d right_, up_, forward_;
  double focal_ = 0.0;
  std::vector<float> depth_;
  std::vector<Eigen::Vector3f> colour_;
};

}  // namespace dressed_human
