#include "dressed_human/core/render/mesh_rasterizer.h"

#include "dressed_human/core/relief/lambert_shading.h"
#include "dressed_human/core/io/png_writer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace dressed_human {

MeshRasterizer::MeshRasterizer(int width, int height, const RasterCamera& camera)
    : width_(width), height_(height), camera_(camera) {
  if (width < 1 || height < 1) throw std::invalid_argument("MeshRasterizer: image size must be >= 1 x 1");
  forward_ = camera.target - camera.eye;
  if (forward_.norm() < 1e-12) throw std::invalid_argument("MeshRasterizer: camera eye and target coincide");
  forward_.normalize();
  right_ = forward_.cross(camera.up);
  if (right_.norm() < 1e-12) throw std::invalid_argument("MeshRasterizer: camera up is parallel to the view direction");
  right_.normalize();
  up_ = right_.cross(forward_);
  if (camera.vertical_fov_radians > 0.0) {
    focal_ = 0.5 * height / std::tan(0.5 * camera.vertical_fov_radians);
  } else if (!(camera.ortho_height > 0.0)) {
    throw std::invalid_argument("MeshRasterizer: orthographic height must be > 0");
  }
  clear(Eigen::Vector3d::Ones());
}

void MeshRasterizer::clear(const Eigen::Vector3d& background) {
  depth_.assign(static_cast<std::size_t>(width_) * height_, std::numeric_limits<float>::infinity());
  colour_.assign(depth_.size(), background.cast<float>());
}

Eigen::Vector3d MeshRasterizer::project(const Eigen::Vector3d& world) const {
  const Eigen::Vector3d d = world - camera_.eye;
  const double x = right_.dot(d), y = up_.dot(d), z = forward_.dot(d);
  if (focal_ > 0.0) {
    return Eigen::Vector3d(0.5 * width_ + focal_ * x / z, 0.5 * height_ - focal_ * y / z, z);
  }
  const double s = height_ / camera_.ortho_height;
  return Eigen::Vector3d(0.5 * width_ + s * x, 0.5 * height_ - s * y, z);
}

void MeshRasterizer::draw(const TriangleMesh& mesh, const RasterMaterial& material, const Eigen::Vector3d& light) {
  std::vector<Eigen::Vector3d> screen(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) screen[v] = project(mesh.positions[v].cast<double>());
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::uint32_t ia = mesh.indices[3 * t], ib = mesh.indices[3 * t + 1], ic = mesh.indices[3 * t + 2];
    const Eigen::Vector3d &a = screen[ia], &b = screen[ib], &c = screen[ic];
    if (focal_ > 0.0 && (a.z() <= 1e-6 || b.z() <= 1e-6 || c.z() <= 1e-6)) continue;  // behind the eye
    const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    if (std::abs(area) < 1e-12) continue;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))));
    const int x1 = std::min(width_ - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))));
    const int y1 = std::min(height_ - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}))));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        const double w0 = ((b.x() - px) * (c.y() - py) - (b.y() - py) * (c.x() - px)) / area;
        const double w1 = ((c.x() - px) * (a.y() - py) - (c.y() - py) * (a.x() - px)) / area;
        const double w2 = 1.0 - w0 - w1;
        if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) continue;
        const double z = w0 * a.z() + w1 * b.z() + w2 * c.z();
        const std::size_t k = static_cast<std::size_t>(y) * width_ + x;
        if (z >= depth_[k]) continue;
        depth_[k] = static_cast<float>(z);
        Eigen::Vector3d n = (w0 * mesh.normals[ia] + w1 * mesh.normals[ib] + w2 * mesh.normals[ic]).cast<double>();
        if (n.norm() < 1e-12) n = -forward_;
        // Facing away from the viewer: the inside of a garment; shade it with the flipped normal.
        const Eigen::Vector3d world =
            (w0 * mesh.positions[ia] + w1 * mesh.positions[ib] + w2 * mesh.positions[ic]).cast<double>();
        const Eigen::Vector3d to_eye = focal_ > 0.0 ? Eigen::Vector3d(camera_.eye - world) : Eigen::Vector3d(-forward_);
        double factor = 1.0;
        if (n.dot(to_eye) < 0.0) {
          n = -n;
          factor = material.back_face_factor;
        }
        const double intensity = std::min(1.0, material.ambient + lambertIntensity(light, n));
        colour_[k] = (factor * intensity * material.colour).cast<float>();
      }
    }
  }
}

std::vector<std::uint8_t> MeshRasterizer::rgb() const {
  std::vector<std::uint8_t> out(colour_.size() * 3);
  for (std::size_t k = 0; k < colour_.size(); ++k) {
    for (int c = 0; c < 3; ++c) {
      out[3 * k + c] =
          static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(static_cast<double>(colour_[k][c]), 0.0, 1.0)));
    }
  }
  return out;
}

void MeshRasterizer::writePng(const std::string& path) const { writePng8(path, width_, height_, 3, rgb()); }

std::size_t MeshRasterizer::coveredPixels() const {
  return static_cast<std::size_t>(
      std::count_if(depth_.begin(), depth_.end(), [](float d) { return std::isfinite(d); }));
}

}  // namespace dressed_human
