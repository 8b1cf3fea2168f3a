// The skin model (issue 4): C0 at joints over the walk, watertight closed meshes at uniform and
// mixed adaptive levels, Eq. 5 scaling consistent with ForwardKinematics, allocation-free posing.
#include "dressed_human/core/surfaces/skin.h"

#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <map>
#include <new>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "allocation_counter.h"

namespace dressed_human {
namespace {

const std::string kSource = DRESSED_HUMAN_SOURCE_DIR;

const Skeleton& skeleton() {
  static const Skeleton s = Skeleton::fromUrdfFile(kSource + "/urdf/human.urdf");
  return s;
}

const BodyDescription& defaultBody() {
  static const BodyDescription b = loadBodyDescriptionFile(kSource + "/config/bodies/default.yaml", skeleton());
  return b;
}

// `count` poses spread over one period of the walk (plus one extreme pose per 10).
std::vector<SkeletonPose> walkPoses(const ForwardKinematics& kinematics, int count) {
  MotionEvaluator walk(loadMotionFile(kSource + "/config/motions/walk.yaml"));
  std::vector<SkeletonPose> poses(static_cast<std::size_t>(count));
  JointAngles angles;
  RigidTransform root;
  for (int i = 0; i < count; ++i) {
    walk.evaluate(walk.motion().period * i / count, angles, root);
    kinematics.compute(root, angles, poses[static_cast<std::size_t>(i)]);
  }
  return poses;
}

double maxJointGap(const Skin& skin) {
  double gap = 0.0;
  for (const SkinJoint& joint : skin.joints()) {
    for (int q = 0; q < 4; ++q) {
      const auto a = edgeControlPoints(skin.patches()[joint.parent_patches[q]], PatchEdge::kV1);
      const auto b = edgeControlPoints(skin.patches()[joint.child_patches[q]], PatchEdge::kV0);
      for (int k = 0; k < 4; ++k) gap = std::max(gap, (a[k] - b[k]).norm());
    }
  }
  return gap;
}

struct EdgeCheck {
  std::size_t edges = 0;
  std::size_t bad_edges = 0;   // not used by exactly two triangles in opposite directions
  std::size_t degenerate = 0;  // triangles with a repeated vertex
  long euler = 0;              // V - E + F
};

EdgeCheck checkEdges(const TriangleMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  EdgeCheck check;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::uint32_t* v = &mesh.indices[3 * t];
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) ++check.degenerate;
    for (int e = 0; e < 3; ++e) ++directed[{v[e], v[(e + 1) % 3]}];
  }
  std::set<std::pair<std::uint32_t, std::uint32_t>> undirected;
  for (const auto& [edge, uses] : directed) {
    undirected.insert({std::min(edge.first, edge.second), std::max(edge.first, edge.second)});
    const auto reverse = directed.find({edge.second, edge.first});
    if (uses != 1 || reverse == directed.end() || reverse->second != 1) ++check.bad_edges;
  }
  check.edges = undirected.size();
  check.euler =
      static_cast<long>(mesh.vertexCount()) - static_cast<long>(check.edges) + static_cast<long>(mesh.triangleCount());
  return check;
}

double signedVolume(const TriangleMesh& mesh) {
  double volume = 0.0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const Eigen::Vector3d a = mesh.positions[mesh.indices[3 * t]].cast<double>();
    const Eigen::Vector3d b = mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
    const Eigen::Vector3d c = mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

void expectClosed(const TriangleMesh& mesh, std::size_t parts, const std::string& what) {
  const EdgeCheck check = checkEdges(mesh);
  EXPECT_EQ(check.bad_edges, 0u) << what << ": edges not shared by exactly two triangles";
  EXPECT_EQ(check.degenerate, 0u) << what;
  // Every part is a topological sphere: V - E + F = 2 per part.
  EXPECT_EQ(check.euler, 2 * static_cast<long>(parts)) << what;
  EXPECT_GT(signedVolume(mesh), 0.0) << what << ": normals must point outwards";
  for (const Eigen::Vector3f& n : mesh.normals) {
    ASSERT_TRUE(n.allFinite()) << what;
    ASSERT_NEAR(n.norm(), 1.0f, 1e-4f) << what;
  }
}

TEST(Skin, DefaultBodyLayout) {
  const Skin skin(skeleton(), defaultBody());
  EXPECT_EQ(skin.partCount(), 7u);       // trunk, 2 clavicles, 2 arms, 2 legs
  EXPECT_EQ(skin.joints().size(), 12u);  // waist, torso, neck, head, 2 x (elbow, wrist, knee, ankle)
  EXPECT_EQ(skin.topology().patchCount(), skin.patches().size());
  for (std::size_t p = 0; p < skin.patches().size(); ++p) {
    ASSERT_GE(skin.patchSegment(p), 0);
    ASSERT_LT(static_cast<std::size_t>(skin.patchSegment(p)), skin.segments().size());
  }
  // The trunk reaches from below the pelvis to the crown of the head, ~1.75 m - 0.96 m above it.
  double top = -1.0, bottom = 1.0;
  for (const BezierPatch& patch : skin.patches()) {
    top = std::max(top, patch.boundingBoxMax().z());
    bottom = std::min(bottom, patch.boundingBoxMin().z());
  }
  EXPECT_NEAR(top, 0.79, 0.02);
  EXPECT_NEAR(bottom, -0.96, 0.04);  // the feet's soles
}

TEST(Skin, C0AtEveryJointOverTheWalk) {
  const ForwardKinematics kinematics(skeleton(), defaultBody().shape);
  Skin skin(skeleton(), defaultBody());
  double worst = 0.0;
  double worst_centre = 0.0;
  for (const SkeletonPose& pose : walkPoses(kinematics, 120)) {
    skin.pose(pose);
    worst = std::max(worst, maxJointGap(skin));
    // The shared ring is centred on the joint (its 4 axis points are symmetric about it).
    for (const SkinJoint& joint : skin.joints()) {
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (int q = 0; q < 4; ++q) centre += skin.patches()[joint.child_patches[q]].controlPoint(0, 0) / 4.0;
      worst_centre = std::max(
          worst_centre, (centre - pose.bone_in_world[static_cast<std::size_t>(joint.child_bone)].translation).norm());
    }
  }
  std::printf("max C0 gap over 120 walk poses, 12 joints: %.3g m; ring centre off joint: %.3g m\n", worst,
              worst_centre);
  EXPECT_LE(worst, 1e-9);
  EXPECT_LE(worst_centre, 1e-9);
}

TEST(Skin, C0ResistsExtremeAngles) {
  const ForwardKinematics kinematics(skeleton(), defaultBody().shape);
  Skin skin(skeleton(), defaultBody());
  std::mt19937 random(4);
  std::uniform_real_distribution<double> angle(-2.0, 2.0);
  SkeletonPose pose;
  for (int i = 0; i < 100; ++i) {
    JointAngles angles;
    for (double& a : angles) a = angle(random);
    RigidTransform root;
    root.translation = Eigen::Vector3d(angle(random), angle(random), 1.0);
    root.rotation = Eigen::AngleAxisd(angle(random), Eigen::Vector3d::UnitZ());
    kinematics.compute(root, angles, pose);
    skin.pose(pose);
    ASSERT_LE(maxJointGap(skin), 1e-9);
  }
}

TEST(Skin, WatertightUniformAndAdaptive) {
  const ForwardKinematics kinematics(skeleton(), defaultBody().shape);
  Skin skin(skeleton(), defaultBody());
  const std::vector<SkeletonPose> poses = walkPoses(kinematics, 4);
  Tessellator tessellator;
  for (const SkeletonPose& pose : poses) {
    skin.pose(pose);
    for (int level : {1, 2, 3, Skin::kDefaultLevel, 8}) {
      expectClosed(tessellator.tessellateUniform(skin.patches(), skin.topology(), level), skin.partCount(),
                   "uniform " + std::to_string(level));
    }
    const TriangleMesh& adaptive = tessellator.tessellateToError(skin.patches(), skin.topology(), 0.5e-3);
    const auto [lo, hi] = std::minmax_element(tessellator.levels().begin(), tessellator.levels().end());
    EXPECT_LT(*lo, *hi) << "the adaptive levels should be mixed";
    expectClosed(adaptive, skin.partCount(), "adaptive 0.5 mm");
    const CameraView camera{Eigen::Vector3d(3.0, 1.0, 0.5), 0.8, 720.0};
    expectClosed(tessellator.tessellateForCamera(skin.patches(), skin.topology(), camera, 0.5), skin.partCount(),
                 "camera 0.5 px");
  }
  // Random mixed levels.
  std::mt19937 random(7);
  std::uniform_int_distribution<int> level(1, 12);
  std::vector<int> levels(skin.patches().size());
  for (int trial = 0; trial < 5; ++trial) {
    for (int& l : levels) l = level(random);
    expectClosed(tessellator.tessellate(skin.patches(), skin.topology(), levels), skin.partCount(), "random levels");
  }
}

TEST(Skin, PoseAndTessellateAllocateNothing) {
  const ForwardKinematics kinematics(skeleton(), defaultBody().shape);
  Skin skin(skeleton(), defaultBody());
  const std::vector<SkeletonPose> poses = walkPoses(kinematics, 10);
  Tessellator tessellator;
  tessellator.tessellateUniform(skin.patches(), skin.topology(), Skin::kDefaultLevel);
  allocation_count = 0;
  counting_allocations = true;
  for (const SkeletonPose& pose : poses) {
    skin.pose(pose);
    tessellator.tessellateUniform(skin.patches(), skin.topology(), Skin::kDefaultLevel);
  }
  counting_allocations = false;
  EXPECT_EQ(allocation_count.load(), 0);
}

// Eq. 5: a, b thicken the bone's skin along its x, y; c lengthens it and moves the child's
// joint ring exactly where ForwardKinematics puts the child.
TEST(Skin, Eq5Scaling) {
  const Skeleton& s = skeleton();
  const std::size_t thigh = static_cast<std::size_t>(s.findBone("l_hip"));
  const std::size_t shank = static_cast<std::size_t>(s.findBone("l_knee"));
  BodyShape shape = defaultBody().shape;
  shape.scale[thigh] = Eigen::Vector3d(1.3, 0.8, 1.2);
  const Skin plain(s, defaultBody());
  const Skin scaled(s, defaultBody(), shape);
  int segment = -1;
  for (std::size_t k = 0; k < plain.segments().size(); ++k) {
    if (plain.segments()[k].bone == static_cast<int>(thigh)) segment = static_cast<int>(k);
  }
  ASSERT_GE(segment, 0);
  // Rest pose: the thigh frame's rotation R and origin o; local = R^T (world - o).
  const ForwardKinematics fk_plain(s, defaultBody().shape), fk_scaled(s, shape);
  SkeletonPose rest_plain, rest_scaled;
  JointAngles zero;
  zero.fill(0.0);
  fk_plain.compute(RigidTransform(), zero, rest_plain);
  fk_scaled.compute(RigidTransform(), zero, rest_scaled);
  const RigidTransform& frame = rest_plain.bone_in_world[thigh];
  EXPECT_LT((rest_scaled.bone_in_world[thigh].translation - frame.translation).norm(), 1e-12);
  const SkinSegment& seg = plain.segments()[static_cast<std::size_t>(segment)];
  // The thigh's own control points scale exactly: the proximal dome and the surface rings of its
  // sections. (The inner handle rings of a stack follow Catmull-Rom slopes that look across the
  // knee at the shank's radii, which this shape does not scale; the knee ring is checked below.)
  for (std::uint32_t p = seg.proximal_cap_first; p < seg.first_patch + 4 * seg.stack_count; ++p) {
    const auto& a = plain.patches()[p].controlPoints();
    const auto& b = scaled.patches()[p].controlPoints();
    const bool cap = p < seg.first_patch;
    const bool last_stack = p >= seg.first_patch + 4 * (seg.stack_count - 1);
    for (int k = 0; k < 16; ++k) {
      const int row = k / 4;
      if (!cap && (row == 1 || row == 2 || (last_stack && row == 3))) continue;
      const Eigen::Vector3d la = frame.rotation.inverse() * (a[k] - frame.translation);
      const Eigen::Vector3d lb = frame.rotation.inverse() * (b[k] - frame.translation);
      EXPECT_NEAR(lb.x(), 1.3 * la.x(), 1e-12);
      EXPECT_NEAR(lb.y(), 0.8 * la.y(), 1e-12);
      EXPECT_NEAR(lb.z(), 1.2 * la.z(), 1e-12);
    }
  }
  // The knee moved down by 0.2 x 0.42 m; the shared ring follows it; the shank is unchanged in
  // its own frame (same shape there), so the foot moved with it.
  const Eigen::Vector3d knee_plain = rest_plain.bone_in_world[shank].translation;
  const Eigen::Vector3d knee_scaled = rest_scaled.bone_in_world[shank].translation;
  EXPECT_NEAR((knee_scaled - knee_plain).norm(), 0.2 * 0.42, 1e-9);
  for (const SkinJoint& joint : scaled.joints()) {
    if (joint.child_bone != static_cast<int>(shank)) continue;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int q = 0; q < 4; ++q) centre += scaled.patches()[joint.child_patches[q]].controlPoint(0, 0) / 4.0;
    EXPECT_LT((centre - knee_scaled).norm(), 1e-12);
  }
  EXPECT_LE(maxJointGap(scaled), 1e-12);
  // Posed with the scaled FK over the walk, C0 still holds.
  Skin posed(s, defaultBody(), shape);
  for (const SkeletonPose& pose : walkPoses(fk_scaled, 20)) {
    posed.pose(pose);
    ASSERT_LE(maxJointGap(posed), 1e-9);
  }
  // radiusAt reports the scaled thickness.
  const Eigen::Vector2d r_plain = plain.radiusAt(static_cast<std::size_t>(segment), 0.0);
  const Eigen::Vector2d r_scaled = scaled.radiusAt(static_cast<std::size_t>(segment), 0.0);
  EXPECT_NEAR(r_scaled.x(), 1.3 * r_plain.x(), 1e-12);
  EXPECT_NEAR(r_scaled.y(), 0.8 * r_plain.y(), 1e-12);
}

TEST(Skin, LimbDomesStayOnTheirJoint) {
  // The proximal dome of an arm or leg is centred on its ball joint: its pole stays at the cap
  // height from the joint in every pose, so swinging the limb uncovers nothing.
  const ForwardKinematics kinematics(skeleton(), defaultBody().shape);
  Skin skin(skeleton(), defaultBody());
  for (const SkeletonPose& pose : walkPoses(kinematics, 20)) {
    skin.pose(pose);
    for (const SkinSegment& segment : skin.segments()) {
      if (!segment.has_proximal_cap || segment.bone < 0) continue;
      const std::string& name = segment.name;
      if (name != "l_shoulder" && name != "r_shoulder" && name != "l_hip" && name != "r_hip") continue;
      const Eigen::Vector3d joint = pose.bone_in_world[static_cast<std::size_t>(segment.bone)].translation;
      const Eigen::Vector3d pole = skin.patches()[segment.proximal_cap_first].controlPoint(0, 0);
      const double radius = skin.radiusAt(static_cast<std::size_t>(&segment - &skin.segments()[0]), 0.0).x();
      EXPECT_NEAR((pole - joint).norm(), radius, 1e-12) << name;
    }
  }
}

TEST(Skin, RejectsDescriptionsThatDoNotFit) {
  BodyDescription body = defaultBody();
  body.segments[0].bone = "tail";
  EXPECT_THROW(Skin(skeleton(), body), SkinError);
  BodyShape shape;
  shape.scale[3] = Eigen::Vector3d(1.0, -1.0, 1.0);
  EXPECT_ANY_THROW(Skin(skeleton(), defaultBody(), shape));
}

}  // namespace
}  // namespace dressed_human
