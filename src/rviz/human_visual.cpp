#include "human_visual.h"

#include <cmath>

namespace dressed_human {

HumanVisual::HumanVisual(Ogre::SceneManager* scene_manager, Ogre::SceneNode* parent, const std::string& name_prefix)
    : scene_manager_(scene_manager),
      node_(parent->createChildSceneNode()),
      name_prefix_(name_prefix),
      skeleton_(std::make_unique<SkeletonVisual>(scene_manager, node_)) {}

HumanVisual::~HumanVisual() {
  parts_.clear();
  skeleton_.reset();
  scene_manager_->destroySceneNode(node_);
}

void HumanVisual::update(const std::vector<SurfacePart>& parts) {
  if (parts_.size() > parts.size()) parts_.resize(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const SurfacePart& source = parts[i];
    const bool gpu_vertices = source.gpuVertices() != nullptr;
    if (i == parts_.size() || parts_[i].name != source.name || parts_[i].relief != source.relief ||
        parts_[i].gpu_vertices != gpu_vertices) {
      if (i < parts_.size()) {
        // The replacement's material takes the same name: the old one must be gone first
        // (its mesh before it, which refers to it by that name).
        parts_[i].mesh.reset();
        parts_[i].material.reset();
      }
      Part part;
      part.name = source.name;
      part.relief = source.relief;
      part.gpu_vertices = gpu_vertices;
      part.closed = source.closed;
      part.material = std::make_unique<ReliefMaterial>(name_prefix_ + "/" + source.name, gpu_vertices,
                                                       source.relief == ReliefKind::kCloth);
      part.material->setBackFacesCulled(part.closed || insides_hidden_);
      part.material->setVertexLit(vertex_lit_);
      part.mesh = std::make_unique<SurfaceMeshObject>(scene_manager_, node_, part.material->name());
      part.mesh->setVisible(visible_);
      applyMaps(part);
      if (i == parts_.size()) {
        parts_.push_back(std::move(part));
      } else {
        parts_[i] = std::move(part);
      }
    }
    Part& part = parts_[i];
    if (!part.colour_set || part.colour != source.colour) {
      part.material->setColour(source.colour.x(), source.colour.y(), source.colour.z(), source.colour.w());
      part.colour = source.colour;
      part.colour_set = true;
    }
    // Split shared vertices only where a relief texture is drawn: they cost vertices (+27 % at
    // level 8, +118 % at level 2), and a relief too small to see is not drawn.
    SurfaceMeshObject::ReliefTexturing texturing;
    if (relief_shown_[source.relief]) texturing = {source.corners, source.relief_tiles, source.relief_tiles_id};
    if (const CpuVertices* cpu = source.cpuVertices()) {
      part.mesh->update(*source.mesh, texturing, *cpu, source.hidden_patches, source.bounds,
                        part.material->litPerVertex());
      continue;
    }
    const GpuVertices& gpu = *source.gpuVertices();
    part.material->setPatches(*source.patches);
    // Wrinkles not drawn (too small to see): the vertex shader skips their strength and axis.
    const bool wrinkles = gpu.inverse_rest_metric != nullptr && relief_shown_[ReliefKind::kCloth];
    part.material->setWrinkleStrength(wrinkles ? &gpu.wrinkle_constants : nullptr);
    part.mesh->updateLayout(*source.mesh, texturing, gpu, source.hidden_patches, source.layout_id, source.bounds);
  }
}

void HumanVisual::setVertexLit(bool lit) {
  if (lit == vertex_lit_) return;
  vertex_lit_ = lit;
  for (Part& part : parts_) part.material->setVertexLit(lit);
}

void HumanVisual::setInsidesHidden(bool hidden) {
  if (hidden == insides_hidden_) return;
  insides_hidden_ = hidden;
  for (Part& part : parts_) part.material->setBackFacesCulled(part.closed || hidden);
}

void HumanVisual::setVisible(bool visible) {
  visible_ = visible;
  for (Part& part : parts_) part.mesh->setVisible(visible);
  skeleton_->setVisible(visible_ && skeleton_visible_);
}

void HumanVisual::setSkeletonVisible(bool visible) {
  skeleton_visible_ = visible;
  skeleton_->setVisible(visible_ && skeleton_visible_);
}

void HumanVisual::updateSkeleton(const ForwardKinematics& kinematics,
                                 const std::array<RigidTransform, kBoneCount>& bones) {
  if (skeleton_visible_) skeleton_->update(kinematics, bones);
}

void HumanVisual::setReliefStrength(ReliefKind kind, float strength) {
  relief_strength_[kind] = strength;
  for (Part& part : parts_) {
    if (part.relief == kind) part.material->setReliefStrength(reliefStrength(kind));
  }
}

void HumanVisual::setReliefFade(ReliefKind kind, float fade) {
  float& current = relief_fade_[kind];
  // Every frame otherwise, per part: a constant lookup by name. Steps of 1/200 do not show.
  if (std::abs(fade - current) < 0.005f && (fade > 0.0f) == (current > 0.0f) && (fade < 1.0f) == (current < 1.0f))
    return;
  current = fade;
  for (Part& part : parts_) {
    if (part.relief == kind) part.material->setReliefStrength(reliefStrength(kind));
  }
}

float HumanVisual::reliefStrength(ReliefKind kind) const { return relief_strength_[kind] * relief_fade_[kind]; }

void HumanVisual::setReliefShown(ReliefKind kind, bool shown) {
  relief_shown_[kind] = shown;
  for (Part& part : parts_) {
    if (part.relief == kind) part.material->setReliefShown(shown);
  }
}

void HumanVisual::setNormalMap(const FinishedReliefMap& finished) {
  if (!finished.map) return;  // a failed build: the display reports its error
  const ReliefKind kind = finished.kind;
  maps_[kind] = finished.normal_map;
  for (Part& part : parts_) {
    if (part.relief == kind) applyMaps(part);
  }
}

void HumanVisual::applyMaps(Part& part) const {
  const std::shared_ptr<const EncodedNormalMap>& map = maps_[part.relief];
  part.material->setReliefStrength(reliefStrength(part.relief));
  part.material->setReliefShown(relief_shown_[part.relief]);
  if (map) part.material->setNormalMap(map);
}

}  // namespace dressed_human
