#include "crowd_output.h"

#include <algorithm>

#include "transform_messages.h"

namespace dressed_human {

CrowdOutput::CrowdOutput(ros::NodeHandle node, bool skeleton_tf, std::string frame_prefix)
    : skeleton_tf_(skeleton_tf), frame_prefix_(std::move(frame_prefix)) {
  crowd_publisher_ = node.advertise<dressed_human::Crowd>("crowd", 10);
  tf_publisher_ = node.advertise<tf2_msgs::TFMessage>("/tf", 100);
  topic_ = crowd_publisher_.getTopic();
}

const std::vector<geometry_msgs::TransformStamped>& CrowdOutput::transformsOf(const Human& human,
                                                                              const std::string& world_frame,
                                                                              const ros::Time& stamp) {
  Named& named = named_[human.id];
  if (!named.transforms.empty() && named.world_frame == world_frame) return named.transforms;
  named.world_frame = world_frame;
  std::vector<geometry_msgs::TransformStamped> moving = movingTransforms(human.skeleton, world_frame);
  const auto prefixed = [&](geometry_msgs::TransformStamped& transform) {
    if (transform.header.frame_id != world_frame) transform.header.frame_id = frame_prefix_ + transform.header.frame_id;
    transform.child_frame_id = frame_prefix_ + transform.child_frame_id;
  };
  if (!skeleton_tf_) moving.resize(1);
  for (geometry_msgs::TransformStamped& transform : moving) prefixed(transform);
  named.transforms = std::move(moving);
  if (skeleton_tf_) {
    // Once per human (and again when its world frame changes): /tf_static is latched.
    std::vector<geometry_msgs::TransformStamped> fixed =
        fixedBoneTransforms(ForwardKinematics(human.skeleton, human.skeleton.bodyShape()), stamp);
    for (geometry_msgs::TransformStamped& transform : fixed) prefixed(transform);
    static_broadcaster_.sendTransform(fixed);
  }
  return named.transforms;
}

void CrowdOutput::publish(const ros::Time& stamp, const std::string& world_frame, const std::vector<Human>& humans) {
  // The transforms' names are laid out again only when the humans or the world frame change;
  // otherwise filled in place (strings copied per tick would cost more than the walk).
  bool same = world_frame == world_frame_ && humans.size() == ids_.size();
  for (std::size_t i = 0; same && i < humans.size(); ++i) same = humans[i].id == ids_[i];
  const std::size_t per_human = skeleton_tf_ ? 1 + kDofCount : 1;
  if (!same) {
    ids_.clear();
    transforms_.transforms.clear();
    for (const Human& human : humans) {
      ids_.push_back(human.id);
      const std::vector<geometry_msgs::TransformStamped>& named = transformsOf(human, world_frame, stamp);
      transforms_.transforms.insert(transforms_.transforms.end(), named.begin(), named.end());
    }
    for (auto it = named_.begin(); it != named_.end();) {
      it = std::find(ids_.begin(), ids_.end(), it->first) != ids_.end() ? std::next(it) : named_.erase(it);
    }
    world_frame_ = world_frame;
  }
  message_.header.stamp = stamp;
  message_.header.frame_id = world_frame;
  message_.humans.resize(humans.size());
  for (std::size_t i = 0; i < humans.size(); ++i) {
    const Human& human = humans[i];
    dressed_human::HumanState& state = message_.humans[i];
    state.id = human.id;
    state.stature = static_cast<float>(human.stature);
    copyPose(human.pose.root, state.root);
    state.joint_angles.resize(kDofCount);
    for (std::size_t d = 0; d < kDofCount; ++d) state.joint_angles[d] = static_cast<float>(human.angles[d]);
    geometry_msgs::TransformStamped* transforms = &transforms_.transforms[i * per_human];
    copyTransform(human.pose.root, transforms[0].transform);
    if (skeleton_tf_) {
      for (std::size_t d = 0; d < kDofCount; ++d)
        copyTransform(human.pose.dof_transforms[d], transforms[1 + d].transform);
    }
  }
  for (geometry_msgs::TransformStamped& transform : transforms_.transforms) transform.header.stamp = stamp;
  crowd_publisher_.publish(message_);
  if (!transforms_.transforms.empty()) tf_publisher_.publish(transforms_);
}

}  // namespace dressed_human
