#include "transform_messages.h"

#include <array>

namespace dressed_human {

namespace {

// geometry_msgs' Point and Vector3 alike.
template <typename Xyz>
void copyXyz(const Eigen::Vector3d& from, Xyz& to) {
  to.x = from.x();
  to.y = from.y();
  to.z = from.z();
}

void copyQuaternion(const Eigen::Quaterniond& from, geometry_msgs::Quaternion& to) {
  to.x = from.x();
  to.y = from.y();
  to.z = from.z();
  to.w = from.w();
}

}  // namespace

void copyTransform(const RigidTransform& from, geometry_msgs::Transform& to) {
  copyXyz(from.translation, to.translation);
  copyQuaternion(from.rotation, to.rotation);
}

void copyPose(const RigidTransform& from, geometry_msgs::Pose& to) {
  copyXyz(from.translation, to.position);
  copyQuaternion(from.rotation, to.orientation);
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
