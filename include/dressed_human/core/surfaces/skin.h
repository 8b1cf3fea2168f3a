// The skin (SPEC §2, issue 4): one generalized cylinder of bicubic Bezier patches per skinned
// bone, posed from the skeleton's bone frames, C0 at every chained joint in every pose.
//
// API summary
//   BodyDescription body = loadBodyDescriptionFile("config/bodies/default.yaml", skeleton);
//   ForwardKinematics fk(skeleton, body.shape);          // the same Eq. 5 shape as the skin
//   Skin skin(skeleton, body);                           // topology and local rings, once
//   fk.compute(root, angles, pose);
//   skin.pose(pose);                                     // world control points, no allocation
//   Tessellator tessellator;                             // keep it: it reuses its layout
//   const TriangleMesh& mesh =
//       tessellator.tessellateUniform(skin.patches(), skin.topology(), Skin::kDefaultLevel);
//   // or tessellateToError(skin.patches(), skin.topology(), 1e-3) /
//   //    tessellateForCamera(skin.patches(), skin.topology(), camera, 1.0)
//   skin.patches()[p], skin.patchSegment(p), skin.segments()[s].bone: what lies where;
//   skin.radiusAt(s, z): the rest cross-section of segment s at bone-frame height z (clearance).
//
// Layout. A segment is the skin of one bone (or of the root frame "body": the pelvis region):
// a list of surface sections (z, radius_x, radius_y) in the bone frame at rest, before Eq. 5.
// Between two sections lies one stack of 4 patches (a quarter of the elliptic cross-section
// each, u around the bone counter-clockwise about +z, v along +z, normals outwards); the two
// inner control rings of a stack follow a Catmull-Rom slope of the radii, so a bone's profile
// is C1 along its length. A segment "joined" to its parent's segment continues it: the parent's
// last stack ends on the child's first section, the joint ring.
//
// C0 at chained joints (neck, elbows, knees, ...): the joint ring is computed once per pose in
// world space, in the joint frame = the half-way rotation (slerp 1/2) between the parent's and
// the child's bone frames, at the child's proximal joint; the parent's last stack and the
// child's first stack both take those very doubles as their joint-side control points (the
// seed's "transformation making the connecting control points identical"). The gap is therefore
// exactly 0 in every pose, and the ring bisects the bend instead of sticking to either bone.
//
// Junctions of several bones (pelvis with waist and hips; chest with neck and clavicles/arms):
// closed overlapping ends tucked inside. The trunk is one chained tube (pelvis region in the
// root frame -> waist -> torso -> neck -> head) closed by a dome under the pelvis and one on
// the head. Each arm (upper arm -> forearm -> hand) and each leg (thigh -> shank -> foot) is a
// chained tube whose proximal end is a hemispherical dome centred on the shoulder / hip joint,
// inside the trunk (or clavicle); clavicles are closed capsules fixed to the chest. A dome
// centred on its joint covers the same ball whatever the joint angles, so rotating a limb
// never opens a gap; every part is a closed surface, so their union is closed. Chosen over a
// single trunk surface with ring-matched openings because that needs a non-cylindrical patch
// layout (n-sided junctions), whereas this stays a set of generalized cylinders exactly as the
// paper describes, and is still C0 wherever a bone continues another.
//
// Openings: none. Every part is closed (caps' poles are collapsed patch edges welded by the
// Tessellator), so a tessellation has every edge shared by exactly two triangles.
#pragma once

#include "dressed_human/core/surfaces/bezier_patch.h"
#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/skeleton/skeleton.h"
#include "dressed_human/core/surfaces/tessellation.h"

#include <Eigen/Geometry>

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace dressed_human {

struct SkinError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One segment as the Skin built it.
struct SkinSegment {
  std::string name;        // bone name, or "body" for the root-frame (pelvis) segment
  int bone = -1;           // -1: the root frame
  int joined_parent = -1;  // segment this one continues (shares the joint ring with), or -1
  int joined_child = -1;   // segment continuing this one, or -1
  std::uint32_t first_patch = 0;
  std::uint32_t stack_count = 0;         // 4 patches per stack
  std::uint32_t proximal_cap_first = 0;  // 4 patches, if has_proximal_cap
  std::uint32_t distal_cap_first = 0;    // 4 patches, if has_distal_cap
  bool has_proximal_cap = false;
  bool has_distal_cap = false;
  std::uint32_t part = 0;  // connected closed surface this segment belongs to
};

// A chained joint: where segment `parent`'s last stack meets segment `child`'s first stack.
struct SkinJoint {
  int parent_segment;
  int child_segment;
  int child_bone;
  // The 4 patches on each side whose joint edges must coincide: the parent's (v = 1 edges) and
  // the child's (v = 0 edges), quarter q against quarter q.
  std::array<std::uint32_t, 4> parent_patches;
  std::array<std::uint32_t, 4> child_patches;
};

class Skin {
 public:
  // A uniform level that keeps pose + tessellate of the whole default body well under 0.25 ms
  // on one core (see bench/bench_skin.cpp and the README).
  static constexpr int kDefaultLevel = 4;

  // Builds local control rings (Eq. 5 `shape` applied) and the fixed patch topology.
  // Throws SkinError if the description does not fit the skeleton.
  Skin(const Skeleton& skeleton, const BodyDescription& body, const BodyShape& shape);
  Skin(const Skeleton& skeleton, const BodyDescription& body) : Skin(skeleton, body, body.shape) {}

  // World-space control points from the bone frames of `pose` (ForwardKinematics output, with
  // the same shape). Cost proportional to the number of control points; allocation-free.
  void pose(const SkeletonPose& pose);
  // The same at rest (all angles zero, root at the origin), as built by the constructor.
  void poseAtRest();

  const std::vector<BezierPatch>& patches() const { return patches_; }
  const PatchTopology& topology() const { return topology_; }
  const std::vector<SkinSegment>& segments() const { return segments_; }
  const std::vector<SkinJoint>& joints() const { return joints_; }
  std::size_t partCount() const { return part_count_; }
  int patchSegment(std::size_t patch) const { return patch_segment_[patch]; }
  const BodyShape& shape() const { return shape_; }

  // Rest cross-section semi-axes (Eq. 5 applied) of segment s at bone-frame height z (metres,
  // shape applied), interpolated along the profile; clamped to the end sections.
  Eigen::Vector2d radiusAt(std::size_t segment, double z) const;

 private:
  // 12 control points of an elliptic ring (4 Bezier quarter arcs, shared ends), local frame.
  using Ring = std::array<Eigen::Vector3d, 12>;
  struct SegmentRings {
    std::vector<Ring> rows;                // 3 * stacks + 1 rows; the joint ring (row 0) when joined
    std::array<Ring, 3> proximal_cap;      // pole-side rows of the proximal dome (pole first)
    std::array<Ring, 3> distal_cap;        // rows after the last section (pole last)
    std::vector<Eigen::Vector3d> profile;  // (z, radius_x, radius_y) of the sections, shape applied
  };

  // A section of a segment's profile: height along the chain (may be shifted into the
  // neighbour's frame, for slopes only) and semi-axes, shape applied.
  struct ProfilePoint {
    double z;
    Eigen::Vector2d radius;
  };
  using Profile = std::vector<ProfilePoint>;

  // The constructor's steps, in order.
  void joinSegments(const BodyDescription& body);
  Eigen::Vector3d boneScale(int bone) const;
  std::vector<Profile> sectionProfiles(const BodyDescription& body, const ForwardKinematics& kinematics) const;
  // dr/dz at each of segment s's own sections.
  std::vector<Eigen::Vector2d> profileSlopes(std::size_t s, const std::vector<Profile>& profiles) const;
  void buildSegmentRings(std::size_t s, const SkinSegmentSpec& spec, const std::vector<Profile>& profiles);
  std::uint32_t numberPatches();
  void linkPatches(std::uint32_t patch_count);

  void transformRing(const Ring& local, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation,
                     Ring& world) const;
  // Writes segment s's patches from its posed rings.
  void assembleSegment(std::size_t s, const SegmentRings& posed);

  Skeleton skeleton_;
  BodyShape shape_;
  std::vector<SkinSegment> segments_;
  std::vector<SkinJoint> joints_;
  std::vector<SegmentRings> local_;
  // Posing goes segment by segment through one scratch (it stays in cache, where a posed copy
  // of every ring would not); joint rings, posed first, are indexed by their child segment.
  SegmentRings posed_segment_;
  std::vector<Ring> posed_joint_rings_;
  std::vector<BezierPatch> patches_;
  std::vector<int> patch_segment_;
  PatchTopology topology_;
  std::size_t part_count_ = 0;
};

}  // namespace dressed_human
