// Buckling of a compressed rectangle (SPEC §4, seed paper 000 §4.1, Eq. 9-11).
//
// Cell: a 2L_x x 2L_y rectangle P1P2P3P4 (x across the wrinkles, y along the compression).
//
// alpha convention (chosen here, used everywhere in dressed_human):
//   alpha = 1  -> uncompressed (flat), the y side keeps its rest length 2 L_y;
//   alpha -> 0 -> fully compressed, the y side is 2 alpha L_y long.
// This follows "compressed to 2 alpha L_y" in the paper's text; the caption near Fig. 6
// that calls alpha = 0 the flat state contradicts that formula and is not followed.
//
// Eq. 9 (I pattern, fold line P5P6 at the middle rises by h1):  h1 = sqrt(1 - alpha^2) L_y.
//
// Eq. 10 (Y/X patterns: P7 rises by h1, the split point P5 moves by w in x and sinks by h2 in z):
//   w^2 - h1^2 + h2^2 = 0                    (|P1P5| keeps its rest length L_y)
//   (w - L_x)^2 + (h1 + h2)^2 - L_x^2 = 0    (|P5P7| keeps its rest length L_x)
// Subtracting the first from the second gives L_x w = h1 (h1 + h2); substituting back:
//   h1 + h2 = 2 h1 L_x^2 / (L_x^2 + h1^2),
//   h2      = h1 (L_x^2 - h1^2) / (L_x^2 + h1^2),
//   w       = 2 h1^2 L_x / (L_x^2 + h1^2)      ( = L_x - sqrt(L_x^2 - (h1 + h2)^2) for h1 <= L_x ).
// With tan(phi/2) = h1 / L_x this is (w, h2) = h1 (sin phi, cos phi): the valley P5P7 swings
// about P7 by phi, and the bend between chained base planes is 2 atan(w/h2) = 2 phi.
// (The printed Eq. 11 has L_x instead of L_x^2 in h2 and loses the minus sign inside the
// square root of w; it does not satisfy Eq. 10.)
//
// Domain: the Y/X solution is physical only while h2 >= 0, i.e. h1 <= L_x, i.e.
//   alpha >= alpha_min = sqrt(max(0, 1 - (L_x / L_y)^2)).
// At the edge (h1 = L_x) P5 lies straight under P7 (w = L_x, h2 = 0), the split faces are
// vertical and the bend is 180 degrees; beyond it P5 would pass P7 and the faces interpenetrate
// (the algebraic solution continues, but on the other root of Eq. 10's second equation).
// For L_x >= L_y every alpha in [0, 1] is valid.
#pragma once

#include <Eigen/Core>

namespace dressed_human {

/// Rest half sizes of one buckling cell: the cell is 2 L_x wide (x) and 2 L_y long (y, compressed).
struct BucklingCell {
  double half_width_x = 1.0;   ///< L_x > 0
  double half_length_y = 1.0;  ///< L_y > 0
};

enum class PatternKind { I, Y, X };

/// What to do when alpha is below alpha_min for a Y or X pattern.
enum class OutOfDomainPolicy {
  /// Default. Use alpha_min: the pattern saturates at the fully tucked state and stops growing.
  /// Chosen because it is continuous in alpha (an animated knee bend never pops between
  /// pattern types) and keeps the Y/X curl that makes them the stable patterns on cylinders;
  /// the rest of the compression has to go into more wrinkle cells, which is the caller's call.
  clampToDomainEdge,
  /// Use the I pattern at the requested alpha (exists for every alpha in [0, 1]); continuous in
  /// height at the fold line but the split valleys vanish abruptly.
  fallBackToIPattern,
  /// Throw std::domain_error naming alpha and alpha_min.
  throwError,
};

struct BucklingSolution {
  PatternKind kind = PatternKind::I;  ///< pattern actually built (may be I after fall back)
  double alpha_requested = 1.0;
  double alpha = 1.0;    ///< effective alpha of the geometry (differs when clamped)
  double h1 = 0.0;       ///< rise of the fold/ridge point (P5P6 for I, P7 for Y/X)
  double w = 0.0;        ///< inward x move of the split point (0 for I)
  double h2 = 0.0;       ///< sink of the split point below the base plane (0 for I)
  bool clamped = false;  ///< alpha was raised to alpha_min
  bool fell_back_to_i = false;

  /// Angle between the base planes of two Y/X cells joined at their split edges, 2 atan(w/h2)
  /// (computed as 4 atan(h1/L_x), which stays defined at the edge h2 = 0). 0 for I.
  double bend_angle = 0.0;
};

/// Eq. 9. Throws std::invalid_argument for alpha outside [0, 1] or L_y <= 0.
double foldHeightIPattern(double alpha, double half_length_y);

/// Smallest alpha at which the Y/X solution exists for this cell.
double minimumAlphaForSplitPatterns(const BucklingCell& cell);

struct SplitDisplacement {
  double w = 0.0;
  double h2 = 0.0;
};

/// Closed-form solution of Eq. 10 for 0 <= h1 <= L_x. Throws std::domain_error when h1 > L_x.
SplitDisplacement solveSplitDisplacement(double h1, double half_width_x);

/// Left-hand sides of the two equations of Eq. 10 (zero for an exact solution).
Eigen::Vector2d equation10Residual(double w, double h1, double h2, double half_width_x);

/// Solve the pattern for a requested alpha under the chosen out-of-domain policy.
/// Throws std::invalid_argument for alpha outside [0, 1] or a non-positive cell size.
BucklingSolution solveBuckling(PatternKind kind, double alpha, const BucklingCell& cell,
                               OutOfDomainPolicy policy = OutOfDomainPolicy::clampToDomainEdge);

const char* patternName(PatternKind kind);

}  // namespace dressed_human
