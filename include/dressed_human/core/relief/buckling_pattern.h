// Exact piecewise-planar geometry of the I, Y and X buckling patterns (seed paper 000, Fig. 5).
// Conventions and the solution of Eq. 9-10 are in buckling_solution.h.
//
// Cell frame: x in [-L_x, L_x] (across the wrinkle), y along the compression, z up (base normal).
// Rest points: P1(-L_x,-L_y) P2(L_x,-L_y) P3(L_x,L_y) P4(-L_x,L_y), edge midpoints P5(-L_x,0),
// P6(L_x,0), centre P7(0,0). Folded: the corners stay in the base plane z = 0 at y = +-alpha L_y,
// P7 rises to h1; an "I edge" midpoint rises to h1 as well, a "split edge" midpoint moves inward by
// w and sinks to -h2. I = two I edges, Y = one split edge + one I edge, X = two split edges.
// Ridges run P7->corners (Y, X) and P7->I-edge midpoints; valleys run P7->split midpoints.
//
// Footprint height: the folded surface is a height field over the compressed rectangle
// [-L_x, L_x] x [-alpha L_y, alpha L_y] except for a notch at each split edge (triangle P1 P5 P4
// in projection): that material has gone into the bend towards the neighbouring cell. For bump
// mapping the notch is filled with the valley floor (z = -h2 along x = +-L_x, sloping up to the
// corners), which keeps the field continuous and equal on both sides of a split-split joint.
#pragma once

#include "dressed_human/core/relief/buckling_solution.h"
#include "dressed_human/core/relief/relief_sample.h"

#include <Eigen/Core>
#include <array>
#include <vector>

namespace dressed_human {

/// One face of the folded cell: the same material triangle at rest (2D) and folded (3D).
struct FoldFace {
  std::array<Eigen::Vector2d, 3> rest;
  std::array<Eigen::Vector3d, 3> folded;
};

class BucklingPattern {
 public:
  /// A Y pattern has its split edge on the left (x = -L_x) unless split_on_right is set.
  /// Throws std::invalid_argument for a bad alpha/cell, std::domain_error per policy, and
  /// std::invalid_argument when the effective alpha is 0 (the footprint has no area).
  BucklingPattern(PatternKind kind, double alpha, const BucklingCell& cell,
                  OutOfDomainPolicy policy = OutOfDomainPolicy::clampToDomainEdge, bool split_on_right = false);

  const BucklingSolution& solution() const { return solution_; }
  const BucklingCell& cell() const { return cell_; }
  PatternKind kind() const { return solution_.kind; }
  bool splitLeft() const { return split_left_; }
  bool splitRight() const { return split_right_; }
  double footprintHalfLength() const { return solution_.alpha * cell_.half_length_y; }

  /// The six material faces (rest and folded), counter-clockwise at rest.
  const std::vector<FoldFace>& faces() const { return faces_; }
  /// Folded position of a named point: index 1..7 for P1..P7.
  Eigen::Vector3d foldedPoint(int index) const;

  /// Height and slope over the footprint; (x, y) is clamped into the footprint rectangle.
  ReliefSample sampleFootprint(double x, double y) const;
  double heightAt(double x, double y) const { return sampleFootprint(x, y).height; }

 private:
  struct ProjectedFace {
    Eigen::Vector2d origin, edge_u, edge_v;  // projected triangle: origin + a edge_u + b edge_v
    double inverse_determinant = 0.0;
    double slope_x = 0.0, slope_y = 0.0, offset = 0.0;  // plane z = slope_x x + slope_y y + offset
  };
  void addProjectedFace(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

  BucklingCell cell_;
  BucklingSolution solution_;
  bool split_left_ = false;
  bool split_right_ = false;
  std::array<Eigen::Vector3d, 8> folded_points_;
  std::vector<FoldFace> faces_;
  std::vector<ProjectedFace> lower_half_faces_;  // y <= 0; the pattern is symmetric in y
};

}  // namespace dressed_human
