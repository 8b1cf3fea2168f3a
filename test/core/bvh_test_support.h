#pragma once
// A BVH file written from our own skeleton, for the retargeting tests: joints at our proximal
// joints (clavicles and hip bones folded into their parents), CMU names, BVH's Y-up axes, a
// rotation order unlike ours, frames from the given poses; optionally a body shape and a unit.

#include <array>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace dressed_human {

constexpr double kBvhTestPi = 3.14159265358979323846;

// Our axes (x forward, y left, z up) -> BVH axes (x left, y up, z forward).
inline Eigen::Matrix3d bvhFromOurs() {
  Eigen::Matrix3d m;
  m << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  return m;
}

inline const std::array<const char*, kBoneCount> kCmuNameOfBone = {
    "LowerBack", "Spine",    "Neck1",    "Head",         "",          "LeftArm",  "LeftForeArm",
    "LeftHand",  "",         "RightArm", "RightForeArm", "RightHand", "",         "LeftUpLeg",
    "LeftLeg",   "LeftFoot", "",         "RightUpLeg",   "RightLeg",  "RightFoot"};

// A BVH of our skeleton: joints at our proximal joints (clavicles and hip bones folded into their
// parents), channels "Yrotation Zrotation Xrotation", frames from the given poses.
inline std::string bvhOfOurSkeleton(const Skeleton& skeleton,
                                    const std::vector<std::pair<RigidTransform, JointAngles>>& poses,
                                    const BodyShape& shape = BodyShape(), double units_per_metre = 1.0) {
  const ForwardKinematics kinematics(skeleton, shape);
  SkeletonPose rest;
  kinematics.compute(RigidTransform(), JointAngles{}, rest);
  const Eigen::Matrix3d m = bvhFromOurs();
  // BVH joint of every bone: the bone itself, or for a fixed bone its nearest articulated ancestor.
  std::vector<int> bvh_parent_bone(kBoneCount, -1);
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    int parent = skeleton.bone(b).parent;
    while (parent >= 0 && std::string(kCmuNameOfBone[static_cast<std::size_t>(parent)]).empty()) {
      parent = skeleton.bone(static_cast<std::size_t>(parent)).parent;
    }
    bvh_parent_bone[b] = parent;
  }
  std::ostringstream text;
  text.precision(17);
  text << "HIERARCHY\nROOT Hips\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Yrotation Zrotation "
          "Xrotation\n";
  // Writes the subtree of BVH joints under `parent_bone` (-1: the root).
  std::function<void(int)> write = [&](int parent_bone) {
    const Eigen::Vector3d parent_position = parent_bone < 0
                                                ? Eigen::Vector3d::Zero()
                                                : rest.bone_in_world[static_cast<std::size_t>(parent_bone)].translation;
    bool any_child = false;
    for (std::size_t b = 0; b < kBoneCount; ++b) {
      if (std::string(kCmuNameOfBone[b]).empty() || bvh_parent_bone[b] != parent_bone) continue;
      any_child = true;
      const Eigen::Vector3d offset = units_per_metre * (m * (rest.bone_in_world[b].translation - parent_position));
      text << "JOINT " << kCmuNameOfBone[b] << "\n{\nOFFSET " << offset.transpose()
           << "\nCHANNELS 3 Yrotation Zrotation Xrotation\n";
      write(static_cast<int>(b));
      text << "}\n";
    }
    if (!any_child && parent_bone >= 0) {
      const auto& bone = rest.bone_in_world[static_cast<std::size_t>(parent_bone)];
      const auto end_bone = static_cast<std::size_t>(parent_bone);
      const Eigen::Vector3d end =
          units_per_metre *
          (m * (bone.rotation * Eigen::Vector3d(0, 0, shape.scale[end_bone].z() * skeleton.bone(end_bone).length)));
      text << "End Site\n{\nOFFSET " << end.transpose() << "\n}\n";
    }
  };
  write(-1);
  text << "}\nMOTION\nFrames: " << poses.size() << "\nFrame Time: 0.01\n";
  // Channel values: the BVH global rotation of a joint is m W R0^T m^T (W: our bone's world
  // rotation, R0: at rest); its local rotation relative to the BVH parent, as Ry Rz Rx.
  const auto euler = [](const Eigen::Matrix3d& r) -> Eigen::Vector3d {
    return r.eulerAngles(1, 2, 0) * 180.0 / kBvhTestPi;
  };
  for (const auto& [root, angles] : poses) {
    SkeletonPose pose;
    kinematics.compute(root, angles, pose);
    const auto global = [&](int bone) -> Eigen::Matrix3d {
      const Eigen::Matrix3d w = bone < 0
                                    ? pose.root.rotation.toRotationMatrix()
                                    : pose.bone_in_world[static_cast<std::size_t>(bone)].rotation.toRotationMatrix();
      const Eigen::Matrix3d r0 = bone < 0
                                     ? Eigen::Matrix3d::Identity()
                                     : rest.bone_in_world[static_cast<std::size_t>(bone)].rotation.toRotationMatrix();
      return m * w * r0.transpose() * m.transpose();
    };
    text << (units_per_metre * (m * root.translation)).transpose() << ' ' << euler(global(-1)).transpose();
    std::function<void(int)> frame = [&](int parent_bone) {
      for (std::size_t b = 0; b < kBoneCount; ++b) {
        if (std::string(kCmuNameOfBone[b]).empty() || bvh_parent_bone[b] != parent_bone) continue;
        text << ' ' << euler(global(parent_bone).transpose() * global(static_cast<int>(b))).transpose();
        frame(static_cast<int>(b));
      }
    };
    frame(-1);
    text << '\n';
  }
  return text.str();
}

}  // namespace dressed_human
