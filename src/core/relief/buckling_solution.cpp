#include "dressed_human/core/relief/buckling_solution.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dressed_human {
namespace {

void requireValidCell(const BucklingCell& cell) {
  if (!(cell.half_width_x > 0.0) || !std::isfinite(cell.half_width_x)) {
    std::ostringstream message;
    message << "BucklingCell.half_width_x (L_x) must be finite and > 0, got " << cell.half_width_x;
    throw std::invalid_argument(message.str());
  }
  if (!(cell.half_length_y > 0.0) || !std::isfinite(cell.half_length_y)) {
    std::ostringstream message;
    message << "BucklingCell.half_length_y (L_y) must be finite and > 0, got " << cell.half_length_y;
    throw std::invalid_argument(message.str());
  }
}

void requireValidAlpha(double alpha) {
  if (!(alpha >= 0.0 && alpha <= 1.0)) {
    std::ostringstream message;
    message << "compression coefficient alpha must be in [0, 1] (1 = uncompressed), got " << alpha;
    throw std::invalid_argument(message.str());
  }
}

}  // namespace

double foldHeightIPattern(double alpha, double half_length_y) {
  requireValidAlpha(alpha);
  if (!(half_length_y > 0.0)) {
    std::ostringstream message;
    message << "half_length_y (L_y) must be > 0, got " << half_length_y;
    throw std::invalid_argument(message.str());
  }
  // (1 - a)(1 + a) instead of 1 - a^2 keeps relative accuracy near alpha = 1.
  return std::sqrt((1.0 - alpha) * (1.0 + alpha)) * half_length_y;
}

double minimumAlphaForSplitPatterns(const BucklingCell& cell) {
  requireValidCell(cell);
  const double ratio = cell.half_width_x / cell.half_length_y;
  if (ratio >= 1.0) return 0.0;
  return std::sqrt((1.0 - ratio) * (1.0 + ratio));
}

SplitDisplacement solveSplitDisplacement(double h1, double half_width_x) {
  if (!(half_width_x > 0.0)) {
    std::ostringstream message;
    message << "half_width_x (L_x) must be > 0, got " << half_width_x;
    throw std::invalid_argument(message.str());
  }
  if (!(h1 >= 0.0)) {
    std::ostringstream message;
    message << "fold height h1 must be >= 0, got " << h1;
    throw std::invalid_argument(message.str());
  }
  if (h1 > half_width_x) {
    std::ostringstream message;
    message << "Y/X buckling has no physical solution for h1 = " << h1 << " > L_x = " << half_width_x
            << " (the split point would pass under the ridge point; see buckling_solution.h)";
    throw std::domain_error(message.str());
  }
  const double lx2 = half_width_x * half_width_x;
  const double h1_squared = h1 * h1;
  const double denominator = lx2 + h1_squared;
  SplitDisplacement result;
  result.w = 2.0 * h1_squared * half_width_x / denominator;
  result.h2 = h1 * (half_width_x - h1) * (half_width_x + h1) / denominator;
  return result;
}

Eigen::Vector2d equation10Residual(double w, double h1, double h2, double half_width_x) {
  const double lx = half_width_x;
  return Eigen::Vector2d(w * w - h1 * h1 + h2 * h2, (w - lx) * (w - lx) + (h1 + h2) * (h1 + h2) - lx * lx);
}

BucklingSolution solveBuckling(PatternKind kind, double alpha, const BucklingCell& cell, OutOfDomainPolicy policy) {
  requireValidCell(cell);
  requireValidAlpha(alpha);
  BucklingSolution solution;
  solution.kind = kind;
  solution.alpha_requested = alpha;
  solution.alpha = alpha;
  if (kind != PatternKind::I) {
    const double alpha_min = minimumAlphaForSplitPatterns(cell);
    if (alpha < alpha_min) {
      switch (policy) {
        case OutOfDomainPolicy::clampToDomainEdge:
          solution.alpha = alpha_min;
          solution.clamped = true;
          break;
        case OutOfDomainPolicy::fallBackToIPattern:
          solution.kind = PatternKind::I;
          solution.fell_back_to_i = true;
          break;
        case OutOfDomainPolicy::throwError: {
          std::ostringstream message;
          message << "alpha = " << alpha << " is below alpha_min = " << alpha_min << " where the " << patternName(kind)
                  << " pattern exists for L_x = " << cell.half_width_x << ", L_y = " << cell.half_length_y;
          throw std::domain_error(message.str());
        }
      }
    }
  }
  solution.h1 = foldHeightIPattern(solution.alpha, cell.half_length_y);
  if (solution.kind != PatternKind::I) {
    // Clamping can leave h1 an ulp above L_x; the edge value is the intended one.
    const double h1 = std::min(solution.h1, cell.half_width_x);
    solution.h1 = h1;
    const SplitDisplacement split = solveSplitDisplacement(h1, cell.half_width_x);
    solution.w = split.w;
    solution.h2 = split.h2;
    solution.bend_angle = 4.0 * std::atan(h1 / cell.half_width_x);
  }
  return solution;
}

const char* patternName(PatternKind kind) {
  switch (kind) {
    case PatternKind::I:
      return "I";
    case PatternKind::Y:
      return "Y";
    case PatternKind::X:
      return "X";
  }
  return "?";
}

}  // namespace dressed_human
