#pragma once
// A segment of ours that carries several joints the source reaches through joints we do not have
// (our chest: CMU's Spine1, Neck and clavicles lie between its Spine and the neck and shoulders).
// It is turned every frame to put those joints, as a whole, where the source has them; and where
// the source holds them while it moves is not where its rest pose has them (CMU 07_01 walks with
// its neck base 2.5 cm and its shoulders 1-1.5 cm from its T-pose's, a near-constant offset,
// 0.1-0.2 cm of spread over the walk, that no rotation of a rigid chest takes up). So the segment
// turns with the joints' held posture, and a fitted body puts its joints there.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dressed_human/core/motion/bvh_file.h"
#include "dressed_human/core/motion/mocap_joint_map.h"
#include "dressed_human/core/skeleton/skeleton.h"

namespace dressed_human {

struct CarriedJoints {
  std::vector<std::size_t> joints;       // ours
  std::vector<std::size_t> source;       // the source joints
  std::vector<Eigen::Vector3d> at_rest;  // from the segment's source joint, our axes, source units:
                                         // at rest, or as held (holdPostures)
};

// The joints our `joint`'s segment carries through joints we lack, with the source's rest pose;
// empty where it carries fewer than two or the source reaches them directly.
CarriedJoints carriedJoints(const BvhClip& clip, const BvhPose& source_rest, const BvhJointMap& map,
                            const Skeleton& skeleton, std::size_t joint, std::size_t segment_source,
                            const Eigen::Matrix3d& to_ours);

// The segment's world rotation in `pose` that puts its carried joints where the source has them
// (least squares; their rest rotation is the identity: BVH rest poses carry no rotation).
// `scratch`: the joints now, from the segment's source joint, our axes.
Eigen::Matrix3d carriedRotation(const CarriedJoints& carried, const BvhPose& pose, std::size_t segment_source,
                                const Eigen::Matrix3d& to_ours, std::vector<Eigen::Vector3d>& scratch);

// Every non-empty `carried[j]` turned to its held posture over `poses` (generalized Procrustes);
// `held_joints[k]` of each carried joint k: where it is held, in segment j's frame (`rest_offset[j]`,
// its rest rotation laid onto the source), from j, source units.
void holdPostures(const std::vector<BvhPose>& poses, const std::array<std::size_t, kJointCount>& source_joint,
                  const Eigen::Matrix3d& to_ours, const std::array<Eigen::Matrix3d, kJointCount>& rest_offset,
                  std::array<CarriedJoints, kJointCount>& carried,
                  std::array<std::optional<Eigen::Vector3d>, kJointCount>& held_joints);

// Moves each held joint of `shape` (a body fitted to the source) to `held_joints` (metres per
// source unit `metres`): through the offset of the topmost bone between it and its carrying
// segment (a clavicle for a shoulder, the neck itself for the neck), which lies in the carrying
// segment's frame. Throws MotionError (naming `source_name`) for a joint moved beyond kMaxShapeOffset.
void holdCarriedJoints(const Skeleton& skeleton, double metres,
                       const std::array<std::optional<Eigen::Vector3d>, kJointCount>& held_joints,
                       const std::string& source_name, BodyShape& shape);

}  // namespace dressed_human
