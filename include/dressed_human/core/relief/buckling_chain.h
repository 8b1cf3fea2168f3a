// Chains of buckling cells along x (seed paper 000 §4.1: Y-Y, Y-X, X-X).
//
// Cells join edge to edge. Two I edges join flat (same base plane, shifted by 2 L_x). Two split
// edges join by a hinge about the corner line P2P3 / P1P4: the neighbour's base plane turns by
// 2 atan(w/h2) so that both split midpoints meet. The turn is towards -z (the ridges end up on the
// outside), so a chain of Y/X cells curls into a cylinder with the wrinkles bulging outwards --
// the seed's argument for Y/X on sleeves and bodices. A split edge cannot meet an I edge (that
// would take a fold of pi - atan(w/h2), not a bend); such chains are rejected.
#pragma once

#include "dressed_human/core/relief/buckling_pattern.h"

#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace dressed_human {

/// Pattern and edge types of one cell in a chain.
struct ChainCell {
  PatternKind kind = PatternKind::I;
  bool split_left = false;
  bool split_right = false;
};

/// Orient the cells of a chain written as a string of 'I', 'Y', 'X' (e.g. "YY", "YXY", "XXXX"):
/// each Y turns its split edge towards the split edge it has to meet. With `periodic`, the last
/// cell also joins the first. Throws std::invalid_argument naming the offending joint.
std::vector<ChainCell> orientChain(const std::string& kinds, bool periodic);

struct BucklingChain {
  std::vector<BucklingPattern> cells;
  std::vector<Eigen::Isometry3d> cell_to_world;  ///< cell frame -> chain frame (cell 0 = identity)
  std::vector<double> joint_bend_angles;         ///< between cell i and i+1 (0 for I-I joints)
};

/// Build the 3D chain for one alpha (open chain, cells laid out along +x from cell 0).
BucklingChain buildBucklingChain(const std::string& kinds, double alpha, const BucklingCell& cell,
                                 OutOfDomainPolicy policy = OutOfDomainPolicy::clampToDomainEdge);

}  // namespace dressed_human
