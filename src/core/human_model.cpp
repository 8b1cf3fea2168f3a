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
    return tessellator.tessellateForCamera(patches, topology, lod.camera, lod.max_error_pixels, lod.max_level);
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
