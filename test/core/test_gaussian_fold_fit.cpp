#include "dressed_human/core/relief/gaussian_fold_fit.h"

#include <gtest/gtest.h>

namespace dressed_human {
namespace {

TEST(GaussianFoldFit, ErrorAgainstExactFoldDecreasesWithTermCount) {
  const BucklingCell cell{1.0, 1.0};
  for (PatternKind kind : {PatternKind::I, PatternKind::Y, PatternKind::X}) {
    const BucklingPattern pattern(kind, 0.7, cell);
    double previous = 1e300, first = 0.0;
    for (int terms : {1, 2, 4, 8, 16}) {
      const double error = rmsApproximationError(pattern, fitGaussians(pattern, terms));
      if (terms == 1) first = error;
      EXPECT_LT(error, previous) << patternName(kind) << " K=" << terms;
      previous = error;
    }
    EXPECT_LT(previous, 0.6 * first) << patternName(kind);
    EXPECT_LT(previous, 0.15 * pattern.solution().h1) << patternName(kind);
  }
}

TEST(GaussianFoldFit, FlatPatternNeedsNoTerms) {
  const BucklingPattern flat(PatternKind::X, 1.0, {1.0, 1.0});
  const GaussianFoldApproximation fit = fitGaussians(flat, 5);
  EXPECT_TRUE(fit.terms().empty());
  EXPECT_DOUBLE_EQ(rmsApproximationError(flat, fit), 0.0);
}

TEST(GaussianFoldFit, SlopeIsTheDerivativeOfTheHeight) {
  const BucklingPattern pattern(PatternKind::Y, 0.7, {1.0, 1.0});
  const GaussianFoldApproximation fit = fitGaussians(pattern, 6);
  for (const Eigen::Vector2d& point :
       {Eigen::Vector2d(0.1, 0.2), Eigen::Vector2d(-0.6, -0.3), Eigen::Vector2d(0.9, 0.5)}) {
    const double h = 1e-6;
    const ReliefSample sample = fit.sample(point.x(), point.y());
    EXPECT_NEAR(sample.slope.x(),
                (fit.sample(point.x() + h, point.y()).height - fit.sample(point.x() - h, point.y()).height) / (2 * h),
                1e-5);
    EXPECT_NEAR(sample.slope.y(),
                (fit.sample(point.x(), point.y() + h).height - fit.sample(point.x(), point.y() - h).height) / (2 * h),
                1e-5);
  }
}

TEST(GaussianFoldFit, RejectsBadCounts) {
  const BucklingPattern pattern(PatternKind::I, 0.7, {1.0, 1.0});
  EXPECT_THROW(fitGaussians(pattern, 0), std::invalid_argument);
  GaussianFitOptions options;
  options.samples_per_axis = 2;
  EXPECT_THROW(fitGaussians(pattern, 3, options), std::invalid_argument);
}

}  // namespace
}  // namespace dressed_human
