#include "dressed_human/core/motion/carried_joints.h"

#include <Eigen/SVD>

#include "dressed_human/core/motion/motion.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace dressed_human {
namespace {

// The rotation Q that best takes the `rest` vectors onto the `now` ones (least squares, Wahba's
// problem, by the SVD; a proper rotation).
Eigen::Matrix3d bestRotation(const std::vector<Eigen::Vector3d>& rest, const std::vector<Eigen::Vector3d>& now) {
  Eigen::Matrix3d correlation = Eigen::Matrix3d::Zero();
  for (std::size_t k = 0; k < rest.size(); ++k) correlation += now[k] * rest[k].transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(correlation, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d sign = Eigen::Matrix3d::Identity();
  sign(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return svd.matrixU() * sign * svd.matrixV().transpose();
}

// Our joints whose bone hangs (through fixed bones) from joint `j`'s bone.
std::vector<std::size_t> childJoints(const Skeleton& skeleton, std::size_t j) {
  std::vector<std::size_t> children;
  const int bone = skeleton.joint(j).bone;
  for (std::size_t k = 0; k < kJointCount; ++k) {
    int parent = skeleton.bone(static_cast<std::size_t>(skeleton.joint(k).bone)).parent;
    while (parent >= 0 && parent != bone && skeleton.bone(static_cast<std::size_t>(parent)).joint < 0) {
      parent = skeleton.bone(static_cast<std::size_t>(parent)).parent;
    }
    if (parent == bone) children.push_back(k);
  }
  return children;
}

// The carried joints as the source holds them over `poses`: each frame turned onto the shape, the
// shape their mean, a few rounds (generalized Procrustes).
std::vector<Eigen::Vector3d> heldPosture(const CarriedJoints& carried, const std::vector<BvhPose>& poses,
                                         std::size_t segment_source, const Eigen::Matrix3d& to_ours) {
  constexpr int kRounds = 4;  // the shape moves < 1e-4 of its size after the third on CMU walks
  CarriedJoints held = carried;
  std::vector<Eigen::Vector3d> now;
  for (int round = 0; round < kRounds; ++round) {
    std::vector<Eigen::Vector3d> sum(held.at_rest.size(), Eigen::Vector3d::Zero());
    for (const BvhPose& pose : poses) {
      const Eigen::Matrix3d back = carriedRotation(held, pose, segment_source, to_ours, now).transpose();
      for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += back * now[i];
    }
    for (std::size_t i = 0; i < sum.size(); ++i) held.at_rest[i] = sum[i] / static_cast<double>(poses.size());
  }
  return held.at_rest;
}

}  // namespace

CarriedJoints carriedJoints(const BvhClip& clip, const BvhPose& source_rest, const BvhJointMap& map,
                            const Skeleton& skeleton, std::size_t joint, std::size_t segment_source,
                            const Eigen::Matrix3d& to_ours) {
  std::vector<std::size_t> ends;
  std::vector<std::size_t> end_joints;
  bool through_others = false;
  for (const std::size_t k : childJoints(skeleton, joint)) {
    if (map.joints[k].empty()) continue;
    end_joints.push_back(k);
    ends.push_back(static_cast<std::size_t>(clip.findJoint(map.joints[k])));
    through_others = through_others || clip.joints[ends.back()].parent != static_cast<int>(segment_source);
  }
  CarriedJoints carried;
  if (ends.size() < 2 || !through_others) return carried;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const Eigen::Vector3d at_rest =
        to_ours * (source_rest.position[ends[i]] - source_rest.position[segment_source]);
    if (at_rest.norm() < 1e-9) continue;
    carried.joints.push_back(end_joints[i]);
    carried.source.push_back(ends[i]);
    carried.at_rest.push_back(at_rest);
  }
  if (carried.source.size() < 2) carried = CarriedJoints();
  return carried;
}

Eigen::Matrix3d carriedRotation(const CarriedJoints& carried, const BvhPose& pose, std::size_t segment_source,
                                const Eigen::Matrix3d& to_ours, std::vector<Eigen::Vector3d>& scratch) {
  scratch.clear();
  for (const std::size_t end : carried.source) {
    scratch.push_back(to_ours * (pose.position[end] - pose.position[segment_source]));
  }
  return bestRotation(carried.at_rest, scratch);
}

void holdPostures(const std::vector<BvhPose>& poses, const std::array<std::size_t, kJointCount>& source_joint,
                  const Eigen::Matrix3d& to_ours, const std::array<Eigen::Matrix3d, kJointCount>& rest_offset,
                  std::array<CarriedJoints, kJointCount>& carried,
                  std::array<std::optional<Eigen::Vector3d>, kJointCount>& held_joints) {
  if (poses.empty()) return;
  for (std::size_t j = 0; j < kJointCount; ++j) {
    if (carried[j].source.empty()) continue;
    carried[j].at_rest = heldPosture(carried[j], poses, source_joint[j], to_ours);
    for (std::size_t i = 0; i < carried[j].joints.size(); ++i) {
      held_joints[carried[j].joints[i]] = Eigen::Vector3d(rest_offset[j].transpose() * carried[j].at_rest[i]);
    }
  }
}

void holdCarriedJoints(const Skeleton& skeleton, double metres,
                       const std::array<std::optional<Eigen::Vector3d>, kJointCount>& held_joints,
                       const std::string& source_name, BodyShape& shape) {
  // Each joint's place now from our rest pose with the fitted shape, not from the source's rest:
  // the shape places a pair by its middle and width, so each joint of a pair may lie apart from it.
  const ForwardKinematics kinematics(skeleton, shape);
  SkeletonPose rest;
  kinematics.compute(RigidTransform(), JointAngles{}, rest);
  for (std::size_t k = 0; k < kJointCount; ++k) {
    if (!held_joints[k]) continue;
    int bone = skeleton.joint(k).bone;
    int parent = skeleton.bone(static_cast<std::size_t>(bone)).parent;
    while (parent >= 0 && skeleton.bone(static_cast<std::size_t>(parent)).joint < 0) {
      bone = parent;
      parent = skeleton.bone(static_cast<std::size_t>(bone)).parent;
    }
    if (parent < 0) continue;
    const RigidTransform& carrying = rest.bone_in_world[static_cast<std::size_t>(parent)];
    const Eigen::Vector3d ours =
        carrying.rotation.conjugate() *
        (rest.bone_in_world[static_cast<std::size_t>(skeleton.joint(k).bone)].translation - carrying.translation);
    const Eigen::Vector3d shift = metres * *held_joints[k] - ours;
    Eigen::Vector3d& offset = shape.offset[static_cast<std::size_t>(bone)];
    if (!(offset + shift).allFinite() || (offset + shift).cwiseAbs().maxCoeff() > kMaxShapeOffset) {
      throw MotionError(source_name + ": the capture holds the joint it maps to our " + skeleton.joint(k).name + " " +
                        std::to_string(shift.norm()) + " m from where our rest pose has it: a wrong joint map?");
    }
    offset += shift;
  }
}

}  // namespace dressed_human
