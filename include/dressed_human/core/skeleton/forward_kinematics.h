#pragma once
// Forward kinematics: 48 joint angles + the root pose -> every frame of the skeleton.

#include <array>

#include <Eigen/Geometry>

#include "dressed_human/core/skeleton/skeleton.h"

namespace dressed_human {

// Angle index = joint * 3 + dof, dof in chain order (y, x, z); radians.
using JointAngles = std::array<double, kDofCount>;

struct RigidTransform {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
};

struct SkeletonPose {
  RigidTransform root;  // body frame in the world
  // Parent -> child transform of every URDF revolute joint, as TF publishes it: for DOF 0 the
  // joint origin (scaled) times the rotation about y; for DOFs 1 and 2 a pure rotation.
  std::array<RigidTransform, kDofCount> dof_transforms;
  std::array<RigidTransform, kBoneCount> bone_in_parent;  // bone frame in its parent bone (or body)
  std::array<RigidTransform, kBoneCount> bone_in_world;
};

// Where a bone's frame sits in its parent with `shape` applied (Eq. 5): the rest offset scaled by
// the parent's factors, moved by the bone's own offset.
Eigen::Vector3d shapedRestTranslation(const Skeleton& skeleton, const BodyShape& shape, std::size_t bone);

// A fixed bone's frame (clavicles, hip bones) in its parent as the URDF, and so TF, carries it:
// with the URDF's own body shape (Skeleton::bodyShape()), which the skeleton's rest offsets lack.
RigidTransform fixedBoneAsInUrdf(const Skeleton& skeleton, std::size_t bone);

class ForwardKinematics {
 public:
  explicit ForwardKinematics(const Skeleton& skeleton, const BodyShape& shape = BodyShape());

  // Allocation-free; `pose` is filled completely.
  void compute(const RigidTransform& root, const JointAngles& angles, SkeletonPose& pose) const;
  // Every bone frame in the world from `root` and each bone's frame in its parent as TF carries
  // it: the URDF's offsets, which hold the URDF's own body shape (Skeleton::bodyShape()). This
  // shape's factors beyond that one move each joint along its parent's axes, as compute() does;
  // the rotations stay as they are. Allocation-free.
  void composeFromTf(const RigidTransform& root, const std::array<RigidTransform, kBoneCount>& tf_in_parent,
                     std::array<RigidTransform, kBoneCount>& bone_in_world) const;

  // Where a bone frame sits in its parent, shape applied (also the fixed joints' TF).
  const Eigen::Vector3d& scaledRestTranslation(std::size_t bone) const { return scaled_rest_translation_[bone]; }
  const Skeleton& skeleton() const { return skeleton_; }
  const BodyShape& shape() const { return shape_; }

 private:
  Skeleton skeleton_;
  BodyShape shape_;
  std::array<Eigen::Vector3d, kBoneCount> scaled_rest_translation_;
  std::array<Eigen::Vector3d, kBoneCount> tf_offset_scale_;  // this shape / the URDF's, of the parent
  std::array<Eigen::Vector3d, kBoneCount> tf_offset_shift_;  // this shape's offset less the URDF's, scaled
};

}  // namespace dressed_human
