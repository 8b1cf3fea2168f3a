#include "skeleton_visual.h"

#include <OgreMaterial.h>
#include <OgreRenderQueue.h>
#include <OgreSceneNode.h>
#include <OgreTechnique.h>
#include <rviz/ogre_helpers/billboard_line.h>

namespace dressed_human {

SkeletonVisual::SkeletonVisual(Ogre::SceneManager* scene_manager, Ogre::SceneNode* parent)
    : scene_manager_(scene_manager), parent_(parent) {}

SkeletonVisual::~SkeletonVisual() = default;

void SkeletonVisual::setVisible(bool visible) {
  if (visible && !lines_) {
    lines_ = std::make_unique<rviz::BillboardLine>(scene_manager_, parent_);
    lines_->setLineWidth(0.015f);
    // Seen through the skin and clothes: the point of showing it.
    lines_->getMaterial()->getTechnique(0)->setDepthCheckEnabled(false);
    lines_->getSceneNode()->getAttachedObject(0)->setRenderQueueGroup(Ogre::RENDER_QUEUE_OVERLAY - 1);
    // Sized once: resizing rebuilds the billboard chains' buffers.
    lines_->setMaxPointsPerLine(2);
    lines_->setNumLines(static_cast<std::uint32_t>(kBoneCount));
  }
  if (lines_) lines_->getSceneNode()->setVisible(visible);
}

void SkeletonVisual::update(const ForwardKinematics& kinematics, const std::array<RigidTransform, kBoneCount>& bones) {
  if (!lines_) return;
  lines_->clear();
  const Ogre::ColourValue colour(1.0f, 0.85f, 0.1f, 1.0f);
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    if (b > 0) lines_->newLine();
    const double length = kinematics.skeleton().bone(b).length * kinematics.shape().scale[b].z();
    const Eigen::Vector3f start = bones[b].translation.cast<float>();
    const Eigen::Vector3f end =
        (bones[b].translation + bones[b].rotation * Eigen::Vector3d(0.0, 0.0, length)).cast<float>();
    lines_->addPoint(Ogre::Vector3(start.x(), start.y(), start.z()), colour);
    lines_->addPoint(Ogre::Vector3(end.x(), end.y(), end.z()), colour);
  }
}

}  // namespace dressed_human
