#include "dressed_human/core/surfaces/bezier_patch.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace dressed_human {
namespace {

BezierPatch::ControlPoints randomControlPoints(std::mt19937& random) {
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  BezierPatch::ControlPoints points;
  for (Eigen::Vector3d& p : points) p = {coordinate(random), coordinate(random), coordinate(random)};
  return points;
}

// Independent reference: repeated linear interpolation, first along u within each v-row, then
// along v through the four results.
Eigen::Vector3d deCasteljau(const std::array<Eigen::Vector3d, 4>& points, double t) {
  std::array<Eigen::Vector3d, 4> level = points;
  for (int size = 3; size > 0; --size) {
    for (int k = 0; k < size; ++k) level[k] = (1.0 - t) * level[k] + t * level[k + 1];
  }
  return level[0];
}

Eigen::Vector3d deCasteljau(const BezierPatch::ControlPoints& points, double u, double v) {
  std::array<Eigen::Vector3d, 4> column;
  for (int j = 0; j < 4; ++j) {
    column[j] = deCasteljau({points[BezierPatch::index(0, j)], points[BezierPatch::index(1, j)],
                             points[BezierPatch::index(2, j)], points[BezierPatch::index(3, j)]},
                            u);
  }
  return deCasteljau(column, v);
}

std::vector<double> parametersWithEnds() { return {0.0, 1e-9, 0.013, 0.2, 0.25, 0.5, 0.61, 0.77, 0.999, 1.0}; }

TEST(Bernstein, PartitionOfUnityAndDerivativesSumToZero) {
  for (double t : parametersWithEnds()) {
    const std::array<Eigen::Vector4d, 4> d = cubicBernsteinDerivatives(t);
    EXPECT_NEAR(d[0].sum(), 1.0, 1e-15);
    for (int order = 1; order < 4; ++order) EXPECT_NEAR(d[order].sum(), 0.0, 1e-13);
    for (int i = 0; i < 4; ++i) {
      const double binomial[4] = {1, 3, 3, 1};
      EXPECT_NEAR(d[0][i], binomial[i] * std::pow(1.0 - t, 3 - i) * std::pow(t, i), 1e-15);
    }
  }
}

TEST(Bernstein, TableRejectsParametersOutsideTheUnitInterval) {
  EXPECT_THROW(BernsteinTable({0.5, 1.5}), std::invalid_argument);
  EXPECT_THROW(BernsteinTable({std::nan("")}), std::invalid_argument);
  EXPECT_THROW(BernsteinTable::uniform(0), std::invalid_argument);
  const BernsteinTable table = BernsteinTable::uniform(4);
  ASSERT_EQ(table.size(), 5u);
  EXPECT_DOUBLE_EQ(table.parameter(3), 0.75);
  EXPECT_EQ(BernsteinTable::uniformInterior(4).size(), 3u);
  EXPECT_EQ(BernsteinTable::uniformInterior(1).size(), 0u);
}

TEST(BezierPatch, EvaluationMatchesDeCasteljau) {
  std::mt19937 random(1);
  for (int trial = 0; trial < 20; ++trial) {
    const BezierPatch::ControlPoints points = randomControlPoints(random);
    const BezierPatch patch(points);
    for (double u : parametersWithEnds()) {
      for (double v : parametersWithEnds()) {
        const Eigen::Vector3d expected = deCasteljau(points, u, v);
        EXPECT_LT((patch.position(u, v) - expected).norm(), 1e-12) << u << ", " << v;
        EXPECT_LT((patch.derivatives(u, v).position - expected).norm(), 1e-12);
        EXPECT_LT((patch.sample(u, v).position - expected).norm(), 1e-12);
      }
    }
  }
}

TEST(BezierPatch, CornersInterpolateTheCornerControlPoints) {
  std::mt19937 random(2);
  const BezierPatch::ControlPoints points = randomControlPoints(random);
  const BezierPatch patch(points);
  EXPECT_EQ(patch.position(0, 0), points[BezierPatch::index(0, 0)]);
  EXPECT_LT((patch.position(1, 0) - points[BezierPatch::index(3, 0)]).norm(), 1e-15);
  EXPECT_LT((patch.position(0, 1) - points[BezierPatch::index(0, 3)]).norm(), 1e-15);
  EXPECT_LT((patch.position(1, 1) - points[BezierPatch::index(3, 3)]).norm(), 1e-15);
}

TEST(BezierPatch, DerivativesMatchCentralFiniteDifferences) {
  std::mt19937 random(3);
  const double h = 1e-5;
  for (int trial = 0; trial < 10; ++trial) {
    const BezierPatch patch(randomControlPoints(random));
    for (double u : {0.1, 0.37, 0.5, 0.9}) {
      for (double v : {0.05, 0.42, 0.8}) {
        const PatchDerivatives d = patch.derivatives(u, v);
        const Eigen::Vector3d fd_u = (patch.position(u + h, v) - patch.position(u - h, v)) / (2 * h);
        const Eigen::Vector3d fd_v = (patch.position(u, v + h) - patch.position(u, v - h)) / (2 * h);
        EXPECT_LT((d.d_du - fd_u).norm(), 1e-8);
        EXPECT_LT((d.d_dv - fd_v).norm(), 1e-8);
        // Second partials as differences of the (already checked) first partials.
        const Eigen::Vector3d fd_uu = (patch.derivatives(u + h, v).d_du - patch.derivatives(u - h, v).d_du) / (2 * h);
        const Eigen::Vector3d fd_vv = (patch.derivatives(u, v + h).d_dv - patch.derivatives(u, v - h).d_dv) / (2 * h);
        const Eigen::Vector3d fd_uv = (patch.derivatives(u, v + h).d_du - patch.derivatives(u, v - h).d_du) / (2 * h);
        const Eigen::Vector3d fd_vu = (patch.derivatives(u + h, v).d_dv - patch.derivatives(u - h, v).d_dv) / (2 * h);
        EXPECT_LT((d.d2_du2 - fd_uu).norm(), 1e-7);
        EXPECT_LT((d.d2_dv2 - fd_vv).norm(), 1e-7);
        EXPECT_LT((d.d2_dudv - fd_uv).norm(), 1e-7);
        EXPECT_LT((d.d2_dudv - fd_vu).norm(), 1e-7);
        // Second partials straight from positions, coarser step.
        const double k = 1e-4;
        const Eigen::Vector3d fd2_uu =
            (patch.position(u + k, v) - 2 * patch.position(u, v) + patch.position(u - k, v)) / (k * k);
        EXPECT_LT((d.d2_du2 - fd2_uu).norm(), 1e-5);
      }
    }
  }
}

TEST(BezierPatch, GridEvaluationMatchesPointEvaluation) {
  std::mt19937 random(4);
  const BezierPatch patch(randomControlPoints(random));
  const BernsteinTable u_table({0.0, 0.3, 0.5, 1.0});
  const BernsteinTable v_table = BernsteinTable::uniform(6);
  const std::size_t count = u_table.size() * v_table.size();
  std::vector<Eigen::Vector3f> positions(count), normals(count), tangents_u(count), tangents_v(count);
  patch.evaluateGrid(u_table, v_table, {positions.data(), normals.data(), tangents_u.data(), tangents_v.data()});
  for (std::size_t b = 0; b < v_table.size(); ++b) {
    for (std::size_t a = 0; a < u_table.size(); ++a) {
      const std::size_t k = b * u_table.size() + a;
      const PatchSample s = patch.sample(u_table.parameter(a), v_table.parameter(b));
      EXPECT_LT((positions[k].cast<double>() - s.position).norm(), 1e-6);
      EXPECT_LT((normals[k].cast<double>() - s.normal).norm(), 1e-6);
      EXPECT_LT((tangents_u[k].cast<double>() - s.d_du).norm(), 1e-5);
      EXPECT_LT((tangents_v[k].cast<double>() - s.d_dv).norm(), 1e-5);
      const PatchSample from_weights =
          patch.sample(u_table.weights(a), u_table.parameter(a), v_table.weights(b), v_table.parameter(b));
      EXPECT_LT((from_weights.position - s.position).norm(), 1e-15);
    }
  }
}

TEST(BezierPatch, RegularNormalIsTheUnitCrossProductOfThePartials) {
  std::mt19937 random(5);
  const BezierPatch patch(randomControlPoints(random));
  for (double u : parametersWithEnds()) {
    for (double v : parametersWithEnds()) {
      const PatchDerivatives d = patch.derivatives(u, v);
      const Eigen::Vector3d n = patch.normal(u, v);
      EXPECT_NEAR(n.norm(), 1.0, 1e-12);
      EXPECT_LT((n - d.d_du.cross(d.d_dv).normalized()).norm(), 1e-9);
    }
  }
}

// ---------------------------------------------------------------- degenerate patches

// Copies the edge's four control points onto its first one: a pole.
BezierPatch::ControlPoints collapseEdge(BezierPatch::ControlPoints points, const std::string& edge) {
  for (int k = 0; k < 4; ++k) {
    if (edge == "v0") points[BezierPatch::index(k, 0)] = points[BezierPatch::index(0, 0)];
    if (edge == "v1") points[BezierPatch::index(k, 3)] = points[BezierPatch::index(0, 3)];
    if (edge == "u0") points[BezierPatch::index(0, k)] = points[BezierPatch::index(0, 0)];
    if (edge == "u1") points[BezierPatch::index(3, k)] = points[BezierPatch::index(3, 0)];
  }
  return points;
}

void expectUnitFiniteNormalsEverywhere(const BezierPatch& patch) {
  const BernsteinTable table = BernsteinTable::uniform(16);
  const std::size_t count = table.size() * table.size();
  std::vector<Eigen::Vector3f> positions(count), normals(count), tangents_u(count), tangents_v(count);
  patch.evaluateGrid(table, table, {positions.data(), normals.data(), tangents_u.data(), tangents_v.data()});
  for (const Eigen::Vector3f& n : normals) {
    ASSERT_TRUE(n.allFinite());
    EXPECT_NEAR(n.norm(), 1.0f, 1e-6f);
  }
  for (double u : parametersWithEnds()) {
    for (double v : parametersWithEnds()) {
      const Eigen::Vector3d n = patch.normal(u, v);
      ASSERT_TRUE(n.allFinite()) << u << ", " << v;
      EXPECT_NEAR(n.norm(), 1.0, 1e-12) << u << ", " << v;
    }
  }
}

TEST(BezierPatch, CollapsedEdgeHasTheLimitNormalOnEveryEdge) {
  std::mt19937 random(6);
  for (const std::string edge : {"v0", "v1", "u0", "u1"}) {
    for (int trial = 0; trial < 5; ++trial) {
      const BezierPatch patch(collapseEdge(randomControlPoints(random), edge));
      expectUnitFiniteNormalsEverywhere(patch);
      for (double t : {0.0, 0.1, 0.5, 0.8, 1.0}) {
        // On the pole and a little inside the patch, moving away from the pole.
        double u = t, v = t, inside_u = t, inside_v = t;
        const double step = 1e-7;
        if (edge == "v0") {
          v = 0.0;
          inside_v = step;
        }
        if (edge == "v1") {
          v = 1.0;
          inside_v = 1.0 - step;
        }
        if (edge == "u0") {
          u = 0.0;
          inside_u = step;
        }
        if (edge == "u1") {
          u = 1.0;
          inside_u = 1.0 - step;
        }
        const PatchDerivatives on_pole = patch.derivatives(u, v);
        ASSERT_LT((edge[0] == 'v' ? on_pole.d_du : on_pole.d_dv).norm(), 1e-14);
        const Eigen::Vector3d limit = patch.normal(u, v);
        EXPECT_LT((limit - patch.normal(inside_u, inside_v)).norm(), 1e-5) << edge << " t=" << t;
        // The classical pole normal: along the collapsed edge F_u = F_uu = 0 and the cross
        // product grows like (distance from the pole) * F_uv x F_v (or F_u x F_uv for u-edges).
        const Eigen::Vector3d analytic =
            edge[0] == 'v' ? on_pole.d2_dudv.cross(on_pole.d_dv) : on_pole.d_du.cross(on_pole.d2_dudv);
        const double away = (edge == "v0" || edge == "u0") ? 1.0 : -1.0;
        EXPECT_LT((limit - away * analytic.normalized()).norm(), 1e-9) << edge << " t=" << t;
      }
    }
  }
}

TEST(BezierPatch, CollapsedCornerHasTheLimitNormalAlongTheDiagonal) {
  std::mt19937 random(7);
  for (int trial = 0; trial < 10; ++trial) {
    BezierPatch::ControlPoints points = randomControlPoints(random);
    if (trial % 2 == 0) {
      // Two coincident corner points: F_u(0,0) = 0.
      points[BezierPatch::index(1, 0)] = points[BezierPatch::index(0, 0)];
    } else {
      // Corner tangents parallel: F_u(0,0) x F_v(0,0) = 0 with both non-zero.
      points[BezierPatch::index(0, 1)] = points[BezierPatch::index(0, 0)] +
                                         0.7 * (points[BezierPatch::index(1, 0)] - points[BezierPatch::index(0, 0)]);
    }
    const BezierPatch patch(points);
    expectUnitFiniteNormalsEverywhere(patch);
    const Eigen::Vector3d corner = patch.normal(0.0, 0.0);
    EXPECT_LT((corner - patch.normal(1e-7, 1e-7)).norm(), 1e-5) << "trial " << trial;
  }
}

TEST(BezierPatch, TwoCollapsedEdgesMeetingAtACornerStayFinite) {
  std::mt19937 random(8);
  for (int trial = 0; trial < 10; ++trial) {
    // v = 0 and u = 0 both collapse to P00: a patch bounded by two curves.
    const BezierPatch patch(collapseEdge(collapseEdge(randomControlPoints(random), "v0"), "u0"));
    expectUnitFiniteNormalsEverywhere(patch);
    const Eigen::Vector3d corner = patch.normal(0.0, 0.0);
    // Higher-order degeneracy converges more slowly: compare with a point well inside.
    EXPECT_LT((corner - patch.normal(1e-6, 1e-6)).norm(), 1e-3) << "trial " << trial;
  }
}

TEST(BezierPatch, PatchDegenerateToACurveThrowsInsteadOfReturningNaN) {
  BezierPatch::ControlPoints points;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) points[BezierPatch::index(i, j)] = {double(i + j), 0.0, 0.0};
  }
  const BezierPatch line(points);
  EXPECT_THROW(line.normal(0.3, 0.6), std::domain_error);
}

TEST(BezierPatch, RejectsBadInput) {
  std::mt19937 random(9);
  BezierPatch::ControlPoints points = randomControlPoints(random);
  points[BezierPatch::index(2, 1)].y() = std::numeric_limits<double>::infinity();
  try {
    BezierPatch patch(points);
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("P[2][1]"), std::string::npos) << error.what();
  }
  BezierPatch::ControlPoints point;
  point.fill(Eigen::Vector3d(1, 2, 3));
  EXPECT_THROW(BezierPatch{point}, std::invalid_argument);
  const BezierPatch patch(randomControlPoints(random));
  EXPECT_THROW(patch.position(-0.1, 0.5), std::invalid_argument);
  EXPECT_THROW(patch.normal(0.5, std::nan("")), std::invalid_argument);
}

TEST(BezierPatch, SetControlPointsEqualsConstructionAndLeavesThePatchOnError) {
  std::mt19937 random(11);
  const BezierPatch::ControlPoints first = randomControlPoints(random);
  const BezierPatch::ControlPoints second = randomControlPoints(random);
  BezierPatch patch(first);
  patch.setControlPoints(second);
  const BezierPatch fresh(second);
  EXPECT_EQ(patch.boundingBoxMin(), fresh.boundingBoxMin());
  EXPECT_EQ(patch.boundingBoxMax(), fresh.boundingBoxMax());
  EXPECT_EQ(patch.scale(), fresh.scale());
  for (const double u : {0.0, 0.3, 1.0}) {
    EXPECT_EQ(patch.position(u, 0.7), fresh.position(u, 0.7));
    EXPECT_EQ(patch.normal(u, 0.7), fresh.normal(u, 0.7));
  }
  BezierPatch::ControlPoints bad = first;
  bad[BezierPatch::index(3, 3)].x() = std::nan("");
  EXPECT_THROW(patch.setControlPoints(bad), std::invalid_argument);
  BezierPatch::ControlPoints point;
  point.fill(Eigen::Vector3d(1, 2, 3));
  EXPECT_THROW(patch.setControlPoints(point), std::invalid_argument);
  EXPECT_EQ(patch.controlPoints(), second) << "a rejected update leaves the patch as it was";
  EXPECT_EQ(patch.position(0.4, 0.4), fresh.position(0.4, 0.4));
}

}  // namespace
}  // namespace dressed_human
