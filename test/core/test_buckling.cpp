#include "dressed_human/core/relief/buckling_chain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace dressed_human {
namespace {

const BucklingCell kCells[] = {{1.0, 1.0}, {1.0, 2.0}, {2.0, 1.0}, {0.3, 0.5}, {0.5, 1.0}};

TEST(BucklingSolution, IPatternFollowsEquation9) {
  for (const BucklingCell& cell : kCells) {
    for (double alpha = 0.0; alpha <= 1.0; alpha += 0.05) {
      const BucklingSolution solution = solveBuckling(PatternKind::I, alpha, cell);
      EXPECT_NEAR(solution.h1, std::sqrt(1.0 - alpha * alpha) * cell.half_length_y, 1e-14);
      // |P1P5| keeps its rest length L_y: (alpha L_y)^2 + h1^2 = L_y^2.
      EXPECT_NEAR(std::hypot(alpha * cell.half_length_y, solution.h1), cell.half_length_y, 1e-14);
    }
  }
  EXPECT_DOUBLE_EQ(foldHeightIPattern(1.0, 3.0), 0.0);
  EXPECT_DOUBLE_EQ(foldHeightIPattern(0.0, 3.0), 3.0);
}

TEST(BucklingSolution, Equation10ResidualAtMachinePrecisionOverValidDomain) {
  for (const BucklingCell& cell : kCells) {
    const double alpha_min = minimumAlphaForSplitPatterns(cell);
    for (int step = 0; step <= 2000; ++step) {
      const double alpha = alpha_min + (1.0 - alpha_min) * step / 2000.0;
      for (PatternKind kind : {PatternKind::Y, PatternKind::X}) {
        const BucklingSolution solution = solveBuckling(kind, alpha, cell, OutOfDomainPolicy::throwError);
        const Eigen::Vector2d residual = equation10Residual(solution.w, solution.h1, solution.h2, cell.half_width_x);
        ASSERT_LE(residual.cwiseAbs().maxCoeff(), 1e-12) << "alpha " << alpha << " L_x " << cell.half_width_x;
        EXPECT_GE(solution.h2, 0.0);
        EXPECT_GE(solution.w, 0.0);
        EXPECT_LE(solution.w, cell.half_width_x * (1.0 + 1e-15));
        EXPECT_FALSE(solution.clamped);
        // The bend of the paper, 2 atan(w / h2), equals the closed form 4 atan(h1 / L_x).
        if (solution.h2 > 1e-9) {
          EXPECT_NEAR(solution.bend_angle, 2.0 * std::atan(solution.w / solution.h2), 1e-9);
        }
      }
    }
  }
}

TEST(BucklingSolution, PrintedEquation11DoesNotSolveEquation10) {
  const double lx = 1.0, h1 = 0.6;
  const double h2 = -(h1 * h1 * h1 - lx * h1) / (lx * lx + h1 * h1);
  const double w = lx - std::sqrt(lx * (h1 + h2) * (h1 + h2));
  EXPECT_GT(equation10Residual(w, h1, h2, lx).cwiseAbs().maxCoeff(), 1e-2);
}

TEST(BucklingSolution, DomainEdgeWhereH1ReachesLx) {
  const BucklingCell cell{0.5, 1.0};
  const double alpha_min = minimumAlphaForSplitPatterns(cell);
  EXPECT_NEAR(alpha_min, std::sqrt(0.75), 1e-15);
  const BucklingSolution edge = solveBuckling(PatternKind::Y, alpha_min, cell, OutOfDomainPolicy::throwError);
  EXPECT_NEAR(edge.h1, cell.half_width_x, 1e-12);
  EXPECT_NEAR(edge.h2, 0.0, 1e-12);
  EXPECT_NEAR(edge.w, cell.half_width_x, 1e-12);
  EXPECT_NEAR(edge.bend_angle, M_PI, 1e-9);

  const double beyond = alpha_min - 0.1;
  const BucklingSolution clamped = solveBuckling(PatternKind::X, beyond, cell, OutOfDomainPolicy::clampToDomainEdge);
  EXPECT_TRUE(clamped.clamped);
  EXPECT_DOUBLE_EQ(clamped.alpha, alpha_min);
  EXPECT_DOUBLE_EQ(clamped.alpha_requested, beyond);
  EXPECT_NEAR(clamped.h2, 0.0, 1e-12);
  const BucklingSolution fallen = solveBuckling(PatternKind::Y, beyond, cell, OutOfDomainPolicy::fallBackToIPattern);
  EXPECT_EQ(fallen.kind, PatternKind::I);
  EXPECT_TRUE(fallen.fell_back_to_i);
  EXPECT_NEAR(fallen.h1, std::sqrt(1.0 - beyond * beyond), 1e-14);
  EXPECT_THROW(solveBuckling(PatternKind::Y, beyond, cell, OutOfDomainPolicy::throwError), std::domain_error);
  EXPECT_THROW(solveSplitDisplacement(0.51, 0.5), std::domain_error);
  // Square cells: the whole range is valid, alpha = 0 sits exactly on the edge.
  EXPECT_DOUBLE_EQ(minimumAlphaForSplitPatterns({1.0, 1.0}), 0.0);
}

TEST(BucklingSolution, RejectsBadInput) {
  EXPECT_THROW(solveBuckling(PatternKind::I, 1.5, {1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(solveBuckling(PatternKind::I, -0.1, {1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(solveBuckling(PatternKind::X, 0.5, {0.0, 1.0}), std::invalid_argument);
  try {
    solveBuckling(PatternKind::X, 0.5, {1.0, -2.0});
    FAIL();
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("half_length_y"), std::string::npos);
  }
  EXPECT_THROW(BucklingPattern(PatternKind::I, 0.0, {1.0, 1.0}), std::invalid_argument);
}

TEST(BucklingPattern, FacesAreIsometricToTheRestRectangle) {
  for (const BucklingCell& cell : kCells) {
    for (PatternKind kind : {PatternKind::I, PatternKind::Y, PatternKind::X}) {
      for (double alpha : {0.95, 0.9, 0.8, 0.7, 0.6, 0.5, 0.3}) {
        const BucklingPattern pattern(kind, alpha, cell);
        double rest_area = 0.0;
        for (const FoldFace& face : pattern.faces()) {
          for (int a = 0; a < 3; ++a) {
            const int b = (a + 1) % 3;
            EXPECT_NEAR((face.rest[a] - face.rest[b]).norm(), (face.folded[a] - face.folded[b]).norm(), 1e-12);
          }
          const Eigen::Vector2d u = face.rest[1] - face.rest[0], v = face.rest[2] - face.rest[0];
          rest_area += 0.5 * (u.x() * v.y() - u.y() * v.x());
        }
        EXPECT_NEAR(rest_area, 4.0 * cell.half_width_x * cell.half_length_y, 1e-12);
      }
    }
  }
}

TEST(BucklingPattern, FootprintHeightAtNamedPointsAndContinuity) {
  const BucklingCell cell{1.0, 1.0};
  for (PatternKind kind : {PatternKind::I, PatternKind::Y, PatternKind::X}) {
    const BucklingPattern pattern(kind, 0.7, cell);
    const BucklingSolution& solution = pattern.solution();
    const double y_edge = pattern.footprintHalfLength();
    EXPECT_NEAR(pattern.heightAt(0.0, 0.0), solution.h1, 1e-12);
    for (double x = -1.0; x <= 1.0; x += 0.125) {
      EXPECT_NEAR(pattern.heightAt(x, y_edge), 0.0, 1e-12);
      EXPECT_NEAR(pattern.heightAt(x, -y_edge), 0.0, 1e-12);
    }
    if (pattern.splitLeft()) {
      EXPECT_NEAR(pattern.heightAt(-1.0 + solution.w, 0.0), -solution.h2, 1e-12);
    }
    if (pattern.splitRight()) {
      EXPECT_NEAR(pattern.heightAt(1.0 - solution.w, 0.0), -solution.h2, 1e-12);
    }
    // Continuous: no jump larger than the steepest face allows between close samples.
    double steepest = 0.0, largest_jump = 0.0;
    const double step = 1e-4;
    for (double y = -y_edge; y <= y_edge; y += y_edge / 37.0) {
      for (double x = -1.0; x + step <= 1.0; x += step) {
        const ReliefSample here = pattern.sampleFootprint(x, y);
        steepest = std::max(steepest, here.slope.norm());
        largest_jump = std::max(largest_jump, std::abs(pattern.heightAt(x + step, y) - here.height));
      }
    }
    EXPECT_LE(largest_jump, steepest * step * 1.0001) << patternName(kind);
    // Slopes are the planes' gradients: match central differences inside a face.
    const ReliefSample inside = pattern.sampleFootprint(0.5, -0.4 * y_edge);
    EXPECT_NEAR(inside.slope.x(),
                (pattern.heightAt(0.5 + 1e-6, -0.4 * y_edge) - pattern.heightAt(0.5 - 1e-6, -0.4 * y_edge)) / 2e-6,
                1e-6);
    EXPECT_NEAR(inside.slope.y(),
                (pattern.heightAt(0.5, -0.4 * y_edge + 1e-6) - pattern.heightAt(0.5, -0.4 * y_edge - 1e-6)) / 2e-6,
                1e-6);
  }
}

TEST(BucklingChain, JointsBendBy2AtanWOverH2AndSharePoints) {
  const BucklingCell cell{1.5, 1.0};
  for (const char* kinds : {"YY", "YX", "XX", "YXY", "XXXX", "YYYY", "II"}) {
    for (double alpha : {0.9, 0.75, 0.6}) {
      const BucklingChain chain = buildBucklingChain(kinds, alpha, cell);
      ASSERT_EQ(chain.cells.size(), std::string(kinds).size());
      for (std::size_t joint = 0; joint + 1 < chain.cells.size(); ++joint) {
        const BucklingPattern& left = chain.cells[joint];
        const BucklingPattern& right = chain.cells[joint + 1];
        ASSERT_EQ(left.splitRight(), right.splitLeft());
        const Eigen::Isometry3d& left_pose = chain.cell_to_world[joint];
        const Eigen::Isometry3d& right_pose = chain.cell_to_world[joint + 1];
        // Shared edge: P2 = P1', P6 = P5', P3 = P4'.
        for (const auto& [a, b] : {std::pair<int, int>{2, 1}, {6, 5}, {3, 4}}) {
          EXPECT_LT((left_pose * left.foldedPoint(a) - right_pose * right.foldedPoint(b)).norm(), 1e-12)
              << kinds << " joint " << joint << " P" << a;
        }
        const double measured = std::acos(std::clamp(
            (left_pose.linear() * Eigen::Vector3d::UnitZ()).dot(right_pose.linear() * Eigen::Vector3d::UnitZ()), -1.0,
            1.0));
        const BucklingSolution& solution = left.solution();
        const double expected = left.splitRight() ? 2.0 * std::atan(solution.w / solution.h2) : 0.0;
        EXPECT_NEAR(measured, expected, 1e-9) << kinds << " joint " << joint;
        EXPECT_NEAR(chain.joint_bend_angles[joint], expected, 1e-9);
      }
    }
  }
}

TEST(BucklingChain, SplitJointsCurlTheChainWithRidgesOutside) {
  const BucklingCell cell{3.0, 1.0};
  const BucklingChain chain = buildBucklingChain("XXX", 0.8, cell);
  // Each base normal turns about +y by the bend; the chain bends away from the ridges (-z).
  const Eigen::Vector3d last_direction = chain.cell_to_world.back().linear() * Eigen::Vector3d::UnitX();
  const double total = 2.0 * chain.cells[0].solution().bend_angle;
  EXPECT_NEAR(last_direction.x(), std::cos(total), 1e-12);
  EXPECT_NEAR(last_direction.z(), -std::sin(total), 1e-12);
}

TEST(BucklingChain, OrientationRulesAndErrors) {
  const std::vector<ChainCell> yy = orientChain("YY", true);
  EXPECT_TRUE(yy[0].split_right);
  EXPECT_TRUE(yy[1].split_left);
  EXPECT_NO_THROW(orientChain("YXY", true));
  EXPECT_NO_THROW(orientChain("X", true));
  EXPECT_THROW(orientChain("XI", false), std::invalid_argument);
  EXPECT_THROW(orientChain("YX", true), std::invalid_argument);
  EXPECT_THROW(orientChain("Q", false), std::invalid_argument);
  EXPECT_THROW(orientChain("", false), std::invalid_argument);
}

}  // namespace
}  // namespace dressed_human
