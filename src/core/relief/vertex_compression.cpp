#include "dressed_human/core/relief/vertex_compression.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace dressed_human {
namespace {

struct VertexStretchInput {
  const Eigen::Vector4f* inverse_rest_metric;
  const Eigen::Vector3f* tangents_u;
  const Eigen::Vector3f* tangents_v;
  std::size_t count;
  WrinkleStrengthConstants constants;
};

// The eigenvalues of M = G_rest^-1 G_posed at a vertex, from the inverse rest metric and the posed
// dF/du, dF/dv; undefined at a pole at rest (inverse zero) or in this pose (rank < 2). Selects
// rather than branches (the per-frame kernel below inlines it).
struct VertexMetric {
  float m11, m12, m21, m22;
  float lambda_min, lambda_max;
  bool defined;
};

inline VertexMetric vertexMetric(const Eigen::Vector4f& inverse, const Eigen::Vector3f& tu, const Eigen::Vector3f& tv) {
  VertexMetric m;
  const float e = tu.squaredNorm(), f = tu.dot(tv), g = tv.squaredNorm();
  m.m11 = inverse.x() * e + inverse.y() * f;
  m.m12 = inverse.x() * f + inverse.y() * g;
  m.m21 = inverse.y() * e + inverse.z() * f;
  m.m22 = inverse.y() * f + inverse.z() * g;
  const float half_difference = 0.5f * (m.m11 - m.m22);
  m.lambda_max = 0.5f * (m.m11 + m.m22) + std::sqrt(std::max(0.0f, half_difference * half_difference + m.m12 * m.m21));
  const float det_posed = e * g - f * f;
  m.lambda_min = std::max(0.0f, inverse.w() * det_posed / std::max(m.lambda_max, 1e-30f));
  m.defined = inverse.w() > 0.0f && det_posed > 1e-6f * e * g;
  return m;
}

// sqrt of the smaller eigenvalue, clamped to 1; 1 where undefined.
inline float stretchAlpha(const VertexMetric& m) { return m.defined ? std::min(1.0f, std::sqrt(m.lambda_min)) : 1.0f; }

// VertexStretch::fold_axis: the eigenvector of lambda_max (the most-stretched material direction,
// which the folds run along) as a double angle in (u, v), scaled by the anisotropy.
inline Eigen::Vector2f foldAxis(const VertexMetric& m) {
  const Eigen::Vector2f from_first(m.m12, m.lambda_max - m.m11);
  const Eigen::Vector2f from_second(m.lambda_max - m.m22, m.m21);
  const Eigen::Vector2f d = from_first.squaredNorm() >= from_second.squaredNorm() ? from_first : from_second;
  const float length2 = d.squaredNorm();
  const float sum = m.lambda_max + m.lambda_min;
  if (!m.defined || !(length2 > 0.0f) || !(sum > 0.0f)) return Eigen::Vector2f::Zero();
  const float anisotropy = (m.lambda_max - m.lambda_min) / sum;
  return Eigen::Vector2f(d.x() * d.x() - d.y() * d.y(), 2.0f * d.x() * d.y()) * (anisotropy / length2);
}

inline float strengthOf(float alpha, const WrinkleStrengthConstants& constants) {
  const float effective = std::min(1.0f, alpha * constants.inverse_threshold);
  return std::min(1.0f, std::sqrt(std::max(0.0f, 1.0f - effective * effective)) * constants.inverse_saturation);
}

// The per-frame kernel of VertexCompression::evaluate, outputs chosen at compile time (no
// per-vertex tests of the output pointers). Not vectorized by GCC at -O3 (sqrt's errno path is
// control flow); ~11 ns per vertex measured (bench_relief).
template <bool kAlpha, bool kStrength, bool kFoldAxis>
void vertexStretch(const VertexStretchInput& in, float* alpha, float* strength, Eigen::Vector2f* fold_axis) {
  for (std::size_t i = 0; i < in.count; ++i) {
    const VertexMetric m = vertexMetric(in.inverse_rest_metric[i], in.tangents_u[i], in.tangents_v[i]);
    const float a = stretchAlpha(m);
    if constexpr (kAlpha) alpha[i] = a;
    if constexpr (kStrength) strength[i] = strengthOf(a, in.constants);
    if constexpr (kFoldAxis) fold_axis[i] = foldAxis(m);
  }
}

}  // namespace

VertexCompression::VertexCompression(const WrinklePlacementOptions& options) : options_(options) {
  checkWrinklePlacementOptions(options_);
}

void VertexCompression::prepare(const TriangleMesh& mesh, const std::vector<BezierPatch>& rest_patches) {
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  const std::size_t vertices = mesh.vertexCount();
  if (mesh.uv.size() != vertices) {
    throw std::invalid_argument("VertexCompression: mesh has " + std::to_string(mesh.uv.size()) + " uv for " +
                                std::to_string(vertices) + " vertices");
  }
  vertex_patch_.assign(vertices, kNone);
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::uint32_t patch = mesh.triangle_patch.at(t);
    if (patch >= rest_patches.size()) {
      throw std::invalid_argument("VertexCompression: triangle " + std::to_string(t) + " lies on patch " +
                                  std::to_string(patch) + " of " + std::to_string(rest_patches.size()) +
                                  " rest patches");
    }
    for (int k = 0; k < 3; ++k) {
      std::uint32_t& owner = vertex_patch_.at(mesh.indices[3 * t + static_cast<std::size_t>(k)]);
      owner = std::min(owner, patch);
    }
  }
  uv_ = mesh.uv;
  inverse_rest_metric_.resize(vertices);
  for (std::size_t i = 0; i < vertices; ++i) {
    if (vertex_patch_[i] == kNone)
      throw std::invalid_argument("VertexCompression: vertex " + std::to_string(i) + " is on no triangle");
    const double u = std::clamp(static_cast<double>(uv_[i].x()), 0.0, 1.0);
    const double v = std::clamp(static_cast<double>(uv_[i].y()), 0.0, 1.0);
    const PatchDerivatives d = rest_patches[vertex_patch_[i]].derivatives(u, v);
    inverse_rest_metric_[i] = dressed_human::inverseRestMetric(d.d_du, d.d_dv);  // not the accessor
  }
}

Eigen::Vector4f inverseRestMetric(const Eigen::Vector3d& rest_du, const Eigen::Vector3d& rest_dv) {
  const double e = rest_du.squaredNorm(), f = rest_du.dot(rest_dv), g = rest_dv.squaredNorm();
  const double det = e * g - f * f;
  if (!(det > kSingularMetric * e * g)) return Eigen::Vector4f::Zero();  // a pole: reported as alpha = 1
  return Eigen::Vector4d(g / det, -f / det, e / det, 1.0 / det).cast<float>();
}

VertexStretch vertexStretchAt(const Eigen::Vector4f& inverse_rest_metric, const Eigen::Vector3f& d_du,
                              const Eigen::Vector3f& d_dv, const WrinkleStrengthConstants& constants) {
  const VertexMetric m = vertexMetric(inverse_rest_metric, d_du, d_dv);
  const float alpha = stretchAlpha(m);
  return {alpha, strengthOf(alpha, constants), foldAxis(m)};
}

WrinkleStrengthConstants VertexCompression::strengthConstants() const {
  return {static_cast<float>(1.0 / options_.alpha_threshold),
          static_cast<float>(1.0 / std::sqrt(1.0 - options_.saturation_alpha * options_.saturation_alpha))};
}

bool VertexCompression::preparedFor(const TriangleMesh& mesh) const {
  return mesh.uv.size() == uv_.size() && std::equal(uv_.begin(), uv_.end(), mesh.uv.begin());
}

void VertexCompression::evaluate(const TriangleMesh& posed_mesh, float* alpha, float* strength,
                                 Eigen::Vector2f* fold_axis) const {
  const std::size_t vertices = inverse_rest_metric_.size();
  if (posed_mesh.tangents_u.size() != vertices || posed_mesh.tangents_v.size() != vertices) {
    throw std::invalid_argument("VertexCompression: posed mesh has " + std::to_string(posed_mesh.tangents_u.size()) +
                                " vertices, prepared for " + std::to_string(vertices));
  }
  const VertexStretchInput input{inverse_rest_metric_.data(), posed_mesh.tangents_u.data(),
                                 posed_mesh.tangents_v.data(), vertices, strengthConstants()};
  // The renderer's per-frame pair (strength and fold axis) and the tests' pair (alpha and
  // strength) get kernels of their own; any other combination takes the general one.
  if (strength && fold_axis && !alpha) {
    vertexStretch<false, true, true>(input, alpha, strength, fold_axis);
  } else if (alpha && strength && !fold_axis) {
    vertexStretch<true, true, false>(input, alpha, strength, fold_axis);
  } else if (strength && !alpha && !fold_axis) {
    vertexStretch<false, true, false>(input, alpha, strength, fold_axis);
  } else {
    for (std::size_t i = 0; i < vertices; ++i) {
      const VertexStretch one =
          vertexStretchAt(inverse_rest_metric_[i], posed_mesh.tangents_u[i], posed_mesh.tangents_v[i], input.constants);
      if (alpha) alpha[i] = one.alpha;
      if (strength) strength[i] = one.strength;
      if (fold_axis) fold_axis[i] = one.fold_axis;
    }
  }
}

void VertexCompression::update(const TriangleMesh& posed_mesh, const std::vector<BezierPatch>& rest_patches,
                               std::vector<float>& strength) {
  if (!preparedFor(posed_mesh)) prepare(posed_mesh, rest_patches);
  strength.resize(posed_mesh.vertexCount());
  evaluate(posed_mesh, nullptr, strength.data());
}

}  // namespace dressed_human
