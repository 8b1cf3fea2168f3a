#include "dressed_human/core/locomotion/leg_ik.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dressed_human {

LegIk::LegIk(const ForwardKinematics& kinematics) : kinematics_(kinematics) {
  const Skeleton& skeleton = kinematics.skeleton();
  const std::array<std::array<const char*, 3>, 2> names = {
      {{"l_hip", "l_knee", "l_ankle"}, {"r_hip", "r_knee", "r_ankle"}}};
  for (std::size_t side = 0; side < 2; ++side) {
    for (std::size_t k = 0; k < 3; ++k) {
      const int bone = skeleton.findBone(names[side][k]);
      if (bone < 0 || skeleton.bone(static_cast<std::size_t>(bone)).joint < 0) {
        throw std::invalid_argument(std::string("the skeleton has no articulated bone ") + names[side][k]);
      }
      bones_[side][k] = static_cast<std::size_t>(bone);
    }
  }
}

void LegIk::setJointRotation(std::size_t bone, const Eigen::Quaterniond& wanted, JointAngles& angles,
                             const SkeletonPose& pose) const {
  const Bone& b = kinematics_.skeleton().bone(bone);
  const Eigen::Quaterniond& parent =
      b.parent < 0 ? pose.root.rotation : pose.bone_in_world[static_cast<std::size_t>(b.parent)].rotation;
  // World = parent * rest * Ry(y) Rx(x) Rz(z); solved for y, x, z with x in [-pi/2, pi/2].
  const Eigen::Matrix3d r = (b.rest_rotation.conjugate() * parent.conjugate() * wanted).toRotationMatrix();
  const std::size_t first = static_cast<std::size_t>(b.joint) * kDofsPerJoint;
  angles[first + static_cast<std::size_t>(JointAxis::kX)] = std::asin(std::clamp(-r(1, 2), -1.0, 1.0));
  angles[first + static_cast<std::size_t>(JointAxis::kY)] = std::atan2(r(0, 2), r(2, 2));
  angles[first + static_cast<std::size_t>(JointAxis::kZ)] = std::atan2(r(1, 0), r(1, 1));
}

void LegIk::shiftFoot(std::size_t side, const Eigen::Vector3d& shift, JointAngles& angles, SkeletonPose& pose) const {
  const std::size_t thigh = bones_[side][0], shank = bones_[side][1], foot = bones_[side][2];
  const Eigen::Vector3d hip = pose.bone_in_world[thigh].translation;
  const Eigen::Vector3d knee = pose.bone_in_world[shank].translation;
  const Eigen::Vector3d ankle = pose.bone_in_world[foot].translation;
  const Eigen::Quaterniond foot_rotation = pose.bone_in_world[foot].rotation;
  const Eigen::Vector3d target = ankle + shift;
  const double thigh_length = (knee - hip).norm(), shank_length = (ankle - knee).norm();
  const double reach = std::clamp((target - hip).norm(), std::abs(thigh_length - shank_length) + 1e-6,
                                  thigh_length + shank_length - 1e-6);
  // Knee: the angle between thigh and shank that spans `reach`, about the axis normal to the leg's plane.
  const Eigen::Vector3d to_hip = (hip - knee).normalized(), to_ankle = (ankle - knee).normalized();
  const Eigen::Vector3d normal = to_hip.cross(to_ankle);
  if (normal.norm() > 1e-9) {
    const double now = std::acos(std::clamp(to_hip.dot(to_ankle), -1.0, 1.0));
    const double wanted =
        std::acos(std::clamp((thigh_length * thigh_length + shank_length * shank_length - reach * reach) /
                                 (2.0 * thigh_length * shank_length),
                             -1.0, 1.0));
    const Eigen::Quaterniond open(Eigen::AngleAxisd(wanted - now, normal.normalized()));
    setJointRotation(shank, open * pose.bone_in_world[shank].rotation, angles, pose);
    kinematics_.compute(pose.root, angles, pose);
  }
  // Thigh: swing the whole leg about the hip so that the ankle lands on the target.
  const Eigen::Quaterniond swing =
      Eigen::Quaterniond::FromTwoVectors(pose.bone_in_world[foot].translation - hip, target - hip);
  setJointRotation(thigh, swing * pose.bone_in_world[thigh].rotation, angles, pose);
  kinematics_.compute(pose.root, angles, pose);
  // Ankle: the foot as it was.
  setJointRotation(foot, foot_rotation, angles, pose);
  kinematics_.compute(pose.root, angles, pose);
}

void LegIk::turnLeg(std::size_t side, double angle, const Eigen::Vector3d& pivot, JointAngles& angles,
                    SkeletonPose& pose) const {
  const std::size_t thigh = bones_[side][0];
  const Eigen::Vector3d axis = pose.bone_in_world[thigh].translation - pivot;
  if (axis.norm() < 1e-9) return;
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(angle, axis.normalized()));
  setJointRotation(thigh, turn * pose.bone_in_world[thigh].rotation, angles, pose);
  kinematics_.compute(pose.root, angles, pose);
}

}  // namespace dressed_human
