#pragma once
// The skeleton drawn as lines over everything (one per bone, from its frame's origin along its
// z axis, as long as the shaped bone): owned by HumanVisual, created when first shown.

#include <array>
#include <cstdint>
#include <memory>

#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace Ogre {
class SceneManager;
class SceneNode;
}  // namespace Ogre
namespace rviz {
class BillboardLine;
}  // namespace rviz

namespace dressed_human {

class SkeletonVisual {
 public:
  SkeletonVisual(Ogre::SceneManager* scene_manager, Ogre::SceneNode* parent);
  ~SkeletonVisual();
  SkeletonVisual(const SkeletonVisual&) = delete;
  SkeletonVisual& operator=(const SkeletonVisual&) = delete;

  void setVisible(bool visible);
  // `bones` in the fixed frame; the lengths are the skeleton's shaped by `kinematics`' shape.
  void update(const ForwardKinematics& kinematics, const std::array<RigidTransform, kBoneCount>& bones);

 private:
  Ogre::SceneManager* scene_manager_;
  Ogre::SceneNode* parent_;
  std::unique_ptr<rviz::BillboardLine> lines_;
};

}  // namespace dressed_human
