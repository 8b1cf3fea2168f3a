#pragma once
// Points spread over each triangle of a tessellation and the surface points they stand for: how a
// tessellation's error against its patches is measured (the tessellation_accuracy tool, the
// tessellator's tests), one way for both.

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dressed_human/core/surfaces/tessellation.h"

namespace dressed_human {

struct TriangleSample {
  std::size_t triangle = 0;
  Eigen::Vector3d on_mesh;  // the point of the flat triangle
  Eigen::Vector2d uv;       // its (u, v) on the triangle's patch: the same weights of the corners' (u, v)
  bool corner = false;      // one of the triangle's corners (they lie on the surface)
};

// Visits the points at barycentric weights (a, b, steps - a - b) / steps of every triangle of
// `mesh`; `corner_parameters` holds 3 (u, v) per triangle (Tessellator::triangleCornerParameters).
template <typename Visit>
void forEachTriangleSample(const TriangleMesh& mesh, const std::vector<Eigen::Vector2d>& corner_parameters, int steps,
                           const Visit& visit) {
  TriangleSample sample;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    sample.triangle = t;
    for (int a = 0; a <= steps; ++a) {
      for (int b = 0; a + b <= steps; ++b) {
        const double wa = static_cast<double>(a) / steps, wb = static_cast<double>(b) / steps, wc = 1.0 - wa - wb;
        sample.corner = a == steps || b == steps || a + b == 0;
        sample.uv =
            (wa * corner_parameters[3 * t] + wb * corner_parameters[3 * t + 1] + wc * corner_parameters[3 * t + 2])
                .cwiseMax(0.0)
                .cwiseMin(1.0);
        sample.on_mesh = wa * mesh.positions[mesh.indices[3 * t]].cast<double>() +
                         wb * mesh.positions[mesh.indices[3 * t + 1]].cast<double>() +
                         wc * mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
        visit(sample);
      }
    }
  }
}

}  // namespace dressed_human
