#pragma once
// One human a DressedHuman display draws: its bones from a pose source (TF or the crowd message,
// HumanPoseSource), its surfaces (the core's HumanModel) and its Ogre objects (HumanVisual). A
// display draws one (its robot description's), every human in TF or every human of a crowd
// topic, each a DrawnHuman; what they share (properties, relief maps, the body file) stays in the
// display.

#include <array>
#include <memory>
#include <string>

#include <ros/time.h>

#include "dressed_human/core/model/human_model.h"
#include "dressed_human/core/model/relief_map_jobs.h"
#include "dressed_human/core/model/relief_visibility.h"
#include "human_visual.h"
#include "human_pose_source.h"

namespace Ogre {
class Camera;
class SceneManager;
class SceneNode;
}  // namespace Ogre
namespace rviz {
class FrameManager;
}  // namespace rviz

namespace dressed_human {

class DisplayStatus;

class DrawnHuman {
 public:
  // `skeleton` names this human's frames; `poses` says where its bones are; `label` tells its
  // statuses apart from other humans' of the display ("" for a display's only human, else its
  // root frame). Throws what HumanModel throws (a garment or body file that does not fit).
  DrawnHuman(const Skeleton& skeleton, std::unique_ptr<HumanPoseSource> poses, const BodyDescription& shaped_body,
             const HumanModelSettings& settings, Ogre::SceneManager* scene_manager, Ogre::SceneNode* parent,
             const std::string& ogre_prefix, const std::string& label);
  ~DrawnHuman();
  DrawnHuman(const DrawnHuman&) = delete;
  DrawnHuman& operator=(const DrawnHuman&) = delete;

  HumanModel& model() { return model_; }
  HumanVisual& visual() { return visual_; }
  const std::string& rootFrame() const { return poses_->rootFrame(); }

  // Bones from the pose source, then surfaces at `lod` (a displaced relief: `displaced_level` instead) and the
  // relief shown or hidden by its size on screen (`hide_unseen_relief`), and what the clothes
  // cover left out while the gap past hems is too small to see into (`hide_covered`,
  // LevelOfDetail::hide_covered). False when the human is not drawn this frame: its source has no
  // pose (TF lacks a bone), it is outside the camera's view (hidden, not posed), or a pose is
  // beyond what rviz can draw (then the human hides and a status names the frame until the
  // pose is sane again).
  bool update(rviz::FrameManager& frames, DisplayStatus& status, LevelOfDetail lod, const Ogre::Camera* camera,
              bool hide_unseen_relief, bool hide_covered);
  // Wall time of the newest update() that found every bone in TF, at most kFreshSeconds old
  // (TF keeps a stopped publisher's last transforms for ever).
  ros::WallTime lastSeen() const { return last_seen_; }
  static constexpr double kFreshSeconds = 1.0;
  // Whether TF data stamped `stamp` is at most kFreshSeconds old (a zero stamp: static, fresh).
  static bool fresh(const ros::Time& stamp) {
    return stamp.isZero() || (ros::Time::now() - stamp).toSec() <= kFreshSeconds;
  }

  // The skin cells' size on the body (`skin_cell_size`: their spacing on the forearm, m;
  // HumanModel::setSkinCellSize) and the feature sizes of both reliefs after it or the model
  // changed; both shown until judged again. Throws std::invalid_argument for a bad size.
  void resetReliefVisibility(double skin_cell_size);
  // Relief as displaced geometry (map null: bump mapping), as the display's relief properties say.
  void setDisplacement(const ReliefMapJobs& jobs, bool displaced, float skin_strength, float wrinkle_strength);
  // Removes every status this human set (it left the display).
  void clearStatuses(DisplayStatus& status);

 private:
  bool posesDrawable(DisplayStatus& status, const std::string& fixed_frame);
  // Whether the human, from its bones grown by the body's reach, is at least partly in `camera`'s
  // view (no camera: in view).
  bool inView(const Ogre::Camera* camera) const;
  // Judges, from where the human was last frame, which reliefs show (if `judge_relief`) and
  // whether the human is small: its garments' gap too small to see into (HumanModel::kCoverGap),
  // where what they cover is left out and lighting per vertex does.
  bool updateDetailVisibility(const Ogre::Camera* camera, bool judge_relief);

  std::unique_ptr<HumanPoseSource> poses_;
  ForwardKinematics kinematics_;
  HumanModel model_;
  HumanVisual visual_;
  std::string pose_status_;                       // "Pose", or "Pose <root frame>"
  RigidTransform root_;                           // in the fixed frame
  std::array<RigidTransform, kBoneCount> bones_;  // in the fixed frame
  std::string undrawable_frame_;                  // the frame whose pose hid the human; empty: none
  bool in_view_ = true;                           // at the last update()
  PerReliefKind<std::unique_ptr<ReliefVisibility>> relief_visibility_;  // null: no such parts
  ReliefVisibility cover_gap_visibility_{HumanModel::kCoverGap};
  ros::WallTime last_seen_;
};

}  // namespace dressed_human
