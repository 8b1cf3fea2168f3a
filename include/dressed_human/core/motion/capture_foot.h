#pragma once
// A captured foot turned into our drawn foot (issue 39): the capture's foot is flat on the floor
// where its ankle stands still, and ours is aimed and rolled so that it stands flat there too and
// rolls off its toe when the capture's does. Used by the BVH retarget (mocap_retarget.h).

#include <cstddef>
#include <functional>
#include <vector>

#include <Eigen/Geometry>

#include "dressed_human/core/motion/bvh_file.h"
#include "dressed_human/core/skeleton/foot_sole.h"

namespace dressed_human {

// The capture's foot: the farthest point its bone points at (the toe tip), and its flat stance.
struct ToeTip {
  BvhPoint point;
  double rest_length = 0.0;  // from the ankle, in the rest pose
  double flat_height = 0.0;  // of the tip below the ankle over the rest length, the sole flat (negative: lower)
  double flat_roll = 0.0;    // rad about our foot bone's axis that levels our sole, side to side, there
};

// The tip's height over the ankle along our up, over the rest length.
double tipHeight(const BvhClip& clip, const BvhPose& pose, const ToeTip& tip, std::size_t ankle,
                 const Eigen::Matrix3d& to_ours);

// The frames where the ankle moves least: the stillest tenth (at least one).
std::vector<std::size_t> stillestFrames(const std::vector<BvhPose>& poses, std::size_t ankle,
                                        const Eigen::Matrix3d& to_ours);

// The capture's foot is flat on the floor when its ankle stands still (between heel strike and
// heel-off, when the heel has landed and not yet risen): the tip's height then, the median over
// the stillest frames. A rig's rest pose is no measure of it: CMU's stands with the ankle-to-tip
// line 9.4 and 11.0 deg down, its walk's flat stance at 12.3 and 12.2.
double flatHeight(const BvhClip& clip, const std::vector<BvhPose>& poses, const ToeTip& tip, std::size_t ankle,
                  const Eigen::Matrix3d& to_ours);

// Our foot's tip (its last sole point: FootSoles) below and along the foot bone, and the bone's
// pitch when the sole stands flat.
struct OurFoot {
  double along = 0.0;
  double below = 0.0;
  double flat_pitch = 0.0;
  explicit OurFoot(const FootSoles& soles)
      : along(soles.inFoot(soles.pointsPerFoot() - 1).z()),
        below(soles.inFoot(soles.pointsPerFoot() - 1).x()),
        flat_pitch(soles.flatPitch()) {}
  // The tip's height under the ankle with the bone pitched `pitch` (toes up positive).
  double tipHeight(double pitch) const { return along * std::sin(pitch) - below * std::cos(pitch); }
};

// Where a rigid foot points: its heading is the capture's ankle-to-tip line's, and its pitch puts
// its tip as far above or below where it is when our sole stands flat as the capture's tip is
// above or below its own flat stance (flatHeight), in metres of our leg (`scale`: our ankle rises
// over the floor as the capture's does). So our foot stands flat where the capture's does (aimed
// along the line itself, every stance rode on the toes with the heel 4 cm up, as the capture's
// ankle sits higher above its toe tip than ours above our sole), and at push-off, where the
// capture's toes bend and ours cannot, the tip sinks as far as the capture's does and leaves the
// ground when it does: turned by the line's angle, our rigid toes dug in and lifted the body; in
// foot lengths, our shorter foot's toe rose early.
Eigen::Vector3d footAim(const BvhClip& clip, const BvhPose& pose, const ToeTip& toe_tip, std::size_t ankle,
                        const Eigen::Matrix3d& to_ours, const OurFoot& foot, double scale);

// Our foot bone's world rotation `foot` (as the capture's foot joint turns it) pointed along `aim`
// (footAim) and turned about its own axis by `roll`.
Eigen::Matrix3d aimedFoot(const Eigen::Matrix3d& foot, const Eigen::Vector3d& aim, double roll);

// Rolled about its own axis as the capture's foot joint is, our sole stood on its edge where the
// capture's foot stands flat (CMU 02_01: 20 deg; the drawn foot's side 5 mm below the floor): the
// roll about the foot's axis that levels it there, side to side: the median over the stillest
// frames of `ankle` of our foot as `aimed_foot` turns it (unrolled). The capture's roll elsewhere is
// kept about it.
double flatRoll(const std::vector<BvhPose>& poses, std::size_t ankle, const Eigen::Matrix3d& to_ours,
                const std::function<Eigen::Matrix3d(const BvhPose&)>& aimed_foot);

}  // namespace dressed_human
