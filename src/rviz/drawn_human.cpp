#include "drawn_human.h"

#include <cstdio>

#include <OgreAxisAlignedBox.h>
#include <OgreCamera.h>
#include <rviz/frame_manager.h>

#include "display_status.h"
#include "properties/lod_properties.h"

namespace dressed_human {
namespace {

// Ogre draws in float: beyond this distance from the fixed frame a human's millimetres are lost
// (float spacing at 100 km is 8 mm) and further out its coordinates overflow. No map is larger.
constexpr double kMaxDrawableCoordinate = 1e5;
// How far skin and clothes reach beyond the bone frames' origins (head top, hands, skirt hem).
constexpr double kReachMetres = 0.5;

bool drawable(const RigidTransform& pose) {
  return pose.translation.allFinite() && pose.translation.cwiseAbs().maxCoeff() <= kMaxDrawableCoordinate &&
         pose.rotation.coeffs().allFinite();
}

}  // namespace

DrawnHuman::DrawnHuman(const Skeleton& skeleton, std::unique_ptr<HumanPoseSource> poses,
                       const BodyDescription& shaped_body, const HumanModelSettings& settings,
                       Ogre::SceneManager* scene_manager, Ogre::SceneNode* parent, const std::string& ogre_prefix,
                       const std::string& label)
    : poses_(std::move(poses)),
      kinematics_(skeleton, shaped_body.shape),
      model_(skeleton, shaped_body, settings),
      visual_(scene_manager, parent, ogre_prefix),
      pose_status_(label.empty() ? "Pose" : "Pose " + label),
      last_seen_(ros::WallTime::now()) {}

DrawnHuman::~DrawnHuman() = default;

bool DrawnHuman::update(rviz::FrameManager& frames, DisplayStatus& status, LevelOfDetail lod,
                        const Ogre::Camera* camera, bool hide_unseen_relief, bool hide_covered) {
  if (!poses_->pose(frames, status, kinematics_, root_, bones_)) return false;
  if (fresh(poses_->stamp())) last_seen_ = ros::WallTime::now();
  if (!posesDrawable(status, frames.getFixedFrame())) return false;
  // A human outside the view is neither posed nor tessellated: a crowd around the camera costs
  // what is in front of it. Hidden, so that Ogre never draws its stale mesh.
  const bool in_view = inView(camera);
  if (!in_view || !in_view_) visual_.setVisible(in_view);  // hidden every frame out of view, as posesDrawable does
  in_view_ = in_view;
  if (!in_view) return false;
  // Visibility first (by where the human was last frame): the model skips the wrinkles' per-vertex
  // work while they are not drawn, and must do it in the very frame they are drawn again.
  const bool small = updateDetailVisibility(camera, hide_unseen_relief);
  lod.hide_covered = hide_covered && small;
  visual_.setVertexLit(hide_unseen_relief && small);
  visual_.setInsidesHidden(lod.hide_covered);
  model_.setWrinklesWanted(visual_.reliefShown(ReliefKind::kCloth));
  model_.update(root_, bones_, lod);
  visual_.update(model_.parts());
  visual_.updateSkeleton(kinematics_, bones_);
  return true;
}

bool DrawnHuman::inView(const Ogre::Camera* camera) const {
  if (camera == nullptr) return true;
  Eigen::AlignedBox3d box;
  for (const RigidTransform& bone : bones_) box.extend(bone.translation);
  box.extend(root_.translation);
  const Eigen::Vector3d low = box.min().array() - kReachMetres, high = box.max().array() + kReachMetres;
  return camera->isVisible(Ogre::AxisAlignedBox(static_cast<float>(low.x()), static_cast<float>(low.y()),
                                                static_cast<float>(low.z()), static_cast<float>(high.x()),
                                                static_cast<float>(high.y()), static_cast<float>(high.z())));
}

void DrawnHuman::resetReliefVisibility(double skin_cell_size) {
  model_.setSkinCellSize(skin_cell_size);
  const double skin = model_.reliefFeatureSize(ReliefKind::kSkin);
  const double cloth = model_.reliefFeatureSize(ReliefKind::kCloth);
  relief_visibility_[ReliefKind::kSkin] = skin > 0.0 ? std::make_unique<ReliefVisibility>(skin) : nullptr;
  relief_visibility_[ReliefKind::kCloth] = cloth > 0.0 ? std::make_unique<ReliefVisibility>(cloth) : nullptr;
  visual_.setReliefShown(ReliefKind::kSkin, true);
  visual_.setReliefShown(ReliefKind::kCloth, true);
}

void DrawnHuman::setDisplacement(const ReliefMapJobs& jobs, bool displaced, float skin_strength,
                                 float wrinkle_strength) {
  // Until a map has been built its kind stays undisplaced; the display calls again when it comes.
  model_.setDisplacement(ReliefKind::kSkin, displaced ? jobs.map(ReliefKind::kSkin) : nullptr, 1.0f, 1.0f,
                         skin_strength);
  model_.setDisplacement(ReliefKind::kCloth, displaced ? jobs.map(ReliefKind::kCloth) : nullptr, 1.0f,
                         ReliefMapJobs::clothHeightToTile(), wrinkle_strength, jobs.foldTiles());
}

void DrawnHuman::clearStatuses(DisplayStatus& status) {
  poses_->clearStatuses(status);
  status.clear(pose_status_);
}

bool DrawnHuman::updateDetailVisibility(const Ogre::Camera* camera, bool judge_relief) {
  const Eigen::AlignedBox3f bounds = model_.bounds();
  const bool placed = camera != nullptr && !bounds.isEmpty();
  double pixels_per_metre = 0.0;  // at the human's nearest point
  if (placed) {
    const CameraView view = LodProperties::cameraView(*camera);
    pixels_per_metre = pixelsPerMetre(view, bounds.cast<double>().exteriorDistance(view.position));
  }
  // The gap past hems and cuffs switches like a relief's features, with the same hysteresis.
  const bool small = placed && !cover_gap_visibility_.update(pixels_per_metre);
  const bool judged = judge_relief && placed;
  for (const ReliefKind kind : {ReliefKind::kSkin, ReliefKind::kCloth}) {
    std::unique_ptr<ReliefVisibility>& visibility = relief_visibility_[kind];
    if (!visibility) continue;
    const bool shown = judged ? visibility->update(pixels_per_metre) : true;
    visual_.setReliefShown(kind, shown);
    visual_.setReliefFade(kind, judged ? static_cast<float>(visibility->fade()) : 1.0f);
  }
  return small;
}

bool DrawnHuman::posesDrawable(DisplayStatus& status, const std::string& fixed_frame) {
  // A glitching publisher (a huge origin, a runaway integration) must not take rviz down: Ogre
  // asserts on non-finite bounds. The human disappears, the frame is named, and it comes back
  // with sane TF.
  std::string frame;
  const RigidTransform* pose = nullptr;
  if (!drawable(root_)) frame = poses_->rootFrame(), pose = &root_;
  for (std::size_t b = 0; pose == nullptr && b < kBoneCount; ++b) {
    if (!drawable(bones_[b])) frame = poses_->boneFrame(b), pose = &bones_[b];
  }
  if (pose == nullptr) {
    if (!undrawable_frame_.empty()) {
      status.clear(pose_status_);
      visual_.setVisible(true);
      undrawable_frame_.clear();
    }
    return true;
  }
  if (undrawable_frame_ != frame) {
    char position[96];
    std::snprintf(position, sizeof(position), "(%.2g, %.2g, %.2g) m", pose->translation.x(), pose->translation.y(),
                  pose->translation.z());
    const bool finite = pose->translation.allFinite() && pose->rotation.coeffs().allFinite();
    status.error(pose_status_,
                 "frame '" + frame + "' in '" + fixed_frame + "' is " +
                     (finite ? std::string("at ") + position + ", beyond the 100 km rviz can draw a human at"
                             : std::string("not finite")) +
                     "; the human is hidden until its TF is sane again");
    undrawable_frame_ = frame;
  }
  visual_.setVisible(false);  // every frame: enabling the display again must not show it
  return false;
}

}  // namespace dressed_human
