#include "dressed_human/core/surfaces/skin_clearance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace dressed_human {

SkinClearance::SkinClearance(const Skeleton& skeleton, const BodyDescription& body, const BodyShape& shape) {
  ForwardKinematics fk(skeleton, shape);
  for (const SkinSegmentSpec& spec : body.segments) {
    Profile p;
    p.name = spec.bone;
    p.bone = spec.bone_index;
    const Eigen::Vector3d s = p.bone < 0 ? Eigen::Vector3d::Ones() : shape.scale[static_cast<std::size_t>(p.bone)];
    for (const SkinSection& section : spec.sections) {
      p.sections.emplace_back(section.z * s.z(), section.radius_x * s.x(), section.radius_y * s.y());
    }
    p.proximal_cap = spec.proximal_cap;
    p.distal_cap = spec.distal_cap;
    segments_.push_back(p);
  }
  // A joined child's first section closes its parent's profile at the child's joint.
  for (std::size_t c = 0; c < body.segments.size(); ++c) {
    const SkinSegmentSpec& child = body.segments[c];
    if (!child.joined_to_parent || child.bone_index < 0) continue;
    const int parent_bone = skeleton.bone(static_cast<std::size_t>(child.bone_index)).parent;
    for (Profile& parent : segments_) {
      if (parent.bone != parent_bone) continue;
      const double z = fk.scaledRestTranslation(static_cast<std::size_t>(child.bone_index)).z();
      const Eigen::Vector3d& first = segments_[c].sections.front();
      parent.sections.emplace_back(z, first.y(), first.z());
    }
  }
}

std::vector<std::size_t> SkinClearance::segmentsNamed(const std::vector<std::string>& names) const {
  std::vector<std::size_t> out;
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    if (std::find(names.begin(), names.end(), segments_[s].name) != names.end()) out.push_back(s);
  }
  return out;
}

double SkinClearance::clearance(const SkeletonPose& pose, std::size_t s, const Eigen::Vector3d& p) const {
  const Profile& profile = segments_.at(s);
  const RigidTransform& frame =
      profile.bone < 0 ? pose.root : pose.bone_in_world[static_cast<std::size_t>(profile.bone)];
  const Eigen::Vector3d q = frame.rotation.conjugate() * (p - frame.translation);
  const std::vector<Eigen::Vector3d>& sec = profile.sections;
  double rx = 0.0, ry = 0.0, scale = 1.0;
  const double z0 = sec.front().x();
  const double z1 = sec.back().x();
  if (q.z() < z0) {
    if (profile.proximal_cap <= 0.0 || q.z() < z0 - profile.proximal_cap)
      return std::numeric_limits<double>::infinity();
    const double t = (z0 - q.z()) / profile.proximal_cap;
    scale = std::sqrt(std::max(0.0, 1.0 - t * t));
    rx = sec.front().y();
    ry = sec.front().z();
  } else if (q.z() > z1) {
    if (profile.distal_cap <= 0.0 || q.z() > z1 + profile.distal_cap) return std::numeric_limits<double>::infinity();
    const double t = (q.z() - z1) / profile.distal_cap;
    scale = std::sqrt(std::max(0.0, 1.0 - t * t));
    rx = sec.back().y();
    ry = sec.back().z();
  } else {
    std::size_t k = 0;
    while (k + 2 < sec.size() && q.z() > sec[k + 1].x()) ++k;
    const double span = sec[k + 1].x() - sec[k].x();
    const double t = span > 0.0 ? (q.z() - sec[k].x()) / span : 0.0;
    rx = (1 - t) * sec[k].y() + t * sec[k + 1].y();
    ry = (1 - t) * sec[k].z() + t * sec[k + 1].z();
  }
  rx *= scale;
  ry *= scale;
  const double r = std::hypot(q.x(), q.y());
  if (r == 0.0) return -std::min(rx, ry);
  const double c = q.x() / r, sn = q.y() / r;
  const double rho = 1.0 / std::sqrt((c / std::max(rx, 1e-12)) * (c / std::max(rx, 1e-12)) +
                                     (sn / std::max(ry, 1e-12)) * (sn / std::max(ry, 1e-12)));
  return r - rho;
}

double SkinClearance::clearance(const SkeletonPose& pose, const Eigen::Vector3d& p,
                                const std::vector<std::size_t>& segments) const {
  double best = std::numeric_limits<double>::infinity();
  if (segments.empty()) {
    for (std::size_t s = 0; s < segments_.size(); ++s) best = std::min(best, clearance(pose, s, p));
  } else {
    for (std::size_t s : segments) best = std::min(best, clearance(pose, s, p));
  }
  return best;
}

namespace {

double boxDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  const Eigen::Vector3d d = (lo - p).cwiseMax(p - hi).cwiseMax(Eigen::Vector3d::Zero());
  return d.norm();
}

// Closest point to p on triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
Eigen::Vector3d closestOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                  const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denominator = 1.0 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

}  // namespace

SkinSurfaceClearance::SkinSurfaceClearance(const Skeleton& skeleton, const BodyDescription& body, int grid)
    : skin_(skeleton, body), grid_(grid) {
  if (grid_ < 1) throw std::invalid_argument("SkinSurfaceClearance: grid must be >= 1");
  part_patches_.resize(skin_.partCount());
  for (std::size_t p = 0; p < skin_.patches().size(); ++p) {
    const int s = skin_.patchSegment(p);
    part_patches_.at(skin_.segments().at(static_cast<std::size_t>(s)).part).push_back(p);
  }
  boxes_.resize(skin_.patches().size());
  triangles_.resize(skin_.patches().size() * static_cast<std::size_t>(2 * grid_ * grid_));
  skin_.poseAtRest();
  pose(SkeletonPose());
}

void SkinSurfaceClearance::pose(const SkeletonPose& pose) {
  if (!pose.bone_in_world.empty()) skin_.pose(pose);
  const int n = grid_;
  std::vector<Eigen::Vector3d> grid(static_cast<std::size_t>((n + 1) * (n + 1)));
  std::size_t t = 0;
  for (std::size_t p = 0; p < skin_.patches().size(); ++p) {
    const BezierPatch& patch = skin_.patches()[p];
    PatchBox& box = boxes_[p];
    box.lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    box.hi = -box.lo;
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) {
        const Eigen::Vector3d x = patch.position(static_cast<double>(i) / n, static_cast<double>(j) / n);
        grid[static_cast<std::size_t>(i * (n + 1) + j)] = x;
        box.lo = box.lo.cwiseMin(x);
        box.hi = box.hi.cwiseMax(x);
      }
    }
    box.first = t;
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const Eigen::Vector3d& q00 = grid[static_cast<std::size_t>(i * (n + 1) + j)];
        const Eigen::Vector3d& q10 = grid[static_cast<std::size_t>((i + 1) * (n + 1) + j)];
        const Eigen::Vector3d& q01 = grid[static_cast<std::size_t>(i * (n + 1) + j + 1)];
        const Eigen::Vector3d& q11 = grid[static_cast<std::size_t>((i + 1) * (n + 1) + j + 1)];
        for (int half = 0; half < 2; ++half) {
          Triangle& tri = triangles_[t++];
          // u then v: (q10 - q00) x (q01 - q00) is along F_u x F_v, outward on the skin.
          if (half == 0) {
            tri.a = q00;
            tri.b = q10;
            tri.c = q11;
          } else {
            tri.a = q00;
            tri.b = q11;
            tri.c = q01;
          }
          const Eigen::Vector3d normal = (tri.b - tri.a).cross(tri.c - tri.a);
          const double length = normal.norm();
          tri.normal = length > 1e-18 ? Eigen::Vector3d(normal / length) : Eigen::Vector3d::Zero();
        }
      }
    }
    box.count = t - box.first;
  }
}

double SkinSurfaceClearance::clearance(const Eigen::Vector3d& p) const {
  std::size_t part = 0;
  return clearance(p, part);
}

double SkinSurfaceClearance::clearance(const Eigen::Vector3d& p, std::size_t& part) const {
  return clearance(p, {}, part);
}

std::vector<std::size_t> SkinSurfaceClearance::partsOf(const std::vector<std::string>& segment_names) const {
  std::vector<std::size_t> out;
  for (const SkinSegment& segment : skin_.segments()) {
    if (std::find(segment_names.begin(), segment_names.end(), segment.name) == segment_names.end()) continue;
    if (std::find(out.begin(), out.end(), segment.part) == out.end()) out.push_back(segment.part);
  }
  std::sort(out.begin(), out.end());
  return out;
}

double SkinSurfaceClearance::clearance(const Eigen::Vector3d& p, const std::vector<std::size_t>& parts,
                                       std::size_t& part) const {
  double best = std::numeric_limits<double>::infinity();
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t k = 0; k < part_patches_.size(); ++k) {
    if (!parts.empty() && std::find(parts.begin(), parts.end(), k) == parts.end()) continue;
    // A part whose patch boxes are all farther than `best` cannot contain p nor beat best.
    double lower = std::numeric_limits<double>::infinity();
    order.clear();
    for (std::size_t patch : part_patches_[k]) {
      const double d = boxDistance(p, boxes_[patch].lo, boxes_[patch].hi);
      lower = std::min(lower, d);
      order.emplace_back(d, patch);
    }
    if (lower > best) continue;
    std::sort(order.begin(), order.end());
    double nearest = std::numeric_limits<double>::infinity();
    double sign_weight = 0.0;
    for (const auto& [box_distance, patch] : order) {
      if (box_distance > nearest) break;
      const PatchBox& box = boxes_[patch];
      for (std::size_t t = box.first; t < box.first + box.count; ++t) {
        const Triangle& tri = triangles_[t];
        if (tri.normal.isZero()) continue;
        const Eigen::Vector3d q = closestOnTriangle(p, tri.a, tri.b, tri.c);
        const double d = (p - q).norm();
        const double side = (p - q).dot(tri.normal);
        // Ties (q on an edge or vertex shared by several triangles): keep the clearest side.
        if (d < nearest - 1e-12 || (d <= nearest + 1e-12 && std::abs(side) > std::abs(sign_weight))) {
          nearest = std::min(nearest, d);
          sign_weight = side;
        }
      }
    }
    const double signed_distance = sign_weight < 0.0 ? -nearest : nearest;
    if (signed_distance < best) {
      best = signed_distance;
      part = k;
    }
  }
  return best;
}

}  // namespace dressed_human
