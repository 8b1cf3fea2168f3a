#include "dressed_human/core/skeleton/forward_kinematics.h"

#include <cmath>
#include <string>

namespace dressed_human {
namespace {

// Rotation about one axis from the half angle; the only trigonometry in FK.
Eigen::Quaterniond axisRotation(double angle, int axis) {
  double s = 0.0;
  double c = 0.0;
  ::sincos(0.5 * angle, &s, &c);
  Eigen::Quaterniond q(c, 0.0, 0.0, 0.0);
  q.coeffs()[axis] = s;  // coeffs() is (x, y, z, w)
  return q;
}

constexpr std::array<int, kDofsPerJoint> kChainAxis = {1, 0, 2};  // y, x, z as Eigen coefficient index

// A bone frame in the world from its parent's and its own in the parent (shape applied).
void attach(const RigidTransform& parent, const Eigen::Vector3d& translation, const Eigen::Quaterniond& rotation,
            RigidTransform& world) {
  world.translation = parent.translation + parent.rotation * translation;
  world.rotation = parent.rotation * rotation;
}

}  // namespace

Eigen::Vector3d shapedRestTranslation(const Skeleton& skeleton, const BodyShape& shape, std::size_t bone) {
  const Bone& b = skeleton.bone(bone);
  const Eigen::Vector3d parent_scale =
      b.parent < 0 ? Eigen::Vector3d(Eigen::Vector3d::Ones()) : shape.scale[static_cast<std::size_t>(b.parent)];
  return parent_scale.cwiseProduct(b.rest_translation) + shape.offset[bone];
}

RigidTransform fixedBoneAsInUrdf(const Skeleton& skeleton, std::size_t bone) {
  return {shapedRestTranslation(skeleton, skeleton.bodyShape(), bone), skeleton.bone(bone).rest_rotation};
}

ForwardKinematics::ForwardKinematics(const Skeleton& skeleton, const BodyShape& shape)
    : skeleton_(skeleton), shape_(shape) {
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    const Eigen::Vector3d& scale = shape_.scale[b];
    if (!scale.allFinite() || (scale.array() <= 0.0).any()) {
      throw SkeletonError("body shape of bone '" + skeleton_.bone(b).name +
                          "': the scale factors a, b, c must be finite and positive");
    }
    if (!shape_.offset[b].allFinite() || shape_.offset[b].cwiseAbs().maxCoeff() > kMaxShapeOffset) {
      throw SkeletonError("body shape of bone '" + skeleton_.bone(b).name + "': the offset must be finite and within " +
                          std::to_string(kMaxShapeOffset) + " m");
    }
  }
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    const Bone& bone = skeleton_.bone(b);
    const Eigen::Vector3d parent_scale =
        bone.parent < 0 ? Eigen::Vector3d::Ones() : shape_.scale[static_cast<std::size_t>(bone.parent)];
    scaled_rest_translation_[b] = shapedRestTranslation(skeleton_, shape_, b);
    tf_offset_scale_[b] = bone.parent < 0 ? Eigen::Vector3d(Eigen::Vector3d::Ones())
                                          : Eigen::Vector3d(parent_scale.cwiseQuotient(
                                                skeleton_.bodyShape().scale[static_cast<std::size_t>(bone.parent)]));
    tf_offset_shift_[b] = shape_.offset[b] - tf_offset_scale_[b].cwiseProduct(skeleton_.bodyShape().offset[b]);
  }
}

void ForwardKinematics::compute(const RigidTransform& root, const JointAngles& angles, SkeletonPose& pose) const {
  pose.root = root;
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    const Bone& bone = skeleton_.bone(b);
    RigidTransform& local = pose.bone_in_parent[b];
    local.translation = scaled_rest_translation_[b];
    if (bone.joint >= 0) {
      const std::size_t first = static_cast<std::size_t>(bone.joint) * kDofsPerJoint;
      std::array<Eigen::Quaterniond, kDofsPerJoint> dof_rotation;
      for (std::size_t d = 0; d < kDofsPerJoint; ++d) {
        dof_rotation[d] = axisRotation(angles[first + d], kChainAxis[d]);
      }
      pose.dof_transforms[first] = {local.translation, bone.rest_rotation * dof_rotation[0]};
      pose.dof_transforms[first + 1] = {Eigen::Vector3d::Zero(), dof_rotation[1]};
      pose.dof_transforms[first + 2] = {Eigen::Vector3d::Zero(), dof_rotation[2]};
      local.rotation = pose.dof_transforms[first].rotation * dof_rotation[1] * dof_rotation[2];
    } else {
      local.rotation = bone.rest_rotation;
    }
    const RigidTransform& parent =
        bone.parent < 0 ? pose.root : pose.bone_in_world[static_cast<std::size_t>(bone.parent)];
    attach(parent, local.translation, local.rotation, pose.bone_in_world[b]);
  }
}

void ForwardKinematics::composeFromTf(const RigidTransform& root,
                                      const std::array<RigidTransform, kBoneCount>& tf_in_parent,
                                      std::array<RigidTransform, kBoneCount>& bone_in_world) const {
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    const int parent = skeleton_.bone(b).parent;
    const RigidTransform& local = tf_in_parent[b];
    attach(parent < 0 ? root : bone_in_world[static_cast<std::size_t>(parent)],
           tf_offset_scale_[b].cwiseProduct(local.translation) + tf_offset_shift_[b], local.rotation, bone_in_world[b]);
  }
}

}  // namespace dressed_human
