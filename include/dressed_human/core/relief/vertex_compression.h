// Per-vertex compression for a renderer, every frame (wrinkle_placement.h explains the measure):
// the wrinkle strength and fold axis at each mesh vertex of a posed garment, from its rest metric
// and the posed tangents. relief_surface.vert transcribes vertexStretchAt to GLSL.
#pragma once

#include "dressed_human/core/relief/wrinkle_placement.h"
#include "dressed_human/core/surfaces/bezier_patch.h"
#include "dressed_human/core/surfaces/tessellation.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace dressed_human {

/// Per-vertex compression for a renderer, every frame. prepare() (once per mesh layout) finds
/// each vertex's patch -- the Tessellator gives a shared vertex to the lowest-index patch that
/// has it, and its uv and tangents are that patch's -- and stores the inverse rest metric
/// there; evaluate() then reads only the posed mesh's tangents: a 2x2 eigenvalue per vertex,
/// no allocation, no patch evaluation.
/// The per-vertex strength formula's constants (see VertexCompression::evaluate), for a renderer
/// that evaluates the strength itself (the GLSL vertex shader):
/// strength = min(1, sqrt(max(0, 1 - min(1, alpha * inverse_threshold)^2)) * inverse_saturation).
struct WrinkleStrengthConstants {
  float inverse_threshold = 1.0f;
  float inverse_saturation = 1.0f;
};

/// One vertex of VertexCompression::evaluate -- which relief_surface.vert transcribes to GLSL:
/// alpha (1 = none) and the wrinkle strength from G_rest^-1 (inverseRestMetric()) and the posed
/// dF/du, dF/dv.
struct VertexStretch {
  float alpha = 1.0f;
  float strength = 0.0f;
  /// Which way the folds run (oriented_folds.h): the posed surface's most-stretched material
  /// direction (across the compression, in both metrics), as the double angle
  /// (cos 2 phi, sin 2 phi) of its angle phi in (u, v) -- a direction, not a vector: d and -d
  /// are the same folds -- scaled by the anisotropy (lambda_max - lambda_min) / (lambda_max +
  /// lambda_min) of G_rest^-1 G_posed. Zero where the cloth is shortened alike in every
  /// direction (no preferred fold direction) or at a pole. Interpolates across a triangle.
  Eigen::Vector2f fold_axis = Eigen::Vector2f::Zero();
};
/// G_rest^-1 as (a, b, c) = [[a, b], [b, c]] and det(G_rest^-1) from the rest dF/du, dF/dv; all
/// zero at a pole (VertexCompression::inverseRestMetric).
Eigen::Vector4f inverseRestMetric(const Eigen::Vector3d& rest_du, const Eigen::Vector3d& rest_dv);
VertexStretch vertexStretchAt(const Eigen::Vector4f& inverse_rest_metric, const Eigen::Vector3f& d_du,
                              const Eigen::Vector3f& d_dv, const WrinkleStrengthConstants& constants);

class VertexCompression {
 public:
  explicit VertexCompression(const WrinklePlacementOptions& options = {});

  /// `mesh`: any tessellation of the garment (its indices, triangle_patch and uv are read);
  /// `rest_patches`: the garment at rest (WrinklePlacement::restPatches(), or a Garment's
  /// patches() right after construction). Throws std::invalid_argument for a vertex on no
  /// triangle or a patch index beyond rest_patches.
  void prepare(const TriangleMesh& mesh, const std::vector<BezierPatch>& rest_patches);
  /// True when prepare() was done for this layout (same vertex count and uv).
  bool preparedFor(const TriangleMesh& mesh) const;
  /// Per vertex of the posed mesh: alpha (1 = none), wrinkle strength in [0, 1]
  /// (sqrt(1 - alpha_effective^2) / sqrt(1 - saturation^2), clamped) and the fold axis
  /// (VertexStretch); any may be null. Throws std::invalid_argument when the mesh does not have
  /// the prepared vertex count.
  void evaluate(const TriangleMesh& posed_mesh, float* alpha, float* strength,
                Eigen::Vector2f* fold_axis = nullptr) const;
  /// prepare() if the layout changed, then evaluate() into `strength` (resized; no allocation
  /// while the layout stays).
  void update(const TriangleMesh& posed_mesh, const std::vector<BezierPatch>& rest_patches,
              std::vector<float>& strength);

  const std::vector<std::uint32_t>& vertexPatches() const { return vertex_patch_; }
  /// Per prepared vertex: G_rest^-1 as (a, b, c) = [[a, b], [b, c]] and det(G_rest^-1); all zero
  /// at a pole. With the posed dF/du, dF/dv this is all evaluate() needs per vertex.
  const std::vector<Eigen::Vector4f>& inverseRestMetric() const { return inverse_rest_metric_; }
  WrinkleStrengthConstants strengthConstants() const;

 private:
  WrinklePlacementOptions options_;
  std::vector<std::uint32_t> vertex_patch_;
  std::vector<Eigen::Vector2f> uv_;
  // Inverse rest metric (a, b, c) = G_rest^-1 = [[a, b], [b, c]] and det(G_rest^-1); zero: pole.
  std::vector<Eigen::Vector4f> inverse_rest_metric_;
};

}  // namespace dressed_human
