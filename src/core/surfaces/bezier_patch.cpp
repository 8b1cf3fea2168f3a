#include "dressed_human/core/surfaces/bezier_patch.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace dressed_human {

namespace {

// |d_du x d_dv| below this fraction of scale^2 is treated as a degenerate point. The cross product
// of a healthy patch is of order scale^2; rounding noise on an exactly collapsed edge is ~1e-16
// scale^2. 1e-10 sits far from both, and the limit normal used below it is continuous with the
// regular normal, so where exactly the switch happens does not show.
constexpr double kDegenerateCrossRelative = 1e-10;

void requireUnitParameter(double t, const char* name) {
  if (!(t >= 0.0 && t <= 1.0)) {
    std::ostringstream message;
    message << "Bezier patch parameter " << name << " = " << t << " is outside [0, 1]";
    throw std::invalid_argument(message.str());
  }
}

// The control net as a 3x16 matrix, column index(i, j); block 4j..4j+3 is the v-row j. A view
// of the control points themselves (16 packed Vector3d are that matrix's storage), not a copy:
// posing writes every patch every frame.
using ControlNet = Eigen::Map<const Eigen::Matrix<double, 3, 16>>;
using ControlRow = Eigen::Matrix<double, 3, 4>;
static_assert(sizeof(BezierPatch::ControlPoints) == 48 * sizeof(double), "control points must be packed");

ControlNet netOf(const BezierPatch::ControlPoints& points) { return ControlNet(points[0].data()); }

}  // namespace

std::array<Eigen::Vector4d, 4> cubicBernsteinDerivatives(double t) {
  const double s = 1.0 - t;
  std::array<Eigen::Vector4d, 4> d;
  d[0] << s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t;
  d[1] << -3.0 * s * s, 3.0 * s * (s - 2.0 * t), 3.0 * t * (2.0 * s - t), 3.0 * t * t;
  d[2] << 6.0 * s, 6.0 * (t - 2.0 * s), 6.0 * (s - 2.0 * t), 6.0 * t;
  d[3] << -6.0, 18.0, -18.0, 6.0;
  return d;
}

BernsteinWeights cubicBernsteinWeights(double t) {
  const std::array<Eigen::Vector4d, 4> d = cubicBernsteinDerivatives(t);
  return BernsteinWeights{d[0], d[1], d[2]};
}

BernsteinTable::BernsteinTable(const std::vector<double>& parameters) : parameters_(parameters) {
  weights_.reserve(parameters_.size());
  for (double t : parameters_) {
    requireUnitParameter(t, "t of a BernsteinTable");
    weights_.push_back(cubicBernsteinWeights(t));
  }
}

BernsteinTable BernsteinTable::uniform(int segments) {
  if (segments < 1) {
    throw std::invalid_argument("BernsteinTable::uniform needs at least 1 segment, got " + std::to_string(segments));
  }
  std::vector<double> parameters(static_cast<std::size_t>(segments) + 1);
  for (int k = 0; k <= segments; ++k) parameters[k] = static_cast<double>(k) / segments;
  return BernsteinTable(parameters);
}

BernsteinTable BernsteinTable::uniformInterior(int segments) {
  if (segments < 1) {
    throw std::invalid_argument("BernsteinTable::uniformInterior needs at least 1 segment, got " +
                                std::to_string(segments));
  }
  std::vector<double> parameters;
  for (int k = 1; k < segments; ++k) parameters.push_back(static_cast<double>(k) / segments);
  return BernsteinTable(parameters);
}

BezierPatch::BezierPatch(const ControlPoints& control_points) { setControlPoints(control_points); }

void BezierPatch::setControlPoints(const ControlPoints& control_points) {
  // Everything is checked on the input first, so that a throw leaves this patch as it was.
  // The net as one 3 x 16 matrix: checked and bounded in a few vector operations (this runs
  // for every patch every frame); the loop that names the culprit runs only on a bad point.
  const Eigen::Map<const Eigen::Matrix<double, 3, 16>> net(control_points.front().data());
  if (!net.allFinite()) {
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) {
        const Eigen::Vector3d& p = control_points[index(i, j)];
        if (p.allFinite()) continue;
        std::ostringstream message;
        message << "Bezier patch control point P[" << i << "][" << j << "] (u-index " << i << ", v-index " << j
                << ") is not finite: (" << p.x() << ", " << p.y() << ", " << p.z() << ")";
        throw std::invalid_argument(message.str());
      }
    }
  }
  const Eigen::Vector3d box_min = net.rowwise().minCoeff();
  const Eigen::Vector3d box_max = net.rowwise().maxCoeff();
  const double scale = (box_max - box_min).norm();
  if (!(scale > 0.0)) {
    throw std::invalid_argument("Bezier patch: all 16 control points coincide, the patch is a point");
  }
  control_points_ = control_points;
  box_min_ = box_min;
  box_max_ = box_max;
  scale_ = scale;
  const double threshold = kDegenerateCrossRelative * scale_ * scale_;
  degenerate_cross_squared_ = threshold * threshold;
}

namespace {

// sum_j weight_j * (v-row j): the patch restricted to one v, as a cubic curve in u.
ControlRow contractV(const ControlNet& net, const Eigen::Vector4d& v_weights) {
  return v_weights[0] * net.middleCols<4>(0) + v_weights[1] * net.middleCols<4>(4) +
         v_weights[2] * net.middleCols<4>(8) + v_weights[3] * net.middleCols<4>(12);
}

// Position and first partials at (u, v) from the net contracted in v (with the v weights and
// their derivative) and the u weights.
template <typename Terms>
void firstOrderTerms(const ControlRow& row, const ControlRow& row_dv, const BernsteinWeights& u_weights, Terms& terms) {
  terms.position = row * u_weights.value;
  terms.d_du = row * u_weights.first_derivative;
  terms.d_dv = row_dv * u_weights.value;
}

}  // namespace

Eigen::Vector3d BezierPatch::position(double u, double v) const {
  requireUnitParameter(u, "u");
  requireUnitParameter(v, "v");
  const ControlNet net = netOf(control_points_);
  return contractV(net, cubicBernsteinWeights(v).value) * cubicBernsteinWeights(u).value;
}

PatchDerivatives BezierPatch::derivatives(double u, double v) const {
  requireUnitParameter(u, "u");
  requireUnitParameter(v, "v");
  const ControlNet net = netOf(control_points_);
  const BernsteinWeights bu = cubicBernsteinWeights(u);
  const BernsteinWeights bv = cubicBernsteinWeights(v);
  const ControlRow row = contractV(net, bv.value);
  const ControlRow row_dv = contractV(net, bv.first_derivative);
  PatchDerivatives d;
  firstOrderTerms(row, row_dv, bu, d);
  d.d2_du2 = row * bu.second_derivative;
  d.d2_dudv = row_dv * bu.first_derivative;
  d.d2_dv2 = contractV(net, bv.second_derivative) * bu.value;
  return d;
}

Eigen::Vector3d BezierPatch::normal(double u, double v) const {
  const PatchDerivatives d = derivatives(u, v);
  return unitNormal(d.d_du, d.d_dv, u, v);
}

PatchSample BezierPatch::sample(double u, double v) const {
  requireUnitParameter(u, "u");
  requireUnitParameter(v, "v");
  return sample(cubicBernsteinWeights(u), u, cubicBernsteinWeights(v), v);
}

PatchSample BezierPatch::sample(const BernsteinWeights& u_weights, double u, const BernsteinWeights& v_weights,
                                double v) const {
  PatchSample s;
  const ControlNet net = netOf(control_points_);
  firstOrderTerms(contractV(net, v_weights.value), contractV(net, v_weights.first_derivative), u_weights, s);
  s.normal = unitNormal(s.d_du, s.d_dv, u, v);
  return s;
}

void BezierPatch::evaluateGrid(const BernsteinTable& u_table, const BernsteinTable& v_table,
                               const SurfaceSampleArrays& out) const {
  const ControlNet net = netOf(control_points_);
  const std::size_t u_count = u_table.size();
  std::size_t k = 0;
  for (std::size_t b = 0; b < v_table.size(); ++b) {
    // Contracting over v once per row leaves 4 points per u sample: 3 small mat-vec products.
    const BernsteinWeights& bv = v_table.weights(b);
    const ControlRow row = contractV(net, bv.value);
    const ControlRow row_dv = contractV(net, bv.first_derivative);
    for (std::size_t a = 0; a < u_count; ++a, ++k) {
      const BernsteinWeights& bu = u_table.weights(a);
      const Eigen::Vector3d position = row * bu.value;
      const Eigen::Vector3d d_du = row * bu.first_derivative;
      const Eigen::Vector3d d_dv = row_dv * bu.value;
      const Eigen::Vector3d cross = d_du.cross(d_dv);
      const double cross_squared = cross.squaredNorm();
      const Eigen::Vector3d normal = cross_squared > degenerate_cross_squared_
                                         ? Eigen::Vector3d(cross / std::sqrt(cross_squared))
                                         : limitNormal(u_table.parameter(a), v_table.parameter(b));
      out.positions[k] = position.cast<float>();
      out.normals[k] = normal.cast<float>();
      out.tangents_u[k] = d_du.cast<float>();
      out.tangents_v[k] = d_dv.cast<float>();
    }
  }
}

Eigen::Vector3d BezierPatch::unitNormal(const Eigen::Vector3d& d_du, const Eigen::Vector3d& d_dv, double u,
                                        double v) const {
  const Eigen::Vector3d cross = d_du.cross(d_dv);
  const double cross_squared = cross.squaredNorm();
  if (cross_squared > degenerate_cross_squared_) return cross / std::sqrt(cross_squared);
  return limitNormal(u, v);
}

// Limit normal at a point where d_du x d_dv vanishes (a collapsed edge such as a cap's pole, a
// corner where two control points coincide or where d_du is parallel to d_dv).
//
// Why this method: the normal there is defined as the limit of the regular normal N/|N|,
// N = F_u x F_v, when the point is approached from inside the patch. Along the segment
// (u, v) + t (du, dv), t >= 0, N(t) is a polynomial in t (degree <= 10), N(t) = sum_k N_k t^k, and
// for small t > 0 its direction tends to that of the lowest-order non-zero coefficient N_k. The
// coefficients are exact: a bicubic is its own Taylor series,
//   F(u+s, v+r) = sum_{a,b<=3} D_ab s^a r^b / (a! b!),  D_ab = d^{a+b}F / du^a dv^b (Bernstein
// derivatives contracted with the net), so F_u(t) and F_v(t) have closed-form coefficients and
// N_k = sum_m F_u,m x F_v,k-m. This needs no finite step (no guessed epsilon inside the patch, no
// cancellation) and covers every degeneracy order: on a collapsed v = 0 edge F_u = F_uu = 0, so N_1
// is dv (F_uv x F_v), the classical pole normal, the same for every approach direction; where two
// collapsed edges meet, orders 2+ take over. Approaching toward the patch centre picks the
// one-sided limit from the inside at corners, where the limit may depend on the direction.
Eigen::Vector3d BezierPatch::limitNormal(double u, double v) const {
  const ControlNet net = netOf(control_points_);
  const std::array<Eigen::Vector4d, 4> bu = cubicBernsteinDerivatives(u);
  const std::array<Eigen::Vector4d, 4> bv = cubicBernsteinDerivatives(v);
  Eigen::Vector3d derivative[4][4];  // [a][b] = d^{a+b}F / du^a dv^b
  for (int b = 0; b < 4; ++b) {
    const ControlRow row = contractV(net, bv[b]);
    for (int a = 0; a < 4; ++a) derivative[a][b] = row * bu[a];
  }

  Eigen::Vector2d direction(0.5 - u, 0.5 - v);
  // At the centre itself any direction is "inside"; take +u.
  direction = direction.norm() > 1e-12 ? direction.normalized() : Eigen::Vector2d(1.0, 0.0);
  const double du = direction.x();
  const double dv = direction.y();
  const double du_power[4] = {1.0, du, du * du, du * du * du};
  const double dv_power[4] = {1.0, dv, dv * dv, dv * dv * dv};
  constexpr double factorial[4] = {1.0, 1.0, 2.0, 6.0};

  // Taylor coefficients in t of F_u and F_v along the segment (degree <= 5 each).
  Eigen::Vector3d f_u[6];
  Eigen::Vector3d f_v[6];
  for (int k = 0; k < 6; ++k) f_u[k] = f_v[k] = Eigen::Vector3d::Zero();
  for (int a = 1; a < 4; ++a) {
    for (int b = 0; b < 4; ++b) {
      f_u[a - 1 + b] += derivative[a][b] * (du_power[a - 1] * dv_power[b] / (factorial[a - 1] * factorial[b]));
    }
  }
  for (int a = 0; a < 4; ++a) {
    for (int b = 1; b < 4; ++b) {
      f_v[a + b - 1] += derivative[a][b] * (du_power[a] * dv_power[b - 1] / (factorial[a] * factorial[b - 1]));
    }
  }
  for (int k = 0; k <= 10; ++k) {
    Eigen::Vector3d coefficient = Eigen::Vector3d::Zero();
    for (int m = std::max(0, k - 5); m <= std::min(k, 5); ++m) coefficient += f_u[m].cross(f_v[k - m]);
    if (coefficient.squaredNorm() > degenerate_cross_squared_) return coefficient.normalized();
  }
  std::ostringstream message;
  message << "Bezier patch has no tangent plane near (u, v) = (" << u << ", " << v
          << "): the surface degenerates to a curve or a point along the way into the patch";
  throw std::domain_error(message.str());
}

}  // namespace dressed_human
