#include "dressed_human/core/model/human_model.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "dressed_human/core/garments/garment_file.h"
#include "dressed_human/core/model/relief_map_jobs.h"
#include "dressed_human/core/model/relief_visibility.h"
#include "dressed_human/core/surfaces/covered_patches.h"
#include "dressed_human/core/surfaces/patch_keyed_cache.h"

namespace dressed_human {
namespace {

constexpr int kDropAfterUpdates = 60;  // 2 s at rviz's 30 fps
constexpr std::array<int, 12> kLevelLadder{{1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64}};

// Index of the smallest ladder level >= level (the top one beyond it).
int ladderRung(int level) {
  for (std::size_t r = 0; r < kLevelLadder.size(); ++r) {
    if (kLevelLadder[r] >= level) return static_cast<int>(r);
  }
  return static_cast<int>(kLevelLadder.size()) - 1;
}

// In double, rounded outwards to float: the float vertices evaluated from these control points
// stay inside.
Eigen::AlignedBox3f outwardToFloat(const Eigen::AlignedBox3d& box) {
  if (box.isEmpty()) return Eigen::AlignedBox3f();
  const float lowest = -std::numeric_limits<float>::infinity(), highest = std::numeric_limits<float>::infinity();
  Eigen::Vector3f min, max;
  for (int k = 0; k < 3; ++k) {
    min[k] = std::nextafter(static_cast<float>(box.min()[k]), lowest);
    max[k] = std::nextafter(static_cast<float>(box.max()[k]), highest);
  }
  return Eigen::AlignedBox3f(min, max);
}

Eigen::AlignedBox3f controlPointBounds(const std::vector<BezierPatch>& patches) {
  Eigen::AlignedBox3d box;
  for (const BezierPatch& patch : patches) {
    box.extend(patch.boundingBoxMin());
    box.extend(patch.boundingBoxMax());
  }
  return outwardToFloat(box);
}

Eigen::AlignedBox3f vertexBounds(const std::vector<Eigen::Vector3f>& positions) {
  Eigen::AlignedBox3f box;
  for (const Eigen::Vector3f& position : positions) box.extend(position);
  return box;
}

// Per part of `rest` (innermost first), per patch: covered by the parts after it. Computed once
// per process for the same surfaces (a crowd of one body and outfit, humans coming and going).
std::shared_ptr<const std::vector<std::vector<bool>>> sharedCoveredPatches(
    const std::vector<const std::vector<BezierPatch>*>& rest) {
  static PatchKeyedCache<std::vector<std::vector<bool>>> cache;
  return cache.obtain(rest, [&] {
    auto covered = std::make_shared<std::vector<std::vector<bool>>>();
    for (std::size_t p = 0; p < rest.size(); ++p) {
      const std::vector<const std::vector<BezierPatch>*> outer(rest.begin() + static_cast<std::ptrdiff_t>(p) + 1,
                                                               rest.end());
      covered->push_back(patchesCoveredBy(*rest[p], outer));
    }
    return std::shared_ptr<const std::vector<std::vector<bool>>>(std::move(covered));
  });
}

}  // namespace

Outfit outfitFromName(const std::string& name) {
  if (name == "none") return Outfit::kNone;
  if (name == "one_piece") return Outfit::kOnePiece;
  if (name == "jacket_skirt") return Outfit::kJacketSkirt;
  if (name == "jacket_pants") return Outfit::kJacketPants;
  throw std::invalid_argument("unknown outfit '" + name + "'; expected none, one_piece, jacket_skirt or jacket_pants");
}

std::vector<std::string> garmentFileNames(Outfit outfit) {
  switch (outfit) {
    case Outfit::kNone:
      return {};
    case Outfit::kOnePiece:
      return {"one_piece"};
    case Outfit::kJacketSkirt:
      return {"skirt", "jacket"};
    case Outfit::kJacketPants:
      return {"pants", "jacket"};
  }
  return {};
}

HumanModel::HumanModel(const Skeleton& skeleton, const BodyDescription& body, const HumanModelSettings& settings)
    : settings_(settings), skin_(skeleton, body), skin_tiling_(skin_) {
  addPart("skin", ReliefKind::kSkin, settings_.skin_colour, std::nullopt);
  parts_.back().closed = true;  // every skin part is a closed surface (skin.h)
  for (const std::string& name : garmentFileNames(settings_.outfit)) {
    GarmentDescription description = loadGarmentFile(settings_.garment_directory + "/" + name + ".yaml", skeleton);
    const bool has_skirt = description.type == GarmentType::kSkirt || description.type == GarmentType::kOnePiece;
    if (settings_.skirt_length >= 0.0 && has_skirt) {
      if (settings_.skirt_length > 1.0) {
        throw std::invalid_argument("skirt length " + std::to_string(settings_.skirt_length) +
                                    " is outside [0, 1] (0 mini, knee length c_k, 1 long)");
      }
      description.legs.length = settings_.skirt_length;
      description.legs.at_knee = false;
    }
    garments_.emplace_back(description, skeleton, body.shape);
    const auto colour = settings_.garment_colours.find(name);
    const Eigen::Vector4f rgba =
        colour != settings_.garment_colours.end()
            ? colour->second
            : Eigen::Vector4f(static_cast<float>(description.colour.x()), static_cast<float>(description.colour.y()),
                              static_cast<float>(description.colour.z()), 1.0f);
    addPart(name, ReliefKind::kCloth, rgba, garments_.size() - 1);
  }
  std::vector<BezierPatch> cloth;
  for (const DressedGarment& dressed : garments_) {
    cloth.insert(cloth.end(), dressed.rest_patches.begin(), dressed.rest_patches.end());
  }
  if (!cloth.empty()) cloth_patch_size_ = typicalPatchSize(cloth);
  std::vector<const std::vector<BezierPatch>*> rest{&skin_.patches()};  // built in the same rest pose
  for (const DressedGarment& dressed : garments_) rest.push_back(&dressed.rest_patches);
  covered_ = sharedCoveredPatches(rest);
  calibrateErrorBounds(skeleton, body.shape);
}

void HumanModel::calibrateErrorBounds(const Skeleton& skeleton, const BodyShape& shape) {
  const std::vector<BezierPatch> skin_rest = skin_.patches();
  std::vector<std::vector<std::vector<BezierPatch>>> posed(parts_.size());  // per part, per pose
  if (!settings_.calibration_poses.empty()) {
    const ForwardKinematics kinematics(skeleton, shape);
    SkeletonPose pose;
    for (const JointAngles& angles : settings_.calibration_poses) {
      kinematics.compute(RigidTransform(), angles, pose);
      poseSurfaces(pose.root, pose.bone_in_world);
      for (std::size_t p = 0; p < parts_.size(); ++p) posed[p].push_back(partPatches(p));
    }
    skin_.poseAtRest();
    JointAngles zero;
    zero.fill(0.0);
    kinematics.compute(RigidTransform(), zero, pose);
    for (DressedGarment& dressed : garments_) dressed.garment.pose(pose);
  }
  for (std::size_t p = 0; p < parts_.size(); ++p) {
    const std::optional<std::size_t>& garment = part_states_[p].garment;
    part_states_[p].error_bound =
        CalibratedErrorBound::shared(garment ? garments_[*garment].rest_patches : skin_rest, posed[p]);
  }
}

void HumanModel::addPart(const std::string& name, ReliefKind relief, const Eigen::Vector4f& colour,
                         std::optional<std::size_t> garment) {
  SurfacePart part;
  part.name = name;
  part.relief = relief;
  part.colour = colour;
  part.mesh = nullptr;
  parts_.push_back(std::move(part));
  part_states_.emplace_back();
  part_states_.back().garment = garment;
}

void HumanModel::setSkinCellSize(double forearm_cell_spacing) {
  skin_tiling_.setForearmCellSpacing(forearm_cell_spacing);
  ++skin_tiles_id_;
}

double HumanModel::reliefFeatureSize(ReliefKind kind) const {
  if (kind == ReliefKind::kSkin) return skin_tiling_.largestCellSpacing();
  return cloth_patch_size_ / (2.0 * garmentWrinkleMapSpec().cells_around * kFoldTilesPerPatch);
}

Eigen::AlignedBox3f HumanModel::bounds() const {
  Eigen::AlignedBox3f box;
  for (const SurfacePart& part : parts_) {
    if (part.mesh != nullptr && !part.bounds.isEmpty()) box.extend(part.bounds);
  }
  return box;
}

HumanModel::DressedGarment::DressedGarment(const GarmentDescription& description, const Skeleton& skeleton,
                                           const BodyShape& shape)
    : garment(description, skeleton, shape), rest_patches(garment.patches()) {}

const std::vector<BezierPatch>& HumanModel::partPatches(std::size_t part) const {
  const std::optional<std::size_t>& garment = part_states_.at(part).garment;
  return garment ? garments_[*garment].garment.patches() : skin_.patches();
}

const PatchTopology& HumanModel::topologyOf(const PartState& state) const {
  return state.garment ? garments_[*state.garment].garment.topology() : skin_.topology();
}

const CalibratedErrorBound& HumanModel::partErrorBound(std::size_t part) const {
  return *part_states_.at(part).error_bound;
}

const std::vector<int>& HumanModel::partLevels(std::size_t part) const {
  return part_states_.at(part).tessellator->levels();
}

void HumanModel::update(const RigidTransform& root, const std::array<RigidTransform, kBoneCount>& bones,
                        const LevelOfDetail& lod) {
  poseSurfaces(root, bones);
  for (std::size_t p = 0; p < parts_.size(); ++p) {
    PartState& state = part_states_[p];
    const bool displaced = displacements_[static_cast<std::size_t>(parts_[p].relief)].map != nullptr;
    const bool cpu_vertices = vertex_evaluation_ == VertexEvaluation::kCpu || displaced;
    const std::vector<int>& levels = withCoveredHidden(p, chooseLevels(state, partPatches(p), lod), lod.hide_covered);
    tessellate(p, levels, cpu_vertices);
    if (state.garment) {
      measureWrinkles(garments_[*state.garment], parts_[p], cpu_vertices, displaced);
    }
    displaceAndBound(p, levels);
  }
}

void HumanModel::poseSurfaces(const RigidTransform& root, const std::array<RigidTransform, kBoneCount>& bones) {
  pose_.root = root;
  pose_.bone_in_world = bones;
  skin_.pose(pose_);
  for (DressedGarment& dressed : garments_) dressed.garment.pose(pose_);
}

const std::vector<int>& HumanModel::chooseLevels(PartState& state, const std::vector<BezierPatch>& patches,
                                                 const LevelOfDetail& lod) {
  if (lod.automatic) {
    // Levels from the screen-space error, with hysteresis: a level drops only when two below
    // the current one would do. Otherwise a walking human flickers between levels and the
    // tessellator rebuilds its layout every frame instead of only re-evaluating vertices.
    std::vector<int>& levels = state.automatic.levels;
    levels.resize(patches.size(), 0);
    state.automatic.frames_below.resize(patches.size(), 0);
    const bool coarse_steps = vertex_evaluation_ == VertexEvaluation::kGpu;
    state.error_bound->levelsForScreenError(patches, lod.camera, lod.max_error_pixels, lod.max_level, wanted_levels_);
    for (std::size_t p = 0; p < patches.size(); ++p) {
      const int wanted = wanted_levels_[p];
      if (coarse_steps) {
        // When the renderer evaluates the vertices, a frame costs the CPU almost nothing unless
        // the layout changes, and a few more triangles cost the vertex shader little. So levels
        // move on a coarse ladder (rounded up: the error bound still holds), rise at once, and
        // drop only after two rungs less have sufficed for kDropAfterUpdates updates in a row:
        // longer than a gait cycle, so a walking human keeps its layout.
        const int rung = ladderRung(wanted);
        const int current = levels[p] == 0 ? -1 : ladderRung(levels[p]);
        int& below = state.automatic.frames_below[p];
        below = rung + 1 < current ? below + 1 : 0;
        if (rung > current || below > kDropAfterUpdates) {
          levels[p] = std::min(kLevelLadder[static_cast<std::size_t>(rung)], lod.max_level);
          below = 0;
        }
      } else if (wanted > levels[p] || wanted < levels[p] - 1) {
        levels[p] = wanted;
      }
    }
    return levels;
  }
  if (lod.level < 1 || lod.level > Tessellator::kMaxLevel) {
    throw std::invalid_argument("tessellation level " + std::to_string(lod.level) + " is outside [1, " +
                                std::to_string(Tessellator::kMaxLevel) + "]");
  }
  uniform_levels_.assign(patches.size(), lod.level);
  return uniform_levels_;
}

// Covered patches (LevelOfDetail::hide_covered) drop to level 1 and are marked hidden.
const std::vector<int>& HumanModel::withCoveredHidden(std::size_t part, const std::vector<int>& levels, bool hide) {
  const std::vector<bool>& covered = (*covered_)[part];
  hide = hide && std::find(covered.begin(), covered.end(), true) != covered.end();
  parts_[part].hidden_patches = hide ? &covered : nullptr;
  if (!hide) return levels;
  drawn_levels_ = levels;
  for (std::size_t k = 0; k < covered.size(); ++k) {
    if (covered[k]) drawn_levels_[k] = 1;
  }
  return drawn_levels_;
}

void HumanModel::tessellate(std::size_t p, const std::vector<int>& levels, bool cpu_vertices) {
  PartState& state = part_states_[p];
  SurfacePart& part = parts_[p];
  const std::vector<BezierPatch>& patches = partPatches(p);
  Tessellator& tessellator = *state.tessellator;
  part.mesh = cpu_vertices ? &tessellator.tessellate(patches, topologyOf(state), levels)
                           : &tessellator.layout(patches, topologyOf(state), levels);
  part.drawn_triangles = part.mesh->triangleCount();
  if (part.hidden_patches != nullptr) {
    for (const std::uint32_t patch : part.mesh->triangle_patch) {
      part.drawn_triangles -= (*part.hidden_patches)[patch] ? 1 : 0;
    }
  }
  if (cpu_vertices) {
    part.vertices = CpuVertices{};
  } else {
    part.vertices = GpuVertices{};
  }
  part.patches = &patches;
  part.layout_id = tessellator.layoutId();
  if (state.corners.layout_id != part.layout_id) {
    splitPatchCorners(*part.mesh, tessellator.triangleCornerParameters(), state.corners.split);
    state.corners.layout_id = part.layout_id;
  }
  part.corners = &state.corners.split;
  if (!state.garment) {
    part.relief_tiles = &skin_tiling_.tilesPerPatch();
    part.relief_tiles_id = skin_tiles_id_;
  }
}

void HumanModel::measureWrinkles(DressedGarment& dressed, SurfacePart& part, bool cpu_vertices, bool displaced) {
  VertexCompression& compression = dressed.compression;
  // The rest metric belongs to the layout: re-derived only when the tessellator laid the mesh
  // out anew (comparing layouts vertex by vertex every frame would cost more than the rest of a
  // GPU-evaluated frame).
  if (dressed.compressed_layout != part.layout_id) {
    compression.prepare(*part.mesh, dressed.rest_patches);
    dressed.compressed_layout = part.layout_id;
  }
  // Coordinates solved before a pause would hold the folds of another pose: start over.
  if (!wrinkles_wanted_) dressed.fold_coordinates.restart();
  if (!cpu_vertices) {
    part.vertices = GpuVertices{&compression.inverseRestMetric(), compression.strengthConstants()};
    if (wrinkles_wanted_) solveFoldCoordinates(dressed, part);
  } else if (wrinkles_wanted_ || displaced) {
    dressed.wrinkle_weights.resize(part.mesh->vertexCount());
    dressed.fold_axes.resize(part.mesh->vertexCount());
    compression.evaluate(*part.mesh, nullptr, dressed.wrinkle_weights.data(), dressed.fold_axes.data());
    part.vertices = CpuVertices{&dressed.wrinkle_weights, &dressed.fold_axes};
    if (wrinkles_wanted_) solveFoldCoordinates(dressed, part);
  }
}

void HumanModel::solveFoldCoordinates(DressedGarment& dressed, SurfacePart& part) {
  const std::vector<BezierPatch>& patches = dressed.garment.patches();
  dressed.grid_levels.resize(patches.size(), FoldCoordinates::kGridLevel);
  const TriangleMesh& grid =
      dressed.grid_tessellator->tessellate(patches, dressed.garment.topology(), dressed.grid_levels);
  if (!dressed.fold_coordinates.prepared()) {
    splitPatchCorners(grid, dressed.grid_tessellator->triangleCornerParameters(), dressed.grid_split);
    dressed.grid_compression.prepare(grid, dressed.rest_patches);
    dressed.fold_coordinates.prepare(grid, dressed.grid_split);
  }
  dressed.grid_strengths.resize(grid.vertexCount());
  dressed.grid_axes.resize(grid.vertexCount());
  dressed.grid_compression.evaluate(grid, nullptr, dressed.grid_strengths.data(), dressed.grid_axes.data());
  dressed.fold_coordinates.solve(dressed.grid_axes, dressed.grid_strengths);
  // The mesh's vertex_patch and uv: filled by tessellate() and by layout() alike.
  dressed.fold_coordinates.sample(*part.mesh, dressed.fold_tiles, dressed.fold_directions);
  std::visit(
      [&](auto& vertices) {
        vertices.fold_tile = &dressed.fold_tiles;
        vertices.fold_direction = &dressed.fold_directions;
      },
      part.vertices);
}

void HumanModel::displaceAndBound(std::size_t p, const std::vector<int>& levels) {
  SurfacePart& part = parts_[p];
  const Displacement& displacement = displacements_[static_cast<std::size_t>(part.relief)];
  if (!displacement.map) {
    part.bounds = controlPointBounds(*part.patches);
    return;
  }
  ReliefDisplacement settings = displacement.settings;
  settings.patch_tiles = part.relief_tiles;
  const CpuVertices& vertices = std::get<CpuVertices>(part.vertices);  // displaced: always evaluated here
  settings.weights = vertices.relief_weight;
  settings.fold_axes = vertices.fold_axis;
  settings.fold_tiles = vertices.fold_tile;
  settings.fold_directions = vertices.fold_direction;
  settings.patch_levels = &levels;
  TriangleMesh& displaced = part_states_[p].displaced;
  displaceMesh(*part.mesh, settings, displaced);
  part.mesh = &displaced;
  part.bounds = vertexBounds(part.mesh->positions);
}

void HumanModel::setDisplacement(ReliefKind kind, std::shared_ptr<const ReliefMap> map, float tiling,
                                 float height_to_tile, float amplitude, std::shared_ptr<const FoldTiles> folds) {
  Displacement& current = displacements_[static_cast<std::size_t>(kind)];
  Displacement displacement{std::move(map), std::move(folds), nullptr, nullptr,
                            ReliefDisplacement{nullptr, tiling, height_to_tile, amplitude}};
  if (displacement.map) {  // the chains again only for another map (a few ms at 512 x 512)
    displacement.map_mips = displacement.map == current.map
                                ? current.map_mips
                                : std::make_shared<const std::vector<ReliefMap>>(buildMipChain(*displacement.map));
  }
  if (displacement.map && displacement.folds) {
    displacement.fold_mips = displacement.folds == current.folds
                                 ? current.fold_mips
                                 : std::make_shared<const FoldTileMips>(buildFoldTileMips(*displacement.folds));
  }
  displacement.settings.map = displacement.map.get();
  displacement.settings.folds = displacement.map ? displacement.folds.get() : nullptr;
  displacement.settings.map_mips = displacement.map_mips.get();
  displacement.settings.fold_mips = displacement.settings.folds ? displacement.fold_mips.get() : nullptr;
  if (displacement.map) {  // now, not at the next update (the chains are built right here; levels come then)
    ReliefDisplacement given = displacement.settings;
    given.map_mips = nullptr;
    given.fold_mips = nullptr;
    checkReliefDisplacement(given);
  }
  displacements_[static_cast<std::size_t>(kind)] = std::move(displacement);
}

std::size_t HumanModel::drawnTriangleCount() const {
  std::size_t count = 0;
  for (const SurfacePart& part : parts_) count += part.mesh ? part.drawn_triangles : 0;
  return count;
}

std::size_t HumanModel::triangleCount() const {
  std::size_t count = 0;
  for (const SurfacePart& part : parts_) count += part.mesh ? part.mesh->triangleCount() : 0;
  return count;
}

}  // namespace dressed_human
