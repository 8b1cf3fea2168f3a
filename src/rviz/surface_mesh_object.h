#pragma once
// An Ogre::ManualObject fed from a core TriangleMesh; refilled in place (its hardware buffers
// reused while they are large enough, grown otherwise).

#include <string>

#include <OgreManualObject.h>
#include <OgreSceneManager.h>
#include <OgreSceneNode.h>

#include "dressed_human/core/tessellation.h"

namespace dressed_human {

class SurfaceMeshObject {
 public:
  SurfaceMeshObject(Ogre::SceneManager* scene_manager, Ogre::SceneNode* parent, const std::string& material);
  ~SurfaceMeshObject();
  SurfaceMeshObject(const SurfaceMeshObject&) = delete;
  SurfaceMeshObject& operator=(const SurfaceMeshObject&) = delete;

  // `relief_weight`: per vertex, how much relief shows (second texture coordinate); null: 1.
  void update(const TriangleMesh& mesh, const std::vector<float>* relief_weight = nullptr);
  void setMaterial(const std::string& material);
  void setVisible(bool visible) { object_->setVisible(visible); }
  std::size_t rebuildCount() const { return rebuild_count_; }

 private:
  Ogre::SceneManager* scene_manager_;
  Ogre::ManualObject* object_;
  std::string material_;
  std::size_t vertex_count_ = 0;  // largest counts seen: what the buffers hold
  std::size_t index_count_ = 0;
  std::size_t rebuild_count_ = 0;  // buffer (re)creations
};

}  // namespace dressed_human
