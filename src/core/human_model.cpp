#include "dressed_human/core/human_model.h"

#include <stdexcept>

namespace dressed_human {

HumanModel::HumanModel(const Skeleton& skeleton, const BodyDescription& body, const HumanModelSettings& settings)
    : settings_(settings), skin_(skeleton, body) {
  parts_.push_back({"skin", ReliefKind::kSkin, settings_.skin_colour, nullptr});
}

const TriangleMesh& HumanModel::tessellate(Tessellator& tessellator, const std::vector<BezierPatch>& patches,
                                           const PatchTopology& topology, const LevelOfDetail& lod) {
  if (lod.automatic) {
    // Levels from the screen-space error, with hysteresis: a level drops only when two below
    // the current one would do. Otherwise a walking human flickers between levels and the
    // tessellator rebuilds its layout every frame instead of only re-evaluating vertices.
    std::vector<int>& levels = automatic_levels_[&tessellator];
    levels.resize(patches.size(), 0);
    for (std::size_t p = 0; p < patches.size(); ++p) {
      const int wanted = levelForScreenError(patches[p], lod.camera, lod.max_error_pixels, lod.max_level);
      if (wanted > levels[p] || wanted < levels[p] - 1) levels[p] = wanted;
    }
    return tessellator.tessellate(patches, topology, levels);
  }
  if (lod.level < 1 || lod.level > Tessellator::kMaxLevel) {
    throw std::invalid_argument("tessellation level " + std::to_string(lod.level) + " is outside [1, " +
                                std::to_string(Tessellator::kMaxLevel) + "]");
  }
  return tessellator.tessellateUniform(patches, topology, lod.level);
}

void HumanModel::update(const RigidTransform& root, const std::array<RigidTransform, kBoneCount>& bones,
                        const LevelOfDetail& lod) {
  pose_.root = root;
  pose_.bone_in_world = bones;
  skin_.pose(pose_);
  parts_[0].mesh = &tessellate(skin_tessellator_, skin_.patches(), skin_.topology(), lod);
}

std::size_t HumanModel::triangleCount() const {
  std::size_t count = 0;
  for (const SurfacePart& part : parts_) count += part.mesh ? part.mesh->triangleCount() : 0;
  return count;
}

}  // namespace dressed_human
