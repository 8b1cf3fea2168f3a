// Skirt length across two bones (seed paper 000 Eq. 6-8, SPEC §3), made continuous.
//
// A hem control point of a skirt (or trouser leg) of normalized length c in [0, 1] rides on two
// bone frames: the upper frame i (thigh, length d_i) and the lower frame j (shank, length d_j),
// j a child of i. Knee length is c_k = d_i / (d_i + d_j).
//
//   P(c) = (1 - A_i) P^0 + A_i P^i + A_j M P^j                                   (Eq. 8')
//
//   P^0  point in frame i (w = 1): where the hem sits for c = 0 (the hip line). P^0 = 0, the
//        thigh's origin, gives back the seed's A_i P^i term literally.
//   P^i  point in frame i (w = 1): the knee-length hem (c = c_k).
//   P^j  vector in frame j (w = 0): from the knee-length hem down to the long hem (c = 1),
//        i.e. P^j = Q^j - M_rest^-1 P^i with Q^j the long hem point in frame j at rest.
//        Being a vector, M P^j = R_ij P^j: it turns with the knee, so the long skirt follows
//        the bending knee, pivoting on the knee-length hem line.
//   M    frame j -> frame i (rotation R_ij, translation t_ij) in the current pose.
//
//   A_i = min(c / c_k, 1)                       (as printed: (d_i + d_j) c / d_i below c_k)
//   A_j = max(0, (c - c_k) / (1 - c_k)) = max(0, ((d_i + d_j) c - d_i) / d_j)
//
// The printed A_j = (c d_i + (c - 1) d_j) / d_j = ((d_i + d_j) c - d_j) / d_j swaps d_i and d_j
// in the subtracted term: it is (d_i - d_j) / d_j at c = c_k, not 0, so Eq. 8 as printed jumps
// at knee length unless d_i = d_j. The corrected A_j is 0 at c_k and 1 at c = 1, and both
// weights are continuous, piecewise linear and non-decreasing in c. With the homogeneous
// w = 1 of P^0, P^i and w = 0 of P^j the result always has w = (1 - A_i) + A_i = 1: a point.
#pragma once

namespace dressed_human {

struct SkirtLengthWeights {
  double a0;  // weight of P^0: 1 - A_i
  double ai;  // A_i
  double aj;  // A_j
};

// c_k = d_i / (d_i + d_j). Throws std::invalid_argument unless d_i > 0 and d_j > 0 (finite).
double kneeLength(double upper_length, double lower_length);

// The weights at normalized length c in [0, 1] (throws std::invalid_argument outside, or for
// bad lengths).
SkirtLengthWeights skirtLengthWeights(double c, double upper_length, double lower_length);

// The seed's printed A_j (kept to show its jump in tests and docs), for c >= c_k; 0 below.
double printedLowerWeight(double c, double upper_length, double lower_length);

}  // namespace dressed_human
