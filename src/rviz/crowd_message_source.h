#pragma once
// A crowd human's bones from the crowd message (CrowdTopic keeps its recent poses): the joint
// angles through the core's forward kinematics, at the time being drawn less the track's render
// delay, so that poses arriving at 30 Hz move smoothly at rviz's frame rate.

#include <memory>
#include <string>
#include <vector>

#include "dressed_human/core/skeleton/pose_track.h"
#include "human_pose_source.h"

namespace dressed_human {

class CrowdMessageSource : public HumanPoseSource {
 public:
  // `skeleton`: the drawn human's, its frames named with the human's suffix.
  CrowdMessageSource(std::shared_ptr<const PoseTrack> track, const Skeleton& skeleton);

  bool pose(rviz::FrameManager& frames, DisplayStatus& status, const ForwardKinematics& kinematics,
            RigidTransform& root, std::array<RigidTransform, kBoneCount>& bones) override;
  ros::Time stamp() const override { return stamp_; }
  const std::string& rootFrame() const override { return root_frame_; }
  const std::string& boneFrame(std::size_t bone) const override { return bone_frames_[bone]; }
  void clearStatuses(DisplayStatus&) const override {}  // the topic's statuses are the display's

 private:
  std::shared_ptr<const PoseTrack> track_;
  std::string root_frame_;
  std::vector<std::string> bone_frames_;
  JointAngles angles_{};
  SkeletonPose pose_;
  ros::Time stamp_;
};

}  // namespace dressed_human
