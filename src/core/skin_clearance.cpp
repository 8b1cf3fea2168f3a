#include "dressed_human/core/skin_clearance.h"

#include <algorithm>
#include <cmath>

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
  const RigidTransform& frame = profile.bone < 0 ? pose.root : pose.bone_in_world[static_cast<std::size_t>(profile.bone)];
  const Eigen::Vector3d q = frame.rotation.conjugate() * (p - frame.translation);
  const std::vector<Eigen::Vector3d>& sec = profile.sections;
  double rx = 0.0, ry = 0.0, scale = 1.0;
  const double z0 = sec.front().x();
  const double z1 = sec.back().x();
  if (q.z() < z0) {
    if (profile.proximal_cap <= 0.0 || q.z() < z0 - profile.proximal_cap) return std::numeric_limits<double>::infinity();
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

double SkinClearance::clearance(const SkeletonPose& pose, const Eigen::Vector3d& p, const std::vector<std::size_t>& segments) const {
  double best = std::numeric_limits<double>::infinity();
  if (segments.empty()) {
    for (std::size_t s = 0; s < segments_.size(); ++s) best = std::min(best, clearance(pose, s, p));
  } else {
    for (std::size_t s : segments) best = std::min(best, clearance(pose, s, p));
  }
  return best;
}

}  // namespace dressed_human
