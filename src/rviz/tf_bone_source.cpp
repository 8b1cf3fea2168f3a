#include "tf_bone_source.h"

#include "dressed_human/core/skeleton/forward_kinematics.h"

#include <algorithm>

#include <rviz/frame_manager.h>
#include <tf2_ros/buffer.h>

#include "display_status.h"

namespace dressed_human {
namespace {

// A frame this much older than the root's is no longer published: left out of the common stamp.
// The newest skeleton transform this much older than now is reported as stale.
constexpr double kStaleSeconds = 1.0;

RigidTransform toRigid(const geometry_msgs::Transform& t) {
  RigidTransform rigid;
  rigid.translation = {t.translation.x, t.translation.y, t.translation.z};
  rigid.rotation = Eigen::Quaterniond(t.rotation.w, t.rotation.x, t.rotation.y, t.rotation.z).normalized();
  return rigid;
}

}  // namespace

TfBoneSource::TfBoneSource(const Skeleton& skeleton, const std::string& label)
    : skeleton_(skeleton), stale_status_name_(label.empty() ? "TF" : "TF " + label) {
  for (const Bone& bone : skeleton_.bones()) {
    bone_frames_.push_back(skeleton_.frameName(bone.name));
    bone_status_names_.push_back("Frame " + bone_frames_.back());
  }
  root_frame_ = skeleton_.rootFrame();
  root_status_name_ = "Frame " + root_frame_;
  // A bone on a fixed URDF joint (clavicles, pelvis halves) sits where the URDF puts it, its own
  // body shape included: no lookup needed, and none that could fail.
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    if (skeleton_.bone(b).joint < 0) bone_in_parent_[b] = fixedBoneAsInUrdf(skeleton_, b);
  }
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    bool has_child = false;
    for (const Bone& other : skeleton_.bones()) has_child = has_child || other.parent == static_cast<int>(b);
    if (!has_child) leaf_bones_.push_back(static_cast<int>(b));
  }
}

bool TfBoneSource::lookUp(rviz::FrameManager& frames, DisplayStatus& status) {
  const std::shared_ptr<tf2_ros::Buffer> buffer = frames.getTF2BufferPtr();
  const std::string& fixed = frames.getFixedFrame();
  const std::string& root = root_frame_;
  // One consistent time for every bone, so that garments spanning two bones never tear. Almost
  // always every bone is known at the root's newest stamp (one message carries the skeleton):
  // a lookup at time zero gives that stamp (tf2's latest common time) with the root's pose.
  // But TF inserts a message's transforms one by one while rviz reads, so a bone can lag its
  // root by one tick: then a lookup at that stamp fails, and all bones are looked up again at
  // the newest time every chain from the fixed frame to a leaf bone (head, hands, feet) is
  // known. Walking every chain each frame instead would cost more than the lookups themselves.
  ros::Time stamp;
  bool found = false;
  try {
    const geometry_msgs::TransformStamped newest = buffer->lookupTransform(fixed, root, ros::Time(0));
    stamp = newest.header.stamp;
    root_ = toRigid(newest.transform);
    found = lookUpAt(*buffer, stamp, false, status);
    if (!found) {
      stamp = leafStamp(*buffer, fixed, stamp);
      root_ = toRigid(buffer->lookupTransform(fixed, root, stamp).transform);
    }
    status.clear(root_status_name_);
  } catch (const tf2::TransformException& error) {
    status.error(root_status_name_, error.what(), true);
    return false;
  }
  const double age = (ros::Time::now() - stamp).toSec();
  if (!stamp.isZero() && age > kStaleSeconds) {
    status.warn(stale_status_name_, "the newest skeleton transform is " + std::to_string(age) + " s old");
  } else {
    status.clear(stale_status_name_);
  }
  stamp_ = stamp;
  return found || lookUpAt(*buffer, stamp, true, status);
}

bool TfBoneSource::pose(rviz::FrameManager& frames, DisplayStatus& status, const ForwardKinematics& kinematics,
                        RigidTransform& root, std::array<RigidTransform, kBoneCount>& bones) {
  if (!lookUp(frames, status)) return false;
  // Eq. 5: TF carries the URDF's offsets (its own body shape in them); the drawn body's on top.
  kinematics.composeFromTf(root_, bone_in_parent_, bones);
  root = root_;
  return true;
}

void TfBoneSource::clearStatuses(DisplayStatus& status) const {
  status.clear(root_status_name_);
  status.clear(stale_status_name_);
  for (const std::string& name : bone_status_names_) status.clear(name);
}

ros::Time TfBoneSource::leafStamp(const tf2_ros::Buffer& buffer, const std::string& fixed,
                                  const ros::Time& root_stamp) const {
  // A chain that is missing, or lags the root by more than the stale limit (a link no longer
  // published), is left out: holding every bone back to it would freeze the human without
  // naming the culprit. Its bone's lookup then fails and reports the frame.
  ros::Time stamp = root_stamp;
  for (const int leaf : leaf_bones_) {
    try {
      const ros::Time newest =
          buffer.lookupTransform(fixed, bone_frames_[static_cast<std::size_t>(leaf)], ros::Time(0)).header.stamp;
      if ((root_stamp - newest).toSec() <= kStaleSeconds) stamp = std::min(stamp, newest);
    } catch (const tf2::TransformException&) {
    }
  }
  return stamp;
}

bool TfBoneSource::lookUpAt(const tf2_ros::Buffer& buffer, const ros::Time& stamp, bool report, DisplayStatus& status) {
  bool all_found = true;
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    // Each bone relative to its parent (bones come parents first): tf2 then walks the three
    // links of one joint instead of the whole chain from the fixed frame every time.
    const Bone& bone = skeleton_.bone(b);
    const std::string& parent_frame =
        bone.parent < 0 ? root_frame_ : bone_frames_[static_cast<std::size_t>(bone.parent)];
    if (bone.joint < 0) continue;  // fixed: set once, where the URDF puts it
    try {
      bone_in_parent_[b] = toRigid(buffer.lookupTransform(parent_frame, bone_frames_[b], stamp).transform);
      status.clear(bone_status_names_[b]);
    } catch (const tf2::TransformException& error) {
      if (!report) return false;
      status.error(bone_status_names_[b], error.what(), true);
      all_found = false;
    }
  }
  return all_found;
}

}  // namespace dressed_human
