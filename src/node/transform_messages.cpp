#include "transform_messages.h"

#include <array>

namespace dressed_human {

void copyTransform(const RigidTransform& from, geometry_msgs::Transform& to) {
  to.translation.x = from.translation.x();
  to.translation.y = from.translation.y();
  to.translation.z = from.translation.z();
  to.rotation.x = from.rotation.x();
  to.rotation.y = from.rotation.y();
  to.rotation.z = from.rotation.z();
  to.rotation.w = from.rotation.w();
}

void copyPose(const RigidTransform& from, geometry_msgs::Pose& to) {
  to.position.x = from.translation.x();
  to.position.y = from.translation.y();
  to.position.z = from.translation.z();
  to.orientation.x = from.rotation.x();
  to.orientation.y = from.rotation.y();
  to.orientation.z = from.rotation.z();
  to.orientation.w = from.rotation.w();
}

geometry_msgs::TransformStamped namedTransform(const std::string& parent, const std::string& child) {
  geometry_msgs::TransformStamped transform;
  transform.header.frame_id = parent;
  transform.child_frame_id = child;
  transform.transform.rotation.w = 1.0;
  return transform;
}

namespace {

std::string parentFrame(const Skeleton& skeleton, const Bone& bone) {
  return bone.parent < 0 ? skeleton.rootFrame()
                         : skeleton.frameName(skeleton.bone(static_cast<std::size_t>(bone.parent)).name);
}

}  // namespace

std::vector<geometry_msgs::TransformStamped> movingTransforms(const Skeleton& skeleton, const std::string& world_frame,
                                                              const std::string& extra_suffix) {
  std::vector<geometry_msgs::TransformStamped> transforms;
  transforms.push_back(namedTransform(world_frame, skeleton.rootFrame() + extra_suffix));
  for (const ArticulatedJoint& joint : skeleton.joints()) {
    const Bone& bone = skeleton.bone(static_cast<std::size_t>(joint.bone));
    const std::array<std::string, 4> chain = {parentFrame(skeleton, bone), joint.intermediate_links[0],
                                              joint.intermediate_links[1], skeleton.frameName(bone.name)};
    for (std::size_t d = 0; d < kDofsPerJoint; ++d) {
      transforms.push_back(namedTransform(chain[d] + extra_suffix, chain[d + 1] + extra_suffix));
    }
  }
  return transforms;
}

std::vector<geometry_msgs::TransformStamped> fixedBoneTransforms(const ForwardKinematics& kinematics,
                                                                 const ros::Time& stamp,
                                                                 const std::string& extra_suffix) {
  const Skeleton& skeleton = kinematics.skeleton();
  std::vector<geometry_msgs::TransformStamped> fixed;
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    const Bone& bone = skeleton.bone(b);
    if (bone.joint >= 0) continue;
    geometry_msgs::TransformStamped transform =
        namedTransform(parentFrame(skeleton, bone) + extra_suffix, skeleton.frameName(bone.name) + extra_suffix);
    transform.header.stamp = stamp;
    copyTransform({kinematics.scaledRestTranslation(b), bone.rest_rotation}, transform.transform);
    fixed.push_back(transform);
  }
  return fixed;
}

}  // namespace dressed_human
