#include "crowd_message_source.h"

namespace dressed_human {

CrowdMessageSource::CrowdMessageSource(std::shared_ptr<const PoseTrack> track, const Skeleton& skeleton)
    : track_(std::move(track)), root_frame_(skeleton.rootFrame()) {
  for (const Bone& bone : skeleton.bones()) bone_frames_.push_back(skeleton.frameName(bone.name));
}

bool CrowdMessageSource::pose(rviz::FrameManager&, DisplayStatus&, const ForwardKinematics& kinematics,
                              RigidTransform& root, std::array<RigidTransform, kBoneCount>& bones) {
  if (track_->empty()) return false;  // a bag loop cleared it: the next message brings poses again
  const double drawn_time = ros::Time::now().toSec() - track_->renderDelay();
  track_->at(drawn_time, root, angles_);
  kinematics.compute(root, angles_, pose_);
  bones = pose_.bone_in_world;
  stamp_.fromSec(track_->newest().time);
  return true;
}

}  // namespace dressed_human
