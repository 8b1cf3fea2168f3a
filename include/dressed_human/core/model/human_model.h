#pragma once
// Everything a renderer needs of one dressed human, in one place: from the bone frames (as TF
// delivers them) to posed, tessellated surface parts with their colour and relief kind. The rviz
// display is a thin adapter around this class; tools and benchmarks use it the same way.

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/garments/garment.h"
#include "dressed_human/core/relief/mesh_displacement.h"
#include "dressed_human/core/surfaces/patch_corner_split.h"
#include "dressed_human/core/surfaces/skin.h"
#include "dressed_human/core/surfaces/tessellation.h"
#include "dressed_human/core/relief/fold_coordinates.h"
#include "dressed_human/core/relief/vertex_compression.h"
#include "dressed_human/core/model/relief_kind.h"
#include "dressed_human/core/model/skin_relief_tiling.h"

namespace dressed_human {

// A part whose vertices the model evaluated: its mesh holds positions, normals and tangents.
struct CpuVertices {
  // Per vertex of the mesh, how much of the relief shows there, in [0, 1]; null: all of it. For
  // garments, the wrinkle strength from the posed garment's compression (wrinkle_placement.h):
  // wrinkles behind a bent knee, none on a straight leg.
  const std::vector<float>* relief_weight = nullptr;
  // Garments, per vertex of the mesh: which way the folds run (VertexStretch::fold_axis,
  // oriented_folds.h); null for the skin.
  const std::vector<Eigen::Vector2f>* fold_axis = nullptr;
  // Garments, per vertex of the mesh: where the fold tile lies (fold_coordinates.h), its tile
  // coordinate and the folds' signed direction in (u, v); null for the skin, and when the
  // wrinkles are not wanted.
  const std::vector<Eigen::Vector2f>* fold_tile = nullptr;
  const std::vector<Eigen::Vector2f>* fold_direction = nullptr;
};

// A part the renderer evaluates (VertexEvaluation::kGpu): its mesh is only the layout (uv,
// vertex_patch, indices; positions, normals, tangents unspecified). The renderer evaluates the
// part's `patches` at (vertex_patch, uv) itself and, for garments, the wrinkle strength from
// these (VertexCompression's formula).
struct GpuVertices {
  const std::vector<Eigen::Vector4f>* inverse_rest_metric = nullptr;  // garments, per vertex; null: the skin
  WrinkleStrengthConstants wrinkle_constants;
  // Garments, per vertex of the layout, while the wrinkles are wanted: the fold coordinates, as
  // CpuVertices (solved on the CPU from the posed patches, new every frame).
  const std::vector<Eigen::Vector2f>* fold_tile = nullptr;
  const std::vector<Eigen::Vector2f>* fold_direction = nullptr;
};

struct SurfacePart {
  std::string name;
  ReliefKind relief;
  Eigen::Vector4f colour;    // RGBA, 0..1
  const TriangleMesh* mesh;  // owned by the HumanModel, valid until its next update()
  // The vertices and triangles to draw: `mesh`'s, with shared vertices split where the patches
  // meeting there give them different (u, v) (patch_corner_split.h): the relief texture is per
  // patch. Per-vertex data (positions, weights, ...) is read at `corners->source`.
  const PatchCornerSplit* corners = nullptr;
  // A closed surface with outward, counter-clockwise triangles (the skin): its inside never
  // shows, so a renderer may cull back faces -- half the triangles it rasterizes. Garments are
  // open (hems, sleeves, collar) and show their inside.
  bool closed = false;
  // Per patch of `mesh`, true where it is covered by outer parts and is not to be drawn
  // (LevelOfDetail::hide_covered; mesh.triangle_patch says which triangle lies on which patch);
  // null: every patch is drawn. `drawn_triangles` counts the others.
  const std::vector<bool>* hidden_patches = nullptr;
  std::size_t drawn_triangles = 0;
  // Per patch of `mesh`: how many times the relief tile repeats along u and along v on it (the
  // skin's, sized in metres: skin_relief_tiling.h); null: once per patch (the garments' fold
  // tiles place themselves, oriented_folds.h). `relief_tiles_id` changes whenever they do.
  const std::vector<Eigen::Vector2f>* relief_tiles = nullptr;
  std::uint64_t relief_tiles_id = 0;
  // Who evaluated `mesh`'s vertices and what comes with them (VertexEvaluation).
  std::variant<CpuVertices, GpuVertices> vertices;
  const CpuVertices* cpuVertices() const { return std::get_if<CpuVertices>(&vertices); }
  const GpuVertices* gpuVertices() const { return std::get_if<GpuVertices>(&vertices); }
  const std::vector<BezierPatch>* patches = nullptr;  // posed, in the world frame of update()
  std::uint64_t layout_id = 0;                        // Tessellator::layoutId() of `mesh`
  // Encloses the posed part in the world frame of update(), whoever evaluates its vertices: the
  // box of the posed control points (a Bezier patch lies in their convex hull), or of the
  // displaced vertices when the relief moves them. A renderer culls by it, so it must follow the
  // human every frame: the layout alone says nothing about where the surface is.
  Eigen::AlignedBox3f bounds;
};

// Who evaluates the surface at the mesh vertices. kGpu leaves it to the renderer (a vertex
// shader evaluating the Bezier patches from their control points): update() then only poses the
// control points and re-lays out the mesh when the levels change, which is what makes a frame
// cheap. Parts with displaced relief are always evaluated here (the displacement needs vertices).
enum class VertexEvaluation { kCpu, kGpu };

struct LevelOfDetail {
  bool automatic = false;  // true: from the camera's screen-space error; false: `level`
  int level = Skin::kDefaultLevel;
  int max_level = 16;
  double max_error_pixels = 1.0;
  CameraView camera{Eigen::Vector3d::Zero(), 0.8, 1000.0};
  // Patches that outer parts cover (covered_patches.h: skin under the garments) are not drawn
  // (SurfacePart::hidden_patches) and drop to level 1: for a human so small on screen that the
  // gap between cloth and body is under a pixel or two (HumanModel::kCoverGap).
  bool hide_covered = false;
};

// The seed paper's three outfits (SPEC §3), or the bare skin.
enum class Outfit { kNone, kOnePiece, kJacketSkirt, kJacketPants };
// "none", "one_piece", "jacket_skirt", "jacket_pants"; throws std::invalid_argument otherwise.
Outfit outfitFromName(const std::string& name);
// The garment files (config/garments/<name>.yaml) an outfit is made of, outermost last.
std::vector<std::string> garmentFileNames(Outfit outfit);

struct HumanModelSettings {
  Eigen::Vector4f skin_colour{0.87f, 0.72f, 0.62f, 1.0f};
  Outfit outfit = Outfit::kJacketSkirt;
  std::string garment_directory;  // holds the outfit's garment YAML files
  double skirt_length = -1.0;     // normalized c in [0, 1] (Eq. 8'); < 0: as the skirt file says
  // Per garment file name ("jacket", "skirt", ...): RGBA replacing the file's colour.
  std::map<std::string, Eigen::Vector4f> garment_colours;
  // Joint angles the level of detail's error bound is calibrated across, besides rest
  // (CalibratedErrorBound): poses like those the human will be drawn in, so its margin for
  // unseen poses can be small. None: rest alone, with the wider margin.
  std::vector<JointAngles> calibration_poses;
};

class HumanModel {
 public:
  // The widest gap between a garment and what it covers (the garments' ease is 1.5-2 cm): where
  // it is under a pixel or two on screen, nothing covered can be seen past a hem or cuff.
  static constexpr double kCoverGap = 0.02;

  HumanModel(const Skeleton& skeleton, const BodyDescription& body, const HumanModelSettings& settings);

  // Loads the outfit's garments; throws (GarmentError, BodyDescriptionError, SkinError) naming
  // the file and what is wrong.
  // `root` is the skeleton's root frame ("body"), `bones` every bone frame, all in one world
  // frame. Allocation-free while the level of detail stays the same.
  void update(const RigidTransform& root, const std::array<RigidTransform, kBoneCount>& bones,
              const LevelOfDetail& lod);

  // Relief as displaced geometry (mesh_displacement.h) for every part of `kind`, from the next
  // update() on; a null map turns it off (bump mapping is then the renderer's business). For
  // garments, `folds` (the map being its strong tile) draws the oriented folds the shader draws.
  // The model keeps the maps alive. Throws std::invalid_argument naming a bad setting.
  void setDisplacement(ReliefKind kind, std::shared_ptr<const ReliefMap> map, float tiling, float height_to_tile,
                       float amplitude, std::shared_ptr<const FoldTiles> folds = nullptr);

  // false: the garments' per-vertex wrinkle strength and fold axis are not computed (relief_weight
  // and fold_axis null) unless their relief is displaced: for a renderer not drawing the wrinkle
  // relief (too small to see). From the next update() on; true by default.
  void setWrinklesWanted(bool wanted) { wrinkles_wanted_ = wanted; }

  // From the next update() on; kCpu by default.
  void setVertexEvaluation(VertexEvaluation evaluation) { vertex_evaluation_ = evaluation; }
  VertexEvaluation vertexEvaluation() const { return vertex_evaluation_; }

  const std::vector<SurfacePart>& parts() const { return parts_; }
  std::size_t triangleCount() const;
  // Triangles not on hidden patches (SurfacePart::drawn_triangles, summed).
  std::size_t drawnTriangleCount() const;
  // Per part, per patch: covered by the parts outside it (skin by every garment, a garment by
  // those listed after it), judged at rest (patchesCoveredBy).
  const std::vector<bool>& coveredPatches(std::size_t part) const { return covered_->at(part); }
  // Part `part`'s posed Bezier patches and the tessellation level each got in the last update()
  // (for error budgets: geometricErrorBound(patch, level)).
  const std::vector<BezierPatch>& partPatches(std::size_t part) const;
  const std::vector<int>& partLevels(std::size_t part) const;
  // The error bound automatic level of detail chooses part `part`'s levels by: calibrated on the
  // part at rest and in HumanModelSettings::calibration_poses (CalibratedErrorBound, about 2x
  // tighter than geometricErrorBound, so about half the triangles for the same screen error).
  const CalibratedErrorBound& partErrorBound(std::size_t part) const;
  const Skin& skin() const { return skin_; }
  // The skin relief's level-1 cell spacing on the forearm (m, > 0), the other regions in their
  // measured proportion (skin_relief_tiling.h); from the next update() on. Throws
  // std::invalid_argument for a spacing that is not positive and finite.
  void setSkinCellSize(double forearm_cell_spacing);
  const SkinReliefTiling& skinTiling() const { return skin_tiling_; }
  // Metres between neighbouring features of the relief of `kind` (what ReliefVisibility judges):
  // the skin's largest cells; the garments' folds, about half a buckling cell apart on a typical
  // patch (cells_around cells per fold tile, kFoldTilesPerPatch tiles per patch). 0 for cloth
  // without garments.
  double reliefFeatureSize(ReliefKind kind) const;
  // Encloses every part as posed by the last update() (empty before).
  Eigen::AlignedBox3f bounds() const;

 private:
  struct AutomaticLevels {
    std::vector<int> levels;        // per patch, the level in use
    std::vector<int> frames_below;  // per patch, updates in a row a lower level would have done
  };
  struct CornerSplit {
    PatchCornerSplit split;
    std::uint64_t layout_id = 0;  // of the layout it was split from
  };
  // What the model keeps of one drawn part between updates (parts_[p] is what it hands out).
  struct PartState {
    std::optional<std::size_t> garment;                       // index in garments_; none: the skin
    std::shared_ptr<const CalibratedErrorBound> error_bound;  // shared by humans of one body and outfit
    std::unique_ptr<Tessellator> tessellator = std::make_unique<Tessellator>();  // not movable
    AutomaticLevels automatic;
    CornerSplit corners;
    TriangleMesh displaced;  // while the part's relief kind is displaced
  };
  // One garment of the outfit and what its wrinkle measure keeps between updates.
  struct DressedGarment {
    DressedGarment(const GarmentDescription& description, const Skeleton& skeleton, const BodyShape& shape);
    Garment garment;
    std::vector<BezierPatch> rest_patches;   // built in the rest pose
    VertexCompression compression;           // the per-vertex compression measure
    std::uint64_t compressed_layout = 0;     // Tessellator::layoutId() `compression` was prepared for
    std::vector<float> wrinkle_weights;      // per vertex, last levels used
    std::vector<Eigen::Vector2f> fold_axes;  // per vertex, last levels used
    // The fold coordinates (fold_coordinates.h): solved every update on the garment's own grid,
    // whatever the level of detail, and sampled at the drawn vertices.
    std::unique_ptr<Tessellator> grid_tessellator = std::make_unique<Tessellator>();
    std::vector<int> grid_levels;  // FoldCoordinates::kGridLevel per patch
    PatchCornerSplit grid_split;
    VertexCompression grid_compression;
    std::vector<float> grid_strengths;
    std::vector<Eigen::Vector2f> grid_axes;
    FoldCoordinates fold_coordinates;
    std::vector<Eigen::Vector2f> fold_tiles, fold_directions;  // per drawn vertex
  };
  struct Displacement {
    std::shared_ptr<const ReliefMap> map;
    std::shared_ptr<const FoldTiles> folds;
    // Their mip chains, so relief finer than the vertices is filtered out, not aliased.
    std::shared_ptr<const std::vector<ReliefMap>> map_mips;
    std::shared_ptr<const FoldTileMips> fold_mips;
    ReliefDisplacement settings;
  };

  void addPart(const std::string& name, ReliefKind relief, const Eigen::Vector4f& colour,
               std::optional<std::size_t> garment);
  // Every part's error bound, at rest and in settings_.calibration_poses; leaves the surfaces at rest.
  void calibrateErrorBounds(const Skeleton& skeleton, const BodyShape& shape);
  const PatchTopology& topologyOf(const PartState& state) const;
  // update()'s steps, in order.
  void poseSurfaces(const RigidTransform& root, const std::array<RigidTransform, kBoneCount>& bones);
  const std::vector<int>& chooseLevels(PartState& state, const std::vector<BezierPatch>& patches,
                                       const LevelOfDetail& lod);
  const std::vector<int>& withCoveredHidden(std::size_t part, const std::vector<int>& levels, bool hide);
  void tessellate(std::size_t part, const std::vector<int>& levels, bool cpu_vertices);
  void measureWrinkles(DressedGarment& dressed, SurfacePart& part, bool cpu_vertices, bool displaced);
  void solveFoldCoordinates(DressedGarment& dressed, SurfacePart& part);
  void displaceAndBound(std::size_t part, const std::vector<int>& levels);

  HumanModelSettings settings_;
  Skin skin_;
  SkeletonPose pose_;
  std::vector<DressedGarment> garments_;
  SkinReliefTiling skin_tiling_;  // built on the skin at rest
  std::uint64_t skin_tiles_id_ = 1;
  double cloth_patch_size_ = 0.0;  // typicalPatchSize of the garments at rest
  std::vector<SurfacePart> parts_;
  std::vector<PartState> part_states_;  // per part
  std::vector<int> uniform_levels_;     // scratch: a fixed level on every patch
  std::vector<int> wanted_levels_;      // scratch: what the screen error asks for, per patch
  std::vector<int> drawn_levels_;       // scratch: the levels with hidden patches at 1
  // Per part, per patch; shared by the humans of the same body and outfit.
  std::shared_ptr<const std::vector<std::vector<bool>>> covered_;
  VertexEvaluation vertex_evaluation_ = VertexEvaluation::kCpu;
  bool wrinkles_wanted_ = true;
  std::array<Displacement, 2> displacements_;  // by ReliefKind
};

}  // namespace dressed_human
