// Stability of forward kinematics where Euler angles and Eq. 5 scaling are known to fail
// (issue #8, docs/stability.md): the gimbal pose of every joint's y-x-z chain, angles at +-pi and
// at large multiples of 2 pi, and bones made very short or very long by the body shape.
#include <gtest/gtest.h>

#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/surfaces/skin.h"
#include "dressed_human/core/surfaces/tessellation.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <limits>
#include <string>

namespace dressed_human {
namespace {

const Skeleton& skeleton() {
  static const Skeleton s = Skeleton::fromUrdfFile(std::string(DRESSED_HUMAN_SOURCE_DIR) + "/urdf/human.urdf");
  return s;
}

Eigen::Vector3d boneEnd(const SkeletonPose& pose, const Skeleton& s, std::size_t bone, double scale_z = 1.0) {
  const RigidTransform& frame = pose.bone_in_world[bone];
  return frame.translation + frame.rotation * Eigen::Vector3d(0.0, 0.0, scale_z * s.bone(bone).length);
}

bool poseIsFinite(const SkeletonPose& pose) {
  for (const RigidTransform& t : pose.bone_in_world) {
    if (!t.translation.allFinite() || !t.rotation.coeffs().allFinite()) return false;
    if (std::abs(t.rotation.norm() - 1.0) > 1e-12) return false;
  }
  return true;
}

std::size_t jointIndex(const std::string& bone) {
  const int joint = skeleton().bone(static_cast<std::size_t>(skeleton().findBone(bone))).joint;
  EXPECT_GE(joint, 0) << bone;
  return static_cast<std::size_t>(joint);
}

// At x = +-90 degrees the y axis of the chain is carried onto the z axis: Ry(a) Rx(pi/2) Rz(c)
// depends on a - c only (a + c at -90). FK composes quaternions and has no singularity there; the
// bone must move continuously and at the speed the angles imply, and only the redundant direction
// must be lost.
TEST(StabilityFk, GimbalPoseIsContinuousAndOnlyLosesTheRedundantDirection) {
  const Skeleton& s = skeleton();
  const ForwardKinematics fk(s);
  for (const char* name : {"l_shoulder", "r_hip", "l_knee", "neck"}) {
    const std::size_t bone = static_cast<std::size_t>(s.findBone(name));
    const std::size_t first = jointIndex(name) * kDofsPerJoint;
    const double length = s.bone(bone).length;
    JointAngles angles{};
    angles[first] = 0.4;       // y
    angles[first + 2] = -0.7;  // z
    SkeletonPose pose, previous;
    // Sweep x through -90 and +90 degrees: the end point moves by at most length * step.
    const int steps = 4000;
    const double step = 2.0 * M_PI / steps;
    for (int k = 0; k <= steps; ++k) {
      angles[first + 1] = -M_PI + k * step;
      fk.compute(RigidTransform(), angles, pose);
      ASSERT_TRUE(poseIsFinite(pose)) << name;
      if (k > 0) {
        const double moved = (boneEnd(pose, s, bone) - boneEnd(previous, s, bone)).norm();
        EXPECT_LE(moved, length * step * (1.0 + 1e-9)) << name << " x = " << angles[first + 1];
      }
      previous = pose;
    }
    // At exactly +90 degrees, (y + d, z + d) is the same rotation; at -90, (y + d, z - d).
    for (double x : {M_PI / 2, -M_PI / 2}) {
      JointAngles moved = angles;
      angles[first + 1] = moved[first + 1] = x;
      moved[first] += 0.3;
      moved[first + 2] += x > 0 ? 0.3 : -0.3;
      SkeletonPose a, b;
      fk.compute(RigidTransform(), angles, a);
      fk.compute(RigidTransform(), moved, b);
      EXPECT_LT(a.bone_in_world[bone].rotation.angularDistance(b.bone_in_world[bone].rotation), 1e-12) << name;
      // ...but any other change of y or z still moves the bone: only one direction is lost.
      moved[first + 2] = angles[first + 2] + 0.3 * (x > 0 ? -1.0 : 1.0);
      fk.compute(RigidTransform(), moved, b);
      EXPECT_GT(a.bone_in_world[bone].rotation.angularDistance(b.bone_in_world[bone].rotation), 0.5) << name;
    }
  }
}

// Angles are not reduced before use: FK must give the same pose for theta, theta +- 2 pi k and at
// the +-pi seam, with an error that grows only like the rounding of the angle itself.
TEST(StabilityFk, AngleWrapAtPiAndLargeMultiplesOfTwoPi) {
  const Skeleton& s = skeleton();
  const ForwardKinematics fk(s);
  JointAngles base{};
  for (std::size_t i = 0; i < kDofCount; ++i) base[i] = 0.3 * std::sin(1.7 * static_cast<double>(i) + 0.2);
  SkeletonPose reference;
  fk.compute(RigidTransform(), base, reference);
  for (double turns : {1.0, -1.0, 3.0, 1e3, -1e3, 1e6, 1e8}) {
    JointAngles shifted = base;
    double largest_angle = 0.0;
    for (double& angle : shifted) {
      angle += 2.0 * M_PI * turns;
      largest_angle = std::max(largest_angle, std::abs(angle));
    }
    SkeletonPose pose;
    fk.compute(RigidTransform(), shifted, pose);
    ASSERT_TRUE(poseIsFinite(pose));
    // Each angle carries a rounding error of eps |angle|; a chain of ~6 joints (3 DOFs each) adds
    // them up, times the ~1 m reach of a chain.
    const double bound = 1e-14 + 40.0 * std::numeric_limits<double>::epsilon() * largest_angle;
    for (std::size_t b = 0; b < kBoneCount; ++b) {
      EXPECT_LT((boneEnd(pose, s, b) - boneEnd(reference, s, b)).norm(), bound) << "turns " << turns << " bone " << b;
    }
  }
  // +pi and -pi are the same rotation: quaternions q and -q.
  JointAngles plus{}, minus{};
  plus.fill(M_PI);
  minus.fill(-M_PI);
  SkeletonPose a, b;
  fk.compute(RigidTransform(), plus, a);
  fk.compute(RigidTransform(), minus, b);
  for (std::size_t bone = 0; bone < kBoneCount; ++bone) {
    EXPECT_LT((boneEnd(a, s, bone) - boneEnd(b, s, bone)).norm(), 1e-14);
    EXPECT_LT(a.bone_in_world[bone].rotation.angularDistance(b.bone_in_world[bone].rotation), 1e-14);
  }
  // Continuity through the seam: knee y from pi - 1e-9 to -pi + 1e-9 is a 2e-9 rad step.
  const std::size_t knee = static_cast<std::size_t>(s.findBone("l_knee"));
  JointAngles before{}, after{};
  before[jointIndex("l_knee") * kDofsPerJoint] = M_PI - 1e-9;
  after[jointIndex("l_knee") * kDofsPerJoint] = -M_PI + 1e-9;
  fk.compute(RigidTransform(), before, a);
  fk.compute(RigidTransform(), after, b);
  EXPECT_LT((boneEnd(a, s, knee) - boneEnd(b, s, knee)).norm(), 3e-9 * s.bone(knee).length);
}

// Eq. 5 with c -> 0 (a zero-length bone) and a, b, c over nine orders of magnitude.
TEST(StabilityFk, ExtremeBodyShapeScalesStayFiniteAndLinear) {
  const Skeleton& s = skeleton();
  const std::size_t thigh = static_cast<std::size_t>(s.findBone("l_hip"));
  const std::size_t shank = static_cast<std::size_t>(s.findBone("l_knee"));
  JointAngles angles{};
  angles[jointIndex("l_hip") * kDofsPerJoint] = 0.5;
  SkeletonPose plain_pose;
  ForwardKinematics(s).compute(RigidTransform(), angles, plain_pose);
  const Eigen::Vector3d hip = plain_pose.bone_in_world[thigh].translation;
  const Eigen::Vector3d knee_plain = plain_pose.bone_in_world[shank].translation;
  for (double c : {1e-6, 1e-3, 1e3}) {
    for (double ab : {1e-6, 1.0, 1e3}) {
      BodyShape shape;
      shape.scale[thigh] = Eigen::Vector3d(ab, ab, c);
      const ForwardKinematics fk(s, shape);
      SkeletonPose pose;
      fk.compute(RigidTransform(), angles, pose);
      ASSERT_TRUE(poseIsFinite(pose)) << "c " << c << " ab " << ab;
      // The knee sits at hip + c (knee - hip): linear in c; the thickness a, b does not move it
      // (the knee lies on the thigh's axis).
      const Eigen::Vector3d expected = hip + c * (knee_plain - hip);
      EXPECT_LT((pose.bone_in_world[shank].translation - expected).norm(), 1e-12 * std::max(1.0, c)) << c << " " << ab;
    }
  }
  // c = 0 would make a zero-length bone whose children all sit on its joint: refused, by name.
  for (const Eigen::Vector3d& bad : {Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(1, -1, 1),
                                     Eigen::Vector3d(1, 1, std::numeric_limits<double>::infinity()),
                                     Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 1, 1)}) {
    BodyShape shape;
    shape.scale[thigh] = bad;
    try {
      ForwardKinematics fk(s, shape);
      FAIL() << bad.transpose();
    } catch (const SkeletonError& error) {
      EXPECT_NE(std::string(error.what()).find("l_hip"), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find("finite and positive"), std::string::npos) << error.what();
    }
  }
}

// A zero-length bone can also come from the URDF (the cylinder visual that defines the length):
// refused when the skeleton is read, naming the link, before any FK runs.
TEST(StabilityFk, ZeroLengthBoneInTheUrdfIsRefusedByName) {
  std::ifstream file(std::string(DRESSED_HUMAN_SOURCE_DIR) + "/urdf/human.urdf");
  std::stringstream text;
  text << file.rdbuf();
  const std::string urdf = text.str();
  const std::string visual =
      "<origin xyz=\"0 0 0.205\" rpy=\"0 0 0\"/>\n      <geometry><cylinder radius=\"0.055\" length=\"0.41\"/>";
  const std::size_t at = urdf.find(visual, urdf.find("<link name=\"l_knee\">"));
  ASSERT_NE(at, std::string::npos) << "the l_knee visual moved: update this test";
  std::string zero = urdf;
  zero.replace(at, visual.size(),
               "<origin xyz=\"0 0 0\" rpy=\"0 0 0\"/>\n      <geometry><cylinder radius=\"0.055\" length=\"0\"/>");
  try {
    Skeleton::fromUrdf(zero);
    FAIL() << "a zero-length shank was accepted";
  } catch (const SkeletonError& error) {
    EXPECT_NE(std::string(error.what()).find("l_knee"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("bone length"), std::string::npos) << error.what();
  }
}

// The skin built on an extremely short or long thigh: a clear error or a finite, unit-normal mesh.
TEST(StabilityFk, SkinOnExtremeBoneScalesIsFiniteOrRefused) {
  const Skeleton& s = skeleton();
  const BodyDescription body =
      loadBodyDescriptionFile(std::string(DRESSED_HUMAN_SOURCE_DIR) + "/config/bodies/default.yaml", s);
  const std::size_t thigh = static_cast<std::size_t>(s.findBone("l_hip"));
  for (const Eigen::Vector3d& scale : {Eigen::Vector3d(1.0, 1.0, 1e-6), Eigen::Vector3d(1.0, 1.0, 1e3),
                                       Eigen::Vector3d(1e-6, 1e-6, 1.0), Eigen::Vector3d(1e3, 1e3, 1.0)}) {
    BodyShape shape = body.shape;
    shape.scale[thigh] = shape.scale[thigh].cwiseProduct(scale);
    try {
      Skin skin(s, body, shape);
      skin.poseAtRest();
      Tessellator tessellator;
      const TriangleMesh& mesh = tessellator.tessellateUniform(skin.patches(), skin.topology(), 4);
      for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        ASSERT_TRUE(mesh.positions[v].allFinite()) << scale.transpose();
        ASSERT_TRUE(mesh.normals[v].allFinite()) << scale.transpose();
        ASSERT_NEAR(mesh.normals[v].norm(), 1.0, 1e-5) << scale.transpose();
      }
    } catch (const std::exception& error) {
      // A refusal must say which part failed; it must not be a NaN deep in the mesh.
      const std::string what = error.what();
      EXPECT_FALSE(what.empty());
      ADD_FAILURE() << "refused scale " << scale.transpose() << ": " << what;
    }
  }
}

}  // namespace
}  // namespace dressed_human
