#pragma once
// One bump-mapped material per surface part: a clone of dressed_human/ReliefSurface (media/) with
// the part's colour, relief strength and tangent-space normal map -- or of
// dressed_human/ReliefBezierSurface, whose vertex shader evaluates the Bezier patches from the
// control points set here.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <OgreMaterial.h>
#include <OgreTexture.h>

#include <Eigen/Geometry>

#include "dressed_human/core/relief/relief_map.h"
#include "dressed_human/core/surfaces/bezier_patch.h"
#include "dressed_human/core/relief/vertex_compression.h"

namespace dressed_human {

class NormalMapTexture;

class ReliefMaterial {
 public:
  // Loads media/materials once per process (resource group "dressed_human"). Throws
  // std::runtime_error with Ogre's message when the material or its GLSL programs do not load.
  static void loadMediaOnce();

  // What the Bezier vertex shader holds per part (its uniform array, relief_surface.vert).
  static constexpr std::size_t kMaxPatches = 192;  // the skin has 188
  // Whether this GL can run the Bezier vertex shader; if not, `why` says what is missing.
  // Loads the media first (may throw like loadMediaOnce).
  static bool bezierEvaluationAvailable(std::string* why);

  // gpu_vertices: the vertex shader evaluates the patches (setPatches), the mesh brings only
  // (u, v, patch) per vertex (SurfaceMeshObject::updateLayout). oriented_folds: a garment's, whose
  // map holds the two fold tiles (encodeFoldTilesRgba, 4 channels), laid by the vertices' fold
  // coordinates (FoldCoordinates: CpuVertices or GpuVertices::fold_tile and fold_direction).
  ReliefMaterial(const std::string& unique_name, bool gpu_vertices, bool oriented_folds);
  ~ReliefMaterial();
  ReliefMaterial(const ReliefMaterial&) = delete;
  ReliefMaterial& operator=(const ReliefMaterial&) = delete;

  const std::string& name() const { return name_; }
  void setColour(float r, float g, float b, float a = 1.0f);
  // Closed surfaces: back faces culled (SurfacePart::closed). Open ones are drawn two-sided.
  void setBackFacesCulled(bool culled);
  // 0 shades with the geometric normal only (flat), 1 with the full relief.
  void setReliefStrength(float strength);
  // false: the plain fragment program (geometric normal, no normal-map fetch) replaces the relief
  // one, for a relief too small to see (ReliefVisibility). Colour and strength carry over.
  void setReliefShown(bool shown);
  bool reliefShown() const { return relief_shown_; }
  // Lit per vertex now (set so and the relief not shown): the programs read each vertex's
  // position and normal only.
  bool litPerVertex() const { return vertex_lit_ && !relief_shown_; }
  // true: while the relief is not shown, the same plain lighting is computed per vertex instead
  // of per pixel (a small human: its triangles cover a few pixels, and on a software renderer
  // the fragment program is most of its cost).
  void setVertexLit(bool lit);
  // 8-bit tangent-space normals (n * 0.5 + 0.5) and their mip levels as given (not the GPU's):
  // RGB (3 channels) for the skin, the fold tiles' RGBA (4) for garments; another count, or a
  // level whose size does not match, throws std::invalid_argument. One texture per map in the
  // process: every material given the same map shares it.
  void setNormalMap(const std::shared_ptr<const EncodedNormalMap>& map);
  // Bezier vertices only: the posed patches (at most kMaxPatches, else std::invalid_argument)
  // and, for garments, the wrinkle strength's constants (null: the relief shows everywhere).
  void setPatches(const std::vector<BezierPatch>& patches);
  void setWrinkleStrength(const WrinkleStrengthConstants* constants);

 private:
  std::string name_;
  Ogre::MaterialPtr material_;
  std::shared_ptr<NormalMapTexture> texture_;
  bool gpu_vertices_;
  const char* relief_fragment_;  // the fragment program showing the relief
  int normal_channels_;
  WrinkleStrengthConstants wrinkle_strength_;  // as last set (zeros: none)
  bool wrinkle_strength_set_ = false;
  bool relief_shown_ = true;
  bool vertex_lit_ = false;
  void applyPrograms();                               // the vertex and fragment programs the state above asks for
  Ogre::ColourValue colour_{0.8f, 0.7f, 0.6f, 1.0f};  // as last set, for a fragment program swap
  float relief_strength_ = 1.0f;
  void applyShadingParameters();  // colour and strength, to whichever program shades
};

}  // namespace dressed_human
