#include "dressed_human/core/relief/buckling_pattern.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dressed_human {

BucklingPattern::BucklingPattern(PatternKind kind, double alpha, const BucklingCell& cell, OutOfDomainPolicy policy,
                                 bool split_on_right)
    : cell_(cell), solution_(solveBuckling(kind, alpha, cell, policy)) {
  if (!(solution_.alpha > 0.0)) {
    std::ostringstream message;
    message << "BucklingPattern: effective alpha = 0 folds the cell onto a line (footprint of zero "
               "area); use alpha > 0 (requested alpha = "
            << alpha << ")";
    throw std::invalid_argument(message.str());
  }
  switch (solution_.kind) {
    case PatternKind::I:
      break;
    case PatternKind::Y:
      split_left_ = !split_on_right;
      split_right_ = split_on_right;
      break;
    case PatternKind::X:
      split_left_ = split_right_ = true;
      break;
  }

  const double lx = cell_.half_width_x;
  const double ly = cell_.half_length_y;
  const double y_edge = solution_.alpha * ly;
  const double h1 = solution_.h1;
  const double w = solution_.w;
  const double h2 = solution_.h2;
  folded_points_[0] = Eigen::Vector3d::Zero();  // unused: points are numbered from 1
  folded_points_[1] = {-lx, -y_edge, 0.0};
  folded_points_[2] = {lx, -y_edge, 0.0};
  folded_points_[3] = {lx, y_edge, 0.0};
  folded_points_[4] = {-lx, y_edge, 0.0};
  folded_points_[5] = split_left_ ? Eigen::Vector3d(-lx + w, 0.0, -h2) : Eigen::Vector3d(-lx, 0.0, h1);
  folded_points_[6] = split_right_ ? Eigen::Vector3d(lx - w, 0.0, -h2) : Eigen::Vector3d(lx, 0.0, h1);
  folded_points_[7] = {0.0, 0.0, h1};

  const std::array<Eigen::Vector2d, 8> rest = {
      Eigen::Vector2d::Zero(),  Eigen::Vector2d(-lx, -ly), Eigen::Vector2d(lx, -ly), Eigen::Vector2d(lx, ly),
      Eigen::Vector2d(-lx, ly), Eigen::Vector2d(-lx, 0.0), Eigen::Vector2d(lx, 0.0), Eigen::Vector2d(0.0, 0.0)};
  // One triangulation serves all three patterns: for an I edge the two side triangles are
  // coplanar with the centre ones, for a split edge they are the tucked-in faces.
  const int triangles[6][3] = {{1, 2, 7}, {7, 3, 4}, {1, 7, 5}, {5, 7, 4}, {2, 6, 7}, {7, 6, 3}};
  for (const auto& triangle : triangles) {
    FoldFace face;
    for (int corner = 0; corner < 3; ++corner) {
      face.rest[corner] = rest[triangle[corner]];
      face.folded[corner] = folded_points_[triangle[corner]];
    }
    faces_.push_back(face);
  }

  // Lower half (y <= 0) of the footprint, split faces first so they win on shared borders.
  const Eigen::Vector3d& p1 = folded_points_[1];
  const Eigen::Vector3d& p2 = folded_points_[2];
  const Eigen::Vector3d& p5 = folded_points_[5];
  const Eigen::Vector3d& p6 = folded_points_[6];
  const Eigen::Vector3d& p7 = folded_points_[7];
  if (split_left_) {
    addProjectedFace(p1, p7, p5);
    addProjectedFace(p1, p5, Eigen::Vector3d(-lx, 0.0, -h2));  // notch fill
  }
  if (split_right_) {
    addProjectedFace(p2, p6, p7);
    addProjectedFace(p2, Eigen::Vector3d(lx, 0.0, -h2), p6);  // notch fill
  }
  // The I plane through P1, P2 and P7 covers everything else (the big ridge face).
  addProjectedFace(p1, p2, p7);
  addProjectedFace(p1, p7, Eigen::Vector3d(-lx, 0.0, h1));
  addProjectedFace(p2, Eigen::Vector3d(lx, 0.0, h1), p7);
}

void BucklingPattern::addProjectedFace(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  ProjectedFace face;
  face.origin = a.head<2>();
  face.edge_u = (b - a).head<2>();
  face.edge_v = (c - a).head<2>();
  const double determinant = face.edge_u.x() * face.edge_v.y() - face.edge_u.y() * face.edge_v.x();
  const double scale = face.edge_u.norm() * face.edge_v.norm();
  if (std::abs(determinant) <= 1e-12 * scale) return;  // vertical face (at the domain edge)
  face.inverse_determinant = 1.0 / determinant;
  const double dz_b = b.z() - a.z();
  const double dz_c = c.z() - a.z();
  // Plane gradient g from g . edge_u = dz_b and g . edge_v = dz_c (Cramer's rule).
  face.slope_x = (dz_b * face.edge_v.y() - dz_c * face.edge_u.y()) * face.inverse_determinant;
  face.slope_y = (dz_c * face.edge_u.x() - dz_b * face.edge_v.x()) * face.inverse_determinant;
  face.offset = a.z() - face.slope_x * a.x() - face.slope_y * a.y();
  lower_half_faces_.push_back(face);
}

Eigen::Vector3d BucklingPattern::foldedPoint(int index) const {
  if (index < 1 || index > 7) {
    std::ostringstream message;
    message << "BucklingPattern::foldedPoint: index must be 1..7 (P1..P7), got " << index;
    throw std::out_of_range(message.str());
  }
  return folded_points_[static_cast<std::size_t>(index)];
}

ReliefSample BucklingPattern::sampleFootprint(double x, double y) const {
  const double lx = cell_.half_width_x;
  const double y_edge = footprintHalfLength();
  x = std::clamp(x, -lx, lx);
  y = std::clamp(y, -y_edge, y_edge);
  const bool upper = y > 0.0;
  const Eigen::Vector2d point(x, upper ? -y : y);
  constexpr double tolerance = 1e-12;
  const ProjectedFace* found = &lower_half_faces_.back();
  for (const ProjectedFace& face : lower_half_faces_) {
    const Eigen::Vector2d d = point - face.origin;
    const double a = (d.x() * face.edge_v.y() - d.y() * face.edge_v.x()) * face.inverse_determinant;
    const double b = (face.edge_u.x() * d.y() - face.edge_u.y() * d.x()) * face.inverse_determinant;
    if (a >= -tolerance && b >= -tolerance && a + b <= 1.0 + tolerance) {
      found = &face;
      break;
    }
  }
  ReliefSample sample;
  sample.height = found->slope_x * point.x() + found->slope_y * point.y() + found->offset;
  sample.slope = {found->slope_x, upper ? -found->slope_y : found->slope_y};
  return sample;
}

}  // namespace dressed_human
