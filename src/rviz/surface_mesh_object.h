#pragma once
// An Ogre::ManualObject fed from a core TriangleMesh; refilled in place (its hardware buffers
// reused while they are large enough, grown otherwise). Either with evaluated vertices every
// frame (update), or with a layout for the Bezier vertex shader, re-sent only when it changes
// (updateLayout). Either way the object's bounds are set to the posed surface's every frame:
// Ogre culls by them.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <OgreManualObject.h>
#include <OgreSceneManager.h>
#include <OgreSceneNode.h>

#include "dressed_human/core/model/human_model.h"
#include "dressed_human/core/surfaces/patch_corner_split.h"
#include "dressed_human/core/surfaces/tessellation.h"

namespace dressed_human {

class SurfaceMeshObject {
 public:
  SurfaceMeshObject(Ogre::SceneManager* scene_manager, Ogre::SceneNode* parent, const std::string& material);
  ~SurfaceMeshObject();
  SurfaceMeshObject(const SurfaceMeshObject&) = delete;
  SurfaceMeshObject& operator=(const SurfaceMeshObject&) = delete;

  // How the relief texture lies on the surface: `corners`, the vertices and triangles
  // (SurfacePart::corners: the mesh's, shared vertices split per patch, each with its patch's
  // (u, v); null: the mesh's own, fewer vertices, for a surface drawn without its relief
  // texture), and `tiles`, the tiles per patch its (u, v) are scaled by (SurfacePart::relief_tiles;
  // null: one), which change only with `tiles_id`.
  struct ReliefTexturing {
    const PatchCornerSplit* corners = nullptr;
    const std::vector<Eigen::Vector2f>* tiles = nullptr;
    std::uint64_t tiles_id = 0;
  };

  // Vertices and triangles as `texturing` says: per vertex its position and normal, and unless
  // `lit_per_vertex` (ReliefMaterial::litPerVertex: its lighting reads nothing else, and a small
  // human's vertices are then most of what rviz's thread fills and sends each frame besides the
  // model) dF/du as the tangent, the relief texture coordinate, and as the second texture
  // coordinate the `vertices`' relief_weight (how much relief shows; null: 1) and fold_axis (which
  // way garment folds run; null: zeros). `bounds`: encloses the posed surface
  // (SurfacePart::bounds). `hidden_patches`: triangles on these patches are left out
  // (SurfacePart::hidden_patches; null: none). Throws std::invalid_argument for per-vertex or
  // per-patch data of another size.
  void update(const TriangleMesh& mesh, const ReliefTexturing& texturing, const CpuVertices& vertices,
              const std::vector<bool>* hidden_patches, const Eigen::AlignedBox3f& bounds, bool lit_per_vertex);
  // Per vertex the owner's (u, v, patch) as the position, the garment's rest metric (the
  // `vertices`' inverse_rest_metric; null: zeros) as texture coordinate 0 and the
  // vertex's relief texture coordinate (`texturing` as above) as texture coordinate 1; triangles
  // on `hidden_patches` left out as above. Nothing is sent while `layout_id`, whether corners are
  // given, the tiles and `hidden_patches` stay the same; `bounds` (the posed surface's) is set every
  // frame, since the (u, v, patch) positions say nothing about where the surface is.
  void updateLayout(const TriangleMesh& layout, const ReliefTexturing& texturing, const GpuVertices& vertices,
                    const std::vector<bool>* hidden_patches, std::uint64_t layout_id,
                    const Eigen::AlignedBox3f& bounds);
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
  // What each vertex of the buffers holds: another set needs another section (its declaration).
  enum class VertexAttributes { kNone, kShading, kRelief, kLayout, kLayoutFolds };
  VertexAttributes attributes_ = VertexAttributes::kNone;
  std::uint64_t layout_id_ = 0;                     // of the layout the buffers hold; 0: evaluated vertices
  bool split_sent_ = false;                         // the buffers hold the corner split of that layout
  std::uint64_t tiles_sent_ = 0;                    // with these tiles per patch
  const std::vector<bool>* hidden_sent_ = nullptr;  // and left out these patches' triangles
  // false: the mesh is empty.
  bool beginFilling(std::size_t vertices, std::size_t indices, VertexAttributes attributes);
  // Split vertex i's relief texture coordinate (vertex i of `mesh` without corners).
  static Eigen::Vector2f reliefCoordinate(const TriangleMesh& mesh, const ReliefTexturing& texturing, std::size_t i);
  void addTriangles(const std::vector<std::uint32_t>& indices, const TriangleMesh& mesh,
                    const std::vector<bool>* hidden_patches);
  void setBounds(const Eigen::AlignedBox3f& bounds);
  static void checkTexturing(const TriangleMesh& mesh, const ReliefTexturing& texturing);
};

}  // namespace dressed_human
