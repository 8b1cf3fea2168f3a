#pragma once
// Where one drawn human's bones come from, as rviz's Robot is driven by a LinkUpdater: TF
// (TfBoneSource) or the crowd message (CrowdMessageSource). The display owns the statuses; a
// source reports its problems into them under names of its own, and hands poses.

#include <array>
#include <string>

#include <ros/time.h>

#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace rviz {
class FrameManager;
}  // namespace rviz

namespace dressed_human {

class DisplayStatus;

class HumanPoseSource {
 public:
  virtual ~HumanPoseSource() = default;
  // The root and every bone in the fixed frame for the frame about to be drawn, bones placed by
  // `kinematics` (the drawn body's). False, with what is missing reported, when there is none.
  virtual bool pose(rviz::FrameManager& frames, DisplayStatus& status, const ForwardKinematics& kinematics,
                    RigidTransform& root, std::array<RigidTransform, kBoneCount>& bones) = 0;
  // When the newest data behind the last pose was stamped.
  virtual ros::Time stamp() const = 0;
  // Frame names for statuses: the root's and each bone's.
  virtual const std::string& rootFrame() const = 0;
  virtual const std::string& boneFrame(std::size_t bone) const = 0;
  // Removes every status pose() set.
  virtual void clearStatuses(DisplayStatus& status) const = 0;
};

}  // namespace dressed_human
