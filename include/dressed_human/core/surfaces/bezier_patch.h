// Bicubic Bezier patch (SPEC §2, paper 000 Eq. 2-3):
//   F(u,v) = sum_i sum_j B_{i,3}(u) B_{j,3}(v) P_ij,   B_{i,3}(t) = C(3,i) (1-t)^{3-i} t^i,
// with i the u-index and j the v-index of the 16 control points, u, v in [0, 1].
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <vector>

namespace dressed_human {

// The four cubic Bernstein polynomials and their first two derivatives at one parameter value.
struct BernsteinWeights {
  Eigen::Vector4d value;
  Eigen::Vector4d first_derivative;
  Eigen::Vector4d second_derivative;
};

// B_{i,3}(t) and its derivatives of order 0..3 (index [order][i]); order 3 is constant.
std::array<Eigen::Vector4d, 4> cubicBernsteinDerivatives(double t);
BernsteinWeights cubicBernsteinWeights(double t);

// Bernstein weights for a fixed list of parameter values, computed once and reused for every patch
// and every frame: evaluating a grid then costs only multiply-adds against the control points.
class BernsteinTable {
 public:
  // Throws std::invalid_argument if a parameter is not finite or lies outside [0, 1].
  explicit BernsteinTable(const std::vector<double>& parameters);
  // segments + 1 values k / segments, k = 0..segments (segments >= 1).
  static BernsteinTable uniform(int segments);
  // The segments - 1 interior values k / segments, k = 1..segments-1 (segments >= 1; may be empty).
  static BernsteinTable uniformInterior(int segments);

  std::size_t size() const { return parameters_.size(); }
  double parameter(std::size_t k) const { return parameters_[k]; }
  const BernsteinWeights& weights(std::size_t k) const { return weights_[k]; }

 private:
  std::vector<double> parameters_;
  std::vector<BernsteinWeights> weights_;
};

// Position and partial derivatives of F at one (u,v).
struct PatchDerivatives {
  Eigen::Vector3d position;
  Eigen::Vector3d d_du;
  Eigen::Vector3d d_dv;
  Eigen::Vector3d d2_du2;
  Eigen::Vector3d d2_dudv;
  Eigen::Vector3d d2_dv2;
};

// What a tessellator stores per vertex: position, unit normal and the first partials
// (the bump-mapping frame). d_du or d_dv vanish on a collapsed edge; the normal never does.
struct PatchSample {
  Eigen::Vector3d position;
  Eigen::Vector3d normal;
  Eigen::Vector3d d_du;
  Eigen::Vector3d d_dv;
};

// Destination of a grid evaluation: each pointer addresses rows of the grid one after the other,
// u varying fastest (index = v_index * u_count + u_index). Single precision because these arrays
// go to the renderer; the evaluation itself runs in double.
struct SurfaceSampleArrays {
  Eigen::Vector3f* positions;
  Eigen::Vector3f* normals;
  Eigen::Vector3f* tangents_u;
  Eigen::Vector3f* tangents_v;
};

class BezierPatch {
 public:
  using ControlPoints = std::array<Eigen::Vector3d, 16>;

  // Index of P_ij in ControlPoints: the v = 0 row is entries 0..3.
  static constexpr int index(int i, int j) { return 4 * j + i; }

  // Throws std::invalid_argument if a control point is not finite or if all 16 coincide.
  explicit BezierPatch(const ControlPoints& control_points);
  // The same in place (posing a surface every frame without a temporary patch); same checks and
  // exceptions, and a throw leaves the patch unchanged.
  void setControlPoints(const ControlPoints& control_points);

  const ControlPoints& controlPoints() const { return control_points_; }
  const Eigen::Vector3d& controlPoint(int i, int j) const { return control_points_[index(i, j)]; }
  // Diagonal of the control net's axis-aligned bounding box: the patch's length scale.
  double scale() const { return scale_; }
  const Eigen::Vector3d& boundingBoxMin() const { return box_min_; }
  const Eigen::Vector3d& boundingBoxMax() const { return box_max_; }

  // Point queries; throw std::invalid_argument for (u,v) outside [0,1]^2 or not finite.
  Eigen::Vector3d position(double u, double v) const;
  PatchDerivatives derivatives(double u, double v) const;
  // Unit normal along d_du x d_dv; at degenerate points the limit normal (see the .cpp).
  Eigen::Vector3d normal(double u, double v) const;
  PatchSample sample(double u, double v) const;

  // Hot-path forms taking precomputed weights (no parameter checks, no allocation).
  PatchSample sample(const BernsteinWeights& u_weights, double u, const BernsteinWeights& v_weights, double v) const;
  // Evaluates the u_table.size() x v_table.size() grid into `out`.
  void evaluateGrid(const BernsteinTable& u_table, const BernsteinTable& v_table, const SurfaceSampleArrays& out) const;

 private:
  // Unit normal from d_du x d_dv, or the limit normal when that cross product (nearly) vanishes.
  Eigen::Vector3d unitNormal(const Eigen::Vector3d& d_du, const Eigen::Vector3d& d_dv, double u, double v) const;
  Eigen::Vector3d limitNormal(double u, double v) const;

  ControlPoints control_points_;  // packed: also the 3 x 16 matrix the evaluation contracts against
  Eigen::Vector3d box_min_;
  Eigen::Vector3d box_max_;
  double scale_ = 0.0;
  // |d_du x d_dv|^2 below this counts as degenerate (relative to scale^2, see the .cpp).
  double degenerate_cross_squared_ = 0.0;
};

}  // namespace dressed_human
