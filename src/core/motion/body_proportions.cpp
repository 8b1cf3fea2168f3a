#include "dressed_human/core/motion/body_proportions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dressed_human/core/motion/capture_units.h"
#include "dressed_human/core/motion/mocap_retarget.h"
#include "dressed_human/core/motion/motion.h"
#include "dressed_human/core/skeleton/body_shape_groups.h"

namespace dressed_human {
namespace {

using namespace human_joint;  // NOLINT: the joint indices by name

std::array<Eigen::Vector3d, kBoneCount> restPositions(const Skeleton& skeleton, const BodyShape& shape) {
  const ForwardKinematics kinematics(skeleton, shape);
  SkeletonPose pose;
  kinematics.compute(RigidTransform(), JointAngles{}, pose);
  std::array<Eigen::Vector3d, kBoneCount> positions;
  for (std::size_t b = 0; b < kBoneCount; ++b) positions[b] = pose.bone_in_world[b].translation;
  return positions;
}

std::string factorText(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g", value);
  return text;
}

// The overall factor: the limbs' mean (thighs, shanks, upper arms, forearms), which capture
// skeletons agree on; the rest stature where no limb is mapped. It is every bone's a and b, and
// c of the bones no segment measured.
void applyOverallFactor(const Skeleton& skeleton, const std::array<bool, kBoneCount>& measured, double stature,
                        BodyProportions& proportions) {
  double sum = 0.0;
  int limbs = 0;
  for (const char* limb : {"l_hip", "r_hip", "l_knee", "r_knee", "l_shoulder", "r_shoulder", "l_elbow", "r_elbow"}) {
    const auto bone = static_cast<std::size_t>(skeleton.findBone(limb));
    if (!measured[bone]) continue;
    sum += proportions.shape.scale[bone].z();
    ++limbs;
  }
  proportions.overall = limbs > 0 ? sum / limbs : stature;
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    proportions.shape.scale[b].x() = proportions.overall;
    proportions.shape.scale[b].y() = proportions.overall;
    if (!measured[b]) proportions.shape.scale[b].z() = proportions.overall;
  }
}

// The capture's rest pose, read joint by joint of the map, and its factors checked against ours.
struct RestSource {
  const BvhClip& clip;
  const BvhJointMap& map;
  const Skeleton& skeleton;
  BvhPose rest;
  const std::string& source_name;

  const Eigen::Vector3d& position(int joint) const {
    return rest.position[static_cast<std::size_t>(clip.findJoint(map.joints[static_cast<std::size_t>(joint)]))];
  }
  std::size_t boneOf(int joint) const {
    return static_cast<std::size_t>(skeleton.joint(static_cast<std::size_t>(joint)).bone);
  }
  double checked(double factor, const std::string& what) const {
    if (!(factor >= kMinShapeScale && factor <= kMaxShapeScale)) {
      throw MotionError(source_name + ": " + what + " is " + factorText(factor) + " times ours, outside [" +
                        factorText(kMinShapeScale) + ", " + factorText(kMaxShapeScale) +
                        "]: a wrong unit (--units) or joint map?");
    }
    return factor;
  }
};

}  // namespace

BodyProportions fitBodyProportions(const BvhClip& clip, const BvhJointMap& map, const Skeleton& skeleton,
                                   double metres_per_unit, const std::string& source_name) {
  checkBvhJointMap(map, clip, source_name);
  const RestSource read{clip, map, skeleton, bvhRestPose(clip), source_name};
  const BvhPose& rest = read.rest;
  const auto source = [&](int joint) -> const Eigen::Vector3d& { return read.position(joint); };
  const auto boneOf = [&](int joint) { return read.boneOf(joint); };
  const auto check = [&](double factor, const std::string& what) { return read.checked(factor, what); };
  BodyProportions proportions;
  const double stature =
      check(bvhRestStature(clip) * metres_per_unit / skeletonStature(skeleton), "the rest pose's stature");

  // Lengths of the bones between two mapped joints, and of the feet (their length sets where the
  // sole meets the ground). Head and hands end in markers placed differently by every capture
  // (CMU's head segment ends mid-skull, its hand at the knuckles): they take the overall factor.
  std::array<bool, kBoneCount> measured{};
  for (int j = 0; j < static_cast<int>(kJointCount); ++j) {
    const std::string& name = map.joints[static_cast<std::size_t>(j)];
    if (name.empty()) continue;
    const std::size_t bone = boneOf(j);
    const int distal = kDistalJoint[static_cast<std::size_t>(j)];
    const bool joint_to_joint = distal >= 0 && !map.joints[static_cast<std::size_t>(distal)].empty();
    if (!joint_to_joint && j != kLeftAnkle && j != kRightAnkle) continue;
    const double source_units =
        joint_to_joint ? (source(distal) - source(j)).norm()
                       : bvhFarthestBelow(clip, rest, static_cast<std::size_t>(clip.findJoint(name))).norm();
    const std::string segment = joint_to_joint
                                    ? "the segment " + name + " to " + map.joints[static_cast<std::size_t>(distal)]
                                    : "the segment below " + name;
    if (!(source_units > 1e-9)) {
      throw MotionError(source_name + ": " + segment + " has no length at rest (zero OFFSETs): the " +
                        skeleton.bone(bone).anatomical + "'s proportion cannot be read");
    }
    const double ours =
        joint_to_joint ? skeleton.bone(boneOf(distal)).rest_translation.norm() : skeleton.bone(bone).length;
    proportions.source_length[bone] = source_units * metres_per_unit;
    proportions.shape.scale[bone].z() = check(proportions.source_length[bone] / ours, segment + "'s length");
    measured[bone] = true;
  }
  applyOverallFactor(skeleton, measured, stature, proportions);

  // The fixed bones set the widths: each one's c moves the joints it carries along its axis, so
  // the distance between the left and right joint is linear in c; two evaluations solve for it.
  const auto fitWidth = [&](int left, int right, const char* fixed_left, const char* fixed_right, const char* what) {
    if (map.joints[static_cast<std::size_t>(left)].empty() || map.joints[static_cast<std::size_t>(right)].empty())
      return;
    const double target = (source(left) - source(right)).norm() * metres_per_unit;
    const auto width = [&](double c) {
      BodyShape shape = proportions.shape;
      for (const char* bone : {fixed_left, fixed_right})
        shape.scale[static_cast<std::size_t>(skeleton.findBone(bone))].z() = c;
      const auto positions = restPositions(skeleton, shape);
      return (positions[boneOf(left)] - positions[boneOf(right)]).norm();
    };
    const double w1 = width(1.0);
    const double w2 = width(2.0);
    const double c = check(1.0 + (target - w1) / (w2 - w1), std::string("the ") + what);
    for (const char* bone : {fixed_left, fixed_right}) {
      const auto b = static_cast<std::size_t>(skeleton.findBone(bone));
      proportions.shape.scale[b].z() = c;
      proportions.source_length[b] = target;
    }
  };
  fitWidth(kLeftHip, kRightHip, "l_pelvis", "r_pelvis", "hip width");
  fitWidth(kLeftShoulder, kRightShoulder, "l_clavicle", "r_clavicle", "shoulder width");

  // Where lengths cannot reach: the middle of each pair relative to the spine joint below it (the
  // waist joint for the hips, in the body frame; the torso joint for the shoulders, in the torso
  // frame as the retarget lays it onto the capture, its axis turned onto the capture's segment).
  // The pair's fixed bones move by the difference (BodyShape::offset); the width stays.
  const Eigen::Matrix3d to_ours = bvhToOurAxes(clip, rest, map, source_name);
  const auto placePair = [&](int left, int right, int anchor, int anchor_distal, bool turn_with_anchor,
                             const char* fixed_left, const char* fixed_right, const char* what) {
    for (const int joint : {left, right, anchor}) {
      if (map.joints[static_cast<std::size_t>(joint)].empty()) return;
    }
    if (turn_with_anchor && map.joints[static_cast<std::size_t>(anchor_distal)].empty()) return;
    const ForwardKinematics kinematics(skeleton, proportions.shape);
    SkeletonPose pose;
    kinematics.compute(RigidTransform(), JointAngles{}, pose);
    const auto at = [&](int joint) -> const RigidTransform& { return pose.bone_in_world[boneOf(joint)]; };
    const Eigen::Matrix3d frame =
        turn_with_anchor ? at(anchor).rotation.toRotationMatrix() : Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d laid =
        turn_with_anchor
            ? Eigen::Quaterniond::FromTwoVectors(frame.col(2), to_ours * (source(anchor_distal) - source(anchor)))
                      .toRotationMatrix() *
                  frame
            : frame;
    const Eigen::Vector3d target =
        metres_per_unit * (laid.transpose() * (to_ours * (0.5 * (source(left) + source(right)) - source(anchor))));
    const Eigen::Vector3d ours =
        frame.transpose() * (0.5 * (at(left).translation + at(right).translation) - at(anchor).translation);
    // In the frame of both fixed bones' parent: the anchor's when turned with it, else from the body frame.
    const int parent = skeleton.bone(static_cast<std::size_t>(skeleton.findBone(fixed_left))).parent;
    Eigen::Matrix3d to_parent = Eigen::Matrix3d::Identity();
    if (!turn_with_anchor && parent >= 0)
      to_parent = pose.bone_in_world[static_cast<std::size_t>(parent)].rotation.toRotationMatrix().transpose();
    const Eigen::Vector3d shift = to_parent * (target - ours);
    if (shift.cwiseAbs().maxCoeff() > kMaxShapeOffset) {
      throw MotionError(source_name + ": the " + what + " lie " + factorText(shift.norm()) +
                        " m from ours: a wrong joint map?");
    }
    for (const char* bone : {fixed_left, fixed_right})
      proportions.shape.offset[static_cast<std::size_t>(skeleton.findBone(bone))] += shift;
  };
  placePair(kLeftHip, kRightHip, kWaist, kTorso, false, "l_pelvis", "r_pelvis", "hip joints");
  // A source whose chest is one rigid piece from the low back up (OpenSim's torso) has no chest
  // joint: the shoulders are placed relative to the waist joint, in the body frame.
  const bool chest = !map.joints[kTorso].empty();
  placePair(kLeftShoulder, kRightShoulder, chest ? kTorso : kWaist, chest ? kNeck : kTorso, chest, "l_clavicle",
            "r_clavicle", "shoulder joints");
  return proportions;
}

}  // namespace dressed_human
