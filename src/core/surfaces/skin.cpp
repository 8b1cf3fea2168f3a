#include "dressed_human/core/surfaces/skin.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace dressed_human {

namespace {

// Inner control point offset of a quarter circle as a cubic Bezier (as in generalized_cylinder).
const double kQuarterCircleHandle = 4.0 * (std::sqrt(2.0) - 1.0) / 3.0;
const Eigen::Vector2d kAxisDirection[4] = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}};

// A section's semi-axes may shrink towards a narrower neighbour through the Catmull-Rom handles,
// but an inner control ring never gets thinner than this fraction of its stack's thinner end.
constexpr double kMinimumHandleRadius = 0.25;

// 12 ring points: axis point q at 3q, then the two handles of quarter q.
template <typename Ring>
void fillRing(double z, double radius_x, double radius_y, Ring& ring) {
  const double k = kQuarterCircleHandle;
  for (int q = 0; q < 4; ++q) {
    const Eigen::Vector2d& start = kAxisDirection[q];
    const Eigen::Vector2d& end = kAxisDirection[(q + 1) % 4];
    const Eigen::Vector2d units[3] = {start, start + k * end, end + k * start};
    for (int i = 0; i < 3; ++i) ring[3 * q + i] = Eigen::Vector3d(radius_x * units[i].x(), radius_y * units[i].y(), z);
  }
}

}  // namespace

Skin::Skin(const Skeleton& skeleton, const BodyDescription& body, const BodyShape& shape)
    : skeleton_(skeleton), shape_(shape) {
  const ForwardKinematics kinematics(skeleton_, shape_);  // validates the shape
  const std::size_t segment_count = body.segments.size();
  if (segment_count == 0) throw SkinError("Skin: the body description has no segments");

  joinSegments(body);
  // Local rings: surface rows (own sections, plus the child's joint ring), handle rows.
  local_.resize(segment_count);
  const std::vector<Profile> profiles = sectionProfiles(body, kinematics);
  for (std::size_t s = 0; s < segment_count; ++s) buildSegmentRings(s, body.segments[s], profiles);
  std::size_t most_rows = 0;
  for (const SegmentRings& rings : local_) most_rows = std::max(most_rows, rings.rows.size());
  posed_segment_.rows.resize(most_rows);
  posed_joint_rings_.resize(segment_count);

  const std::uint32_t patch_count = numberPatches();
  linkPatches(patch_count);  // fixed for every pose

  // Placeholder patches, overwritten by pose() (BezierPatch has no empty state).
  BezierPatch::ControlPoints unit;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) unit[BezierPatch::index(i, j)] = Eigen::Vector3d(i, j, 0.0);
  }
  patches_.assign(patch_count, BezierPatch(unit));
  poseAtRest();
}

// Segments, the joins between them, and the parts they make up.
void Skin::joinSegments(const BodyDescription& body) {
  const std::size_t segment_count = body.segments.size();
  segments_.resize(segment_count);
  for (std::size_t s = 0; s < segment_count; ++s) {
    const SkinSegmentSpec& spec = body.segments[s];
    SkinSegment& segment = segments_[s];
    segment.name = spec.bone;
    segment.bone = spec.bone == "body" ? -1 : skeleton_.findBone(spec.bone);
    if (spec.bone != "body" && segment.bone < 0) throw SkinError("Skin: no bone '" + spec.bone + "' in the skeleton");
    if (spec.sections.empty()) throw SkinError("Skin: segment '" + spec.bone + "' has no section");
    if (spec.joined_to_parent) {
      if (segment.bone < 0) throw SkinError("Skin: the root segment cannot be joined");
      const int parent_bone = skeleton_.bone(static_cast<std::size_t>(segment.bone)).parent;
      for (std::size_t p = 0; p < s; ++p) {
        if (segments_[p].bone == parent_bone) segment.joined_parent = static_cast<int>(p);
      }
      if (segment.joined_parent < 0)
        throw SkinError("Skin: segment '" + spec.bone + "' joins a parent segment that is not listed before it");
      SkinSegment& parent = segments_[static_cast<std::size_t>(segment.joined_parent)];
      if (parent.joined_child >= 0) throw SkinError("Skin: segment '" + parent.name + "' is joined by two children");
      parent.joined_child = static_cast<int>(s);
      segment.part = parent.part;
    } else {
      segment.part = static_cast<std::uint32_t>(part_count_++);
    }
  }
}

// Eq. 5's scale of a bone; the pelvis segment ("body", bone -1) is not scaled.
Eigen::Vector3d Skin::boneScale(int bone) const {
  return bone < 0 ? Eigen::Vector3d::Ones() : shape_.scale[static_cast<std::size_t>(bone)];
}

std::vector<Skin::Profile> Skin::sectionProfiles(const BodyDescription& body,
                                                 const ForwardKinematics& kinematics) const {
  const std::size_t segment_count = body.segments.size();
  std::vector<Profile> profiles(segment_count);
  for (std::size_t s = 0; s < segment_count; ++s) {
    const SkinSegmentSpec& spec = body.segments[s];
    const Eigen::Vector3d scale = boneScale(segments_[s].bone);
    for (const SkinSection& section : spec.sections) {
      profiles[s].push_back(
          {scale.z() * section.z, Eigen::Vector2d(scale.x() * section.radius_x, scale.y() * section.radius_y)});
    }
  }
  for (std::size_t s = 0; s < segment_count; ++s) {
    const SkinSegment& segment = segments_[s];
    if (segment.joined_child < 0) continue;
    const auto child = static_cast<std::size_t>(segment.joined_child);
    const double joint_z = kinematics.scaledRestTranslation(static_cast<std::size_t>(segments_[child].bone)).z();
    if (!(joint_z > profiles[s].back().z)) {
      throw SkinError("Skin: segment '" + segment.name + "' has a section at or beyond the joint of '" +
                      segments_[child].name + "'");
    }
    profiles[s].push_back({joint_z, profiles[child].front().radius});
  }
  return profiles;
}

// Central differences, across a joint too (the neighbour's z shifted along the chain, so both
// sides of a joint compute the same slope); 0 next to a cap (tangent to the dome).
std::vector<Eigen::Vector2d> Skin::profileSlopes(std::size_t s, const std::vector<Profile>& profiles) const {
  const SkinSegment& segment = segments_[s];
  const Profile& own = profiles[s];
  std::vector<ProfilePoint> extended;
  if (segment.joined_parent >= 0) {
    const std::vector<ProfilePoint>& parent = profiles[static_cast<std::size_t>(segment.joined_parent)];
    const ProfilePoint& before = parent[parent.size() - 2];
    extended.push_back({before.z - parent.back().z, before.radius});
  }
  const std::size_t offset = extended.size();
  extended.insert(extended.end(), own.begin(), own.end());
  if (segment.joined_child >= 0) {
    const std::vector<ProfilePoint>& child = profiles[static_cast<std::size_t>(segment.joined_child)];
    const ProfilePoint& after = child.size() > 1 ? child[1] : child[0];
    if (child.size() > 1) extended.push_back({own.back().z + after.z, after.radius});
  }
  const std::size_t rows = own.size();
  std::vector<Eigen::Vector2d> slope(rows, Eigen::Vector2d::Zero());
  for (std::size_t k = 0; k < rows; ++k) {
    const std::size_t e = k + offset;
    const bool capped_end = (k == 0 && segment.has_proximal_cap) || (k + 1 == rows && segment.has_distal_cap);
    if (capped_end) continue;
    const std::size_t lo = e > 0 ? e - 1 : e;
    const std::size_t hi = e + 1 < extended.size() ? e + 1 : e;
    slope[k] = (extended[hi].radius - extended[lo].radius) / (extended[hi].z - extended[lo].z);
  }
  return slope;
}

void Skin::buildSegmentRings(std::size_t s, const SkinSegmentSpec& spec, const std::vector<Profile>& profiles) {
  SkinSegment& segment = segments_[s];
  const Profile& own = profiles[s];
  if (own.size() < 2) throw SkinError("Skin: segment '" + segment.name + "' needs two surface rings");
  segment.has_proximal_cap = segment.joined_parent < 0;
  segment.has_distal_cap = segment.joined_child < 0;
  if (segment.has_proximal_cap && !(spec.proximal_cap > 0.0))
    throw SkinError("Skin: segment '" + segment.name + "' has an open proximal end");
  if (segment.has_distal_cap && !(spec.distal_cap > 0.0))
    throw SkinError("Skin: segment '" + segment.name + "' has an open distal end");

  const std::size_t rows = own.size();
  const std::vector<Eigen::Vector2d> slope = profileSlopes(s, profiles);
  SegmentRings& rings = local_[s];
  rings.rows.resize(3 * (rows - 1) + 1);
  for (std::size_t k = 0; k < rows; ++k) {
    fillRing(own[k].z, own[k].radius.x(), own[k].radius.y(), rings.rows[3 * k]);
    rings.profile.emplace_back(own[k].z, own[k].radius.x(), own[k].radius.y());
    if (k + 1 == rows) break;
    const double third = (own[k + 1].z - own[k].z) / 3.0;
    const Eigen::Vector2d floor = kMinimumHandleRadius * own[k].radius.cwiseMin(own[k + 1].radius);
    const Eigen::Vector2d near = (own[k].radius + third * slope[k]).cwiseMax(floor);
    const Eigen::Vector2d far = (own[k + 1].radius - third * slope[k + 1]).cwiseMax(floor);
    fillRing(own[k].z + third, near.x(), near.y(), rings.rows[3 * k + 1]);
    fillRing(own[k + 1].z - third, far.x(), far.y(), rings.rows[3 * k + 2]);
  }
  const double k = kQuarterCircleHandle;
  const double length_scale = boneScale(segment.bone).z();  // Eq. 5 applies to the domes too
  if (segment.has_proximal_cap) {
    const ProfilePoint& end = own.front();
    const double height = length_scale * spec.proximal_cap;
    const double pole_z = end.z - height;
    fillRing(pole_z, 0.0, 0.0, rings.proximal_cap[0]);
    fillRing(pole_z, k * end.radius.x(), k * end.radius.y(), rings.proximal_cap[1]);
    fillRing(end.z - k * height, end.radius.x(), end.radius.y(), rings.proximal_cap[2]);
  }
  if (segment.has_distal_cap) {
    const ProfilePoint& end = own.back();
    const double height = length_scale * spec.distal_cap;
    const double pole_z = end.z + height;
    fillRing(end.z + k * height, end.radius.x(), end.radius.y(), rings.distal_cap[0]);
    fillRing(pole_z, k * end.radius.x(), k * end.radius.y(), rings.distal_cap[1]);
    fillRing(pole_z, 0.0, 0.0, rings.distal_cap[2]);
  }
  segment.stack_count = static_cast<std::uint32_t>(rows - 1);
}

// Per segment: proximal cap, stacks, distal cap. Returns the patch count.
std::uint32_t Skin::numberPatches() {
  const std::size_t segment_count = segments_.size();
  std::uint32_t patch_count = 0;
  for (std::size_t s = 0; s < segment_count; ++s) {
    SkinSegment& segment = segments_[s];
    if (segment.has_proximal_cap) {
      segment.proximal_cap_first = patch_count;
      patch_count += 4;
    }
    segment.first_patch = patch_count;
    patch_count += 4 * segment.stack_count;
    if (segment.has_distal_cap) {
      segment.distal_cap_first = patch_count;
      patch_count += 4;
    }
  }
  patch_segment_.resize(patch_count);
  for (std::size_t s = 0; s < segment_count; ++s) {
    const SkinSegment& segment = segments_[s];
    const std::uint32_t first = segment.has_proximal_cap ? segment.proximal_cap_first : segment.first_patch;
    const std::uint32_t last =
        segment.has_distal_cap ? segment.distal_cap_first + 4 : segment.first_patch + 4 * segment.stack_count;
    for (std::uint32_t p = first; p < last; ++p) patch_segment_[p] = static_cast<int>(s);
  }

  return patch_count;
}

void Skin::linkPatches(std::uint32_t patch_count) {
  const std::size_t segment_count = segments_.size();
  topology_ = PatchTopology(patch_count);
  for (std::size_t s = 0; s < segment_count; ++s) {
    const SkinSegment& segment = segments_[s];
    auto side = [&](std::uint32_t stack, int q) {
      return segment.first_patch + 4 * stack + static_cast<std::uint32_t>(q);
    };
    for (int q = 0; q < 4; ++q) {
      const int next = (q + 1) % 4;
      for (std::uint32_t stack = 0; stack < segment.stack_count; ++stack) {
        topology_.link(side(stack, q), PatchEdge::kU1, side(stack, next), PatchEdge::kU0, false);
        if (stack + 1 < segment.stack_count)
          topology_.link(side(stack, q), PatchEdge::kV1, side(stack + 1, q), PatchEdge::kV0, false);
      }
      if (segment.has_proximal_cap) {
        const std::uint32_t cap = segment.proximal_cap_first;
        topology_.link(cap + q, PatchEdge::kU1, cap + next, PatchEdge::kU0, false);
        topology_.link(cap + q, PatchEdge::kV1, side(0, q), PatchEdge::kV0, false);
      }
      if (segment.has_distal_cap) {
        const std::uint32_t cap = segment.distal_cap_first;
        topology_.link(cap + q, PatchEdge::kU1, cap + next, PatchEdge::kU0, false);
        topology_.link(side(segment.stack_count - 1, q), PatchEdge::kV1, cap + q, PatchEdge::kV0, false);
      }
    }
    if (segment.joined_child >= 0) {
      const SkinSegment& child = segments_[static_cast<std::size_t>(segment.joined_child)];
      SkinJoint joint{static_cast<int>(s), segment.joined_child, child.bone, {}, {}};
      for (int q = 0; q < 4; ++q) {
        joint.parent_patches[q] = side(segment.stack_count - 1, q);
        joint.child_patches[q] = child.first_patch + static_cast<std::uint32_t>(q);
        topology_.link(joint.parent_patches[q], PatchEdge::kV1, joint.child_patches[q], PatchEdge::kV0, false);
      }
      joints_.push_back(joint);
    }
  }
}

void Skin::poseAtRest() {
  const ForwardKinematics kinematics(skeleton_, shape_);
  SkeletonPose rest;
  JointAngles zero;
  zero.fill(0.0);
  kinematics.compute(RigidTransform(), zero, rest);
  pose(rest);
}

void Skin::transformRing(const Ring& local, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation,
                         Ring& world) const {
  for (std::size_t i = 0; i < local.size(); ++i) world[i].noalias() = rotation * local[i] + translation;
}

void Skin::pose(const SkeletonPose& pose) {
  auto frameOf = [&](int bone) -> const RigidTransform& {
    return bone < 0 ? pose.root : pose.bone_in_world[static_cast<std::size_t>(bone)];
  };
  // Joint rings: once, in the half-way frame at the child's joint; both segments take it.
  for (const SkinJoint& joint : joints_) {
    const RigidTransform& parent_frame = frameOf(segments_[static_cast<std::size_t>(joint.parent_segment)].bone);
    const RigidTransform& child_frame = pose.bone_in_world[static_cast<std::size_t>(joint.child_bone)];
    const Eigen::Matrix3d rotation = parent_frame.rotation.slerp(0.5, child_frame.rotation).toRotationMatrix();
    const auto child = static_cast<std::size_t>(joint.child_segment);
    transformRing(local_[child].rows.front(), rotation, child_frame.translation, posed_joint_rings_[child]);
  }
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    const SkinSegment& segment = segments_[s];
    const RigidTransform& frame = frameOf(segment.bone);
    const Eigen::Matrix3d rotation = frame.rotation.toRotationMatrix();
    const SegmentRings& local = local_[s];
    SegmentRings& posed = posed_segment_;
    const std::size_t rows = local.rows.size();
    const std::size_t first = segment.joined_parent >= 0 ? 1 : 0;
    const std::size_t end = rows - (segment.joined_child >= 0 ? 1 : 0);
    for (std::size_t r = first; r < end; ++r) transformRing(local.rows[r], rotation, frame.translation, posed.rows[r]);
    if (segment.joined_parent >= 0) posed.rows.front() = posed_joint_rings_[s];
    if (segment.joined_child >= 0)
      posed.rows[rows - 1] = posed_joint_rings_[static_cast<std::size_t>(segment.joined_child)];
    if (segment.has_proximal_cap) {
      for (std::size_t r = 0; r < 3; ++r)
        transformRing(local.proximal_cap[r], rotation, frame.translation, posed.proximal_cap[r]);
    }
    if (segment.has_distal_cap) {
      for (std::size_t r = 0; r < 3; ++r)
        transformRing(local.distal_cap[r], rotation, frame.translation, posed.distal_cap[r]);
    }
    assembleSegment(s, posed);
  }
}

void Skin::assembleSegment(std::size_t s, const SegmentRings& posed) {
  const SkinSegment& segment = segments_[s];
  const Ring& last_row = posed.rows[local_[s].rows.size() - 1];
  BezierPatch::ControlPoints points;
  auto emit = [&](std::uint32_t patch, int q, const Ring* rows[4]) {
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i)
        points[BezierPatch::index(i, j)] = (*rows[j])[static_cast<std::size_t>((3 * q + i) % 12)];
    }
    patches_[patch].setControlPoints(points);
  };
  for (int q = 0; q < 4; ++q) {
    if (segment.has_proximal_cap) {
      const Ring* rows[4] = {&posed.proximal_cap[0], &posed.proximal_cap[1], &posed.proximal_cap[2],
                             &posed.rows.front()};
      emit(segment.proximal_cap_first + static_cast<std::uint32_t>(q), q, rows);
    }
    for (std::uint32_t stack = 0; stack < segment.stack_count; ++stack) {
      const Ring* rows[4] = {&posed.rows[3 * stack], &posed.rows[3 * stack + 1], &posed.rows[3 * stack + 2],
                             &posed.rows[3 * stack + 3]};
      emit(segment.first_patch + 4 * stack + static_cast<std::uint32_t>(q), q, rows);
    }
    if (segment.has_distal_cap) {
      const Ring* rows[4] = {&last_row, &posed.distal_cap[0], &posed.distal_cap[1], &posed.distal_cap[2]};
      emit(segment.distal_cap_first + static_cast<std::uint32_t>(q), q, rows);
    }
  }
}

Eigen::Vector2d Skin::radiusAt(std::size_t segment, double z) const {
  const std::vector<Eigen::Vector3d>& profile = local_.at(segment).profile;
  if (z <= profile.front().x()) return profile.front().tail<2>();
  for (std::size_t k = 1; k < profile.size(); ++k) {
    if (z <= profile[k].x()) {
      const double t = (z - profile[k - 1].x()) / (profile[k].x() - profile[k - 1].x());
      return (1.0 - t) * profile[k - 1].tail<2>() + t * profile[k].tail<2>();
    }
  }
  return profile.back().tail<2>();
}

}  // namespace dressed_human
