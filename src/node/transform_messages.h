#pragma once
// The core's rigid transforms as the geometry_msgs both nodes publish.

#include <string>
#include <vector>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/time.h>

#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace dressed_human {

void copyTransform(const RigidTransform& from, geometry_msgs::Transform& to);
void copyPose(const RigidTransform& from, geometry_msgs::Pose& to);
// A transform from `parent` to `child`, identity until filled.
geometry_msgs::TransformStamped namedTransform(const std::string& parent, const std::string& child);

// The transforms a skeleton puts on /tf, named (`extra_suffix` appended to every frame): the root
// in `world_frame`, then per DOF in angle order its parent and child link (SkeletonPose's
// dof_transforms fill them in that order).
std::vector<geometry_msgs::TransformStamped> movingTransforms(const Skeleton& skeleton, const std::string& world_frame,
                                                              const std::string& extra_suffix = "");
// The fixed bones (clavicles, hip bones) where `kinematics` puts them, for /tf_static.
std::vector<geometry_msgs::TransformStamped> fixedBoneTransforms(const ForwardKinematics& kinematics,
                                                                 const ros::Time& stamp,
                                                                 const std::string& extra_suffix = "");

}  // namespace dressed_human
