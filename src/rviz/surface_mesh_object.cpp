#include "surface_mesh_object.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace dressed_human {

SurfaceMeshObject::SurfaceMeshObject(Ogre::SceneManager* scene_manager, Ogre::SceneNode* parent,
                                     const std::string& material)
    : scene_manager_(scene_manager), object_(scene_manager->createManualObject()), material_(material) {
  object_->setDynamic(true);
  parent->attachObject(object_);
}

SurfaceMeshObject::~SurfaceMeshObject() { scene_manager_->destroyManualObject(object_); }

void SurfaceMeshObject::setMaterial(const std::string& material) {
  material_ = material;
  if (object_->getSections().size() > 0) object_->setMaterialName(0, material_);
}

bool SurfaceMeshObject::beginFilling(std::size_t vertices, std::size_t indices, VertexAttributes attributes) {
  if (vertices == 0 || indices == 0) {
    object_->clear();
    vertex_count_ = index_count_ = 0;
    attributes_ = VertexAttributes::kNone;
    return false;
  }
  if (object_->getSections().size() == 1 && attributes == attributes_) {
    // Same section, new data: Ogre keeps the hardware buffers while they are large enough and
    // grows them otherwise, so level-of-detail and relief-mode changes stop reallocating once
    // the largest mesh has been seen. Other vertex attributes (lit per vertex or not) need a
    // section of their own.
    object_->beginUpdate(0);
    if (vertices > vertex_count_ || indices > index_count_) ++rebuild_count_;
  } else {
    object_->clear();
    vertex_count_ = index_count_ = 0;  // the new section's buffers hold nothing yet
    object_->begin(material_, Ogre::RenderOperation::OT_TRIANGLE_LIST, "dressed_human");
    attributes_ = attributes;
    ++rebuild_count_;
  }
  vertex_count_ = std::max(vertex_count_, vertices);
  index_count_ = std::max(index_count_, indices);
  return true;
}

void SurfaceMeshObject::setBounds(const Eigen::AlignedBox3f& bounds) {
  if (object_->getSections().size() != 1 || bounds.isEmpty()) return;
  // Every frame, in both vertex modes. ManualObject only ever grows its box while vertices are
  // written (never when the GPU moves them), and the scene node caches its world box until it is
  // told: without both steps the human is culled by where it once was.
  object_->setBoundingBox(Ogre::AxisAlignedBox(bounds.min().x(), bounds.min().y(), bounds.min().z(), bounds.max().x(),
                                               bounds.max().y(), bounds.max().z()));
  object_->getParentSceneNode()->needUpdate();
}

void SurfaceMeshObject::addTriangles(const std::vector<std::uint32_t>& indices, const TriangleMesh& mesh,
                                     const std::vector<bool>* hidden_patches) {
  if (hidden_patches == nullptr) {
    for (const std::uint32_t index : indices) object_->index(index);
    return;
  }
  if (mesh.triangle_patch.size() * 3 != indices.size()) {
    throw std::invalid_argument("mesh with " + std::to_string(indices.size()) + " triangle corners has " +
                                std::to_string(mesh.triangle_patch.size()) + " triangle patches");
  }
  for (std::size_t t = 0; t < mesh.triangle_patch.size(); ++t) {
    const std::uint32_t patch = mesh.triangle_patch[t];
    if (patch >= hidden_patches->size()) {
      throw std::invalid_argument("triangle on patch " + std::to_string(patch) + " of " +
                                  std::to_string(hidden_patches->size()) + " hidden-patch flags");
    }
    if ((*hidden_patches)[patch]) continue;
    for (std::size_t c = 3 * t; c < 3 * t + 3; ++c) object_->index(indices[c]);
  }
}

Eigen::Vector2f SurfaceMeshObject::reliefCoordinate(const TriangleMesh& mesh, const ReliefTexturing& texturing,
                                                    std::size_t i) {
  const PatchCornerSplit* corners = texturing.corners;
  const Eigen::Vector2f& uv = corners ? corners->uv[i] : mesh.uv[i];
  if (texturing.tiles == nullptr) return uv;
  const std::uint32_t patch = corners ? corners->patch[i] : mesh.vertex_patch[i];
  return uv.cwiseProduct((*texturing.tiles)[patch]);
}

void SurfaceMeshObject::update(const TriangleMesh& mesh, const ReliefTexturing& texturing,
                               const CpuVertices& vertex_data, const std::vector<bool>* hidden_patches,
                               const Eigen::AlignedBox3f& bounds, bool lit_per_vertex) {
  const std::vector<float>* relief_weight = vertex_data.relief_weight;
  const std::vector<Eigen::Vector2f>* fold_axis = vertex_data.fold_axis;
  const std::vector<Eigen::Vector2f>* fold_tile = vertex_data.fold_tile;
  const std::vector<Eigen::Vector2f>* fold_direction = vertex_data.fold_direction;
  layout_id_ = 0;
  const std::size_t vertices = mesh.positions.size();
  const auto count_of = [vertices](const auto* values) { return values ? values->size() : vertices; };
  if (count_of(relief_weight) != vertices || count_of(fold_axis) != vertices || count_of(fold_tile) != vertices ||
      count_of(fold_direction) != vertices || (fold_tile == nullptr) != (fold_direction == nullptr)) {
    throw std::invalid_argument("mesh with " + std::to_string(vertices) + " vertices has " +
                                std::to_string(count_of(relief_weight)) + " relief weights, " +
                                std::to_string(count_of(fold_axis)) + " fold axes, " +
                                (fold_tile ? std::to_string(fold_tile->size()) : std::string("no")) +
                                " fold tile coordinates and " +
                                (fold_direction ? std::to_string(fold_direction->size()) : std::string("no")) +
                                " fold directions");
  }
  // Lit per vertex, the relief is not drawn: no corner split, no texturing to check or send.
  const PatchCornerSplit* corners = lit_per_vertex ? nullptr : texturing.corners;
  if (!lit_per_vertex) checkTexturing(mesh, texturing);
  const std::vector<std::uint32_t>& indices = corners ? corners->indices : mesh.indices;
  const std::size_t count = corners ? corners->source.size() : vertices;
  if (!beginFilling(count, indices.size(), lit_per_vertex ? VertexAttributes::kShading : VertexAttributes::kRelief))
    return;
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t v = corners ? corners->source[i] : static_cast<std::uint32_t>(i);
    const Eigen::Vector3f& p = mesh.positions[v];
    const Eigen::Vector3f& n = mesh.normals[v];
    object_->position(p.x(), p.y(), p.z());
    object_->normal(n.x(), n.y(), n.z());
    if (lit_per_vertex) continue;
    const Eigen::Vector3f& t = mesh.tangents_u[v];
    // Folds laid by their coordinates (FoldCoordinates): the tile coordinate instead of the patch's
    // (u, v), the folds' signed direction instead of their axis (relief_surface.frag, FOLD_COORDINATES).
    const Eigen::Vector2f uv = fold_tile ? (*fold_tile)[v] : reliefCoordinate(mesh, texturing, i);
    object_->tangent(t.x(), t.y(), t.z());
    object_->textureCoord(uv.x(), uv.y());
    const Eigen::Vector2f axis = fold_direction ? (*fold_direction)[v]
                                 : fold_axis    ? (*fold_axis)[v]
                                                : Eigen::Vector2f::Zero();
    object_->textureCoord(relief_weight != nullptr ? (*relief_weight)[v] : 1.0f, axis.x(), axis.y());
  }
  addTriangles(indices, mesh, hidden_patches);
  object_->end();
  setBounds(bounds);
}

void SurfaceMeshObject::updateLayout(const TriangleMesh& layout, const ReliefTexturing& texturing,
                                     const GpuVertices& vertex_data, const std::vector<bool>* hidden_patches,
                                     std::uint64_t layout_id, const Eigen::AlignedBox3f& bounds) {
  const std::vector<Eigen::Vector4f>* inverse_rest_metric = vertex_data.inverse_rest_metric;
  const std::vector<Eigen::Vector2f>* fold_tile = vertex_data.fold_tile;
  const std::vector<Eigen::Vector2f>* fold_direction = vertex_data.fold_direction;
  const PatchCornerSplit* corners = texturing.corners;
  const std::uint64_t tiles = texturing.tiles ? texturing.tiles_id : 0;
  // Fold coordinates change every frame: the layout goes out again with them.
  if (layout_id == 0 || layout_id != layout_id_ || (corners != nullptr) != split_sent_ || tiles != tiles_sent_ ||
      hidden_patches != hidden_sent_ || fold_tile != nullptr || attributes_ == VertexAttributes::kLayoutFolds) {
    const std::size_t vertices = layout.uv.size();
    const auto count_of = [vertices](const auto* values) { return values ? values->size() : vertices; };
    if (layout.vertex_patch.size() != vertices || count_of(inverse_rest_metric) != vertices ||
        count_of(fold_tile) != vertices || count_of(fold_direction) != vertices ||
        (fold_tile == nullptr) != (fold_direction == nullptr)) {
      throw std::invalid_argument("mesh layout with " + std::to_string(vertices) + " vertices has " +
                                  std::to_string(layout.vertex_patch.size()) + " vertex patches, " +
                                  std::to_string(count_of(inverse_rest_metric)) + " rest metrics, " +
                                  (fold_tile ? std::to_string(fold_tile->size()) : std::string("no")) +
                                  " fold tile coordinates and " +
                                  (fold_direction ? std::to_string(fold_direction->size()) : std::string("no")) +
                                  " fold directions");
    }
    checkTexturing(layout, texturing);
    const std::vector<std::uint32_t>& indices = corners ? corners->indices : layout.indices;
    const std::size_t count = corners ? corners->source.size() : vertices;
    if (!beginFilling(count, indices.size(), fold_tile ? VertexAttributes::kLayoutFolds : VertexAttributes::kLayout))
      return;
    for (std::size_t i = 0; i < count; ++i) {
      // The owner's (u, v, patch) for the position, so that copies evaluate to the same bits.
      const std::uint32_t v = corners ? corners->source[i] : static_cast<std::uint32_t>(i);
      object_->position(layout.uv[v].x(), layout.uv[v].y(), static_cast<float>(layout.vertex_patch[v]));
      const Eigen::Vector4f metric = inverse_rest_metric ? (*inverse_rest_metric)[v] : Eigen::Vector4f::Zero();
      object_->textureCoord(metric.x(), metric.y(), metric.z(), metric.w());
      // With fold coordinates, the tile coordinate in place of the relief's (u, v), and the folds'
      // direction (relief_surface.vert, EVALUATE_BEZIER).
      const Eigen::Vector2f uv = fold_tile ? (*fold_tile)[v] : reliefCoordinate(layout, texturing, i);
      object_->textureCoord(uv.x(), uv.y());
      if (fold_direction) object_->textureCoord((*fold_direction)[v].x(), (*fold_direction)[v].y());
    }
    addTriangles(indices, layout, hidden_patches);
    object_->end();
    layout_id_ = layout_id;  // only now: a layout that failed above is tried again next frame
    split_sent_ = corners != nullptr;
    tiles_sent_ = tiles;
    hidden_sent_ = hidden_patches;
  }
  setBounds(bounds);
}

void SurfaceMeshObject::checkTexturing(const TriangleMesh& mesh, const ReliefTexturing& texturing) {
  const std::size_t vertices = mesh.uv.size();
  if (const PatchCornerSplit* corners = texturing.corners) {
    if (corners->uv.size() != corners->source.size() || corners->patch.size() != corners->source.size()) {
      throw std::invalid_argument("corner split with " + std::to_string(corners->source.size()) + " sources has " +
                                  std::to_string(corners->uv.size()) + " uv and " +
                                  std::to_string(corners->patch.size()) + " patches");
    }
    for (const std::uint32_t source : corners->source) {
      if (source >= vertices) {
        throw std::invalid_argument("corner split refers to vertex " + std::to_string(source) + " of a mesh of " +
                                    std::to_string(vertices));
      }
    }
  }
  if (texturing.tiles == nullptr) return;
  const std::vector<std::uint32_t>& patches = texturing.corners ? texturing.corners->patch : mesh.vertex_patch;
  if (!texturing.corners && patches.size() != vertices) {
    throw std::invalid_argument("mesh with " + std::to_string(vertices) + " vertices has " +
                                std::to_string(patches.size()) + " vertex patches");
  }
  for (const std::uint32_t patch : patches) {
    if (patch >= texturing.tiles->size()) {
      throw std::invalid_argument("relief tiles for " + std::to_string(texturing.tiles->size()) +
                                  " patches, a vertex on patch " + std::to_string(patch));
    }
  }
}

}  // namespace dressed_human
