#pragma once
// The Ogre side of one dressed human, owning every Ogre object it draws: a scene node with one
// bump-mapped mesh per surface part (skin, each garment) and the skeleton's lines. Created and
// updated only from the display's update().

#include <array>
#include <memory>
#include <string>
#include <vector>

#include <OgreSceneManager.h>
#include <OgreSceneNode.h>

#include "dressed_human/core/model/human_model.h"
#include "dressed_human/core/model/relief_map_jobs.h"
#include "relief_material.h"
#include "skeleton_visual.h"
#include "surface_mesh_object.h"

namespace dressed_human {

class HumanVisual {
 public:
  HumanVisual(Ogre::SceneManager* scene_manager, Ogre::SceneNode* parent, const std::string& name_prefix);
  ~HumanVisual();
  HumanVisual(const HumanVisual&) = delete;
  HumanVisual& operator=(const HumanVisual&) = delete;

  // Meshes are in the fixed frame; parts are matched by index and (re)created when they change.
  void update(const std::vector<SurfacePart>& parts);
  void setVisible(bool visible);
  void setReliefStrength(ReliefKind kind, float strength);
  // false: parts of `kind` drawn with the plain material (ReliefMaterial::setReliefShown).
  void setReliefShown(ReliefKind kind, bool shown);
  bool reliefShown(ReliefKind kind) const { return relief_shown_[kind]; }
  // Scales the relief strength of parts of `kind` (ReliefVisibility::fade: 0 to 1 with distance).
  void setReliefFade(ReliefKind kind, float fade);
  // true: parts whose relief is not shown are lit per vertex (ReliefMaterial::setVertexLit).
  void setVertexLit(bool lit);
  // true: open parts' back faces are culled too. A garment's inside shows only past its hems and
  // cuffs; while that gap is too small to see (LevelOfDetail::hide_covered) drawing it is wasted:
  // on llvmpipe a small human's cost is its triangles' setup, not its pixels.
  void setInsidesHidden(bool hidden);
  // A finished map's texture (3 channels for the skin, 4 for the garments' fold tiles), tiled once
  // per patch, on every part of its kind.
  void setNormalMap(const FinishedReliefMap& finished);
  // Bones as lines drawn over everything (SkeletonVisual); updated only while shown.
  void setSkeletonVisible(bool visible);
  void updateSkeleton(const ForwardKinematics& kinematics, const std::array<RigidTransform, kBoneCount>& bones);

 private:
  struct Part {
    std::string name;
    ReliefKind relief;
    bool gpu_vertices;  // the vertex shader evaluates the patches (SurfacePart::cpu_vertices false)
    bool closed;        // SurfacePart::closed: back faces always culled
    Eigen::Vector4f colour = Eigen::Vector4f::Zero();
    bool colour_set = false;
    std::unique_ptr<ReliefMaterial> material;
    std::unique_ptr<SurfaceMeshObject> mesh;
  };
  void applyMaps(Part& part) const;

  Ogre::SceneManager* scene_manager_;
  Ogre::SceneNode* node_;
  std::string name_prefix_;
  std::vector<Part> parts_;
  PerReliefKind<float> relief_strength_{1.0f, 1.0f};  // the user's
  PerReliefKind<bool> relief_shown_{true, true};
  PerReliefKind<float> relief_fade_{1.0f, 1.0f};
  float reliefStrength(ReliefKind kind) const;                   // the user's times the fade
  PerReliefKind<std::shared_ptr<const EncodedNormalMap>> maps_;  // null until built
  bool visible_ = true;
  bool vertex_lit_ = false;
  bool insides_hidden_ = false;
  std::unique_ptr<SkeletonVisual> skeleton_;
  bool skeleton_visible_ = false;
};

}  // namespace dressed_human
