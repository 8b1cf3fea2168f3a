#pragma once
// Where one human's bones are, read from TF (as rviz's TFLinkUpdater reads a robot's links):
// the skeleton's root in the fixed frame and each bone in its parent, all at one stamp, through
// rviz's FrameManager and tf2's public lookups. Missing, lagging and stale frames are reported
// as statuses naming the frame ("Frame <tf frame>", "TF").

#include <array>
#include <string>
#include <vector>

#include <ros/time.h>

#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "human_pose_source.h"

namespace rviz {
class FrameManager;
}  // namespace rviz
namespace tf2_ros {
class Buffer;
}  // namespace tf2_ros

namespace dressed_human {

class TfBoneSource : public HumanPoseSource {
 public:
  // `label` tells this human's "TF" status apart from other humans' of one display ("TF <label>").
  explicit TfBoneSource(const Skeleton& skeleton, const std::string& label = "");

  // lookUp(), then every bone in the fixed frame (ForwardKinematics::composeFromTf).
  bool pose(rviz::FrameManager& frames, DisplayStatus& status, const ForwardKinematics& kinematics,
            RigidTransform& root, std::array<RigidTransform, kBoneCount>& bones) override;
  ros::Time stamp() const override { return stamp_; }
  const std::string& rootFrame() const override { return root_frame_; }
  const std::string& boneFrame(std::size_t bone) const override { return bone_frames_[bone]; }
  void clearStatuses(DisplayStatus& status) const override;

  // Looks up the root and every bone at one stamp; false (and the failing frames reported) if
  // any is missing. Clears the statuses of frames found again.
  bool lookUp(rviz::FrameManager& frames, DisplayStatus& status);
  // From the last successful lookUp(): the root in the fixed frame, and each bone in its parent
  // as TF carries it (the URDF's offsets, its body shape in them; ForwardKinematics::composeFromTf).
  const RigidTransform& root() const { return root_; }
  const std::array<RigidTransform, kBoneCount>& bonesInParent() const { return bone_in_parent_; }

 private:
  // Every bone at `stamp`; false at the first failure, or (report) after reporting each one.
  bool lookUpAt(const tf2_ros::Buffer& buffer, const ros::Time& stamp, bool report, DisplayStatus& status);
  // The newest stamp at which every chain from the fixed frame to a leaf bone is known, no
  // earlier than `root_stamp` minus the stale limit.
  ros::Time leafStamp(const tf2_ros::Buffer& buffer, const std::string& fixed, const ros::Time& root_stamp) const;

  Skeleton skeleton_;
  std::vector<int> leaf_bones_;  // bones no other bone hangs from: the ends of the TF chains
  // Per bone its TF frame and the status reporting it, named once (every frame uses them).
  std::vector<std::string> bone_frames_;
  std::vector<std::string> bone_status_names_;
  std::string root_frame_;
  std::string root_status_name_;
  std::string stale_status_name_;  // "TF" or "TF <label>"
  RigidTransform root_;
  ros::Time stamp_;
  std::array<RigidTransform, kBoneCount> bone_in_parent_;
};

}  // namespace dressed_human
