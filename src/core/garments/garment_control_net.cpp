#include "dressed_human/core/garments/garment_control_net.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

namespace dressed_human {

const char* controlPointKindName(ControlPointKind kind) {
  switch (kind) {
    case ControlPointKind::kShape:
      return "shape";
    case ControlPointKind::kBoundaryMidpoint:
      return "boundary midpoint";
    case ControlPointKind::kCornerMidpoint:
      return "corner midpoint";
    case ControlPointKind::kTangentProjection:
      return "tangent projection";
  }
  return "?";
}

std::array<std::uint32_t, 4> edgeIndices(const GarmentControlNet::PatchIndices& patch, PatchEdge edge) {
  std::array<std::uint32_t, 4> out{};
  for (int t = 0; t < 4; ++t) {
    switch (edge) {
      case PatchEdge::kV0:
        out[t] = patch[BezierPatch::index(t, 0)];
        break;
      case PatchEdge::kV1:
        out[t] = patch[BezierPatch::index(t, 3)];
        break;
      case PatchEdge::kU0:
        out[t] = patch[BezierPatch::index(0, t)];
        break;
      case PatchEdge::kU1:
        out[t] = patch[BezierPatch::index(3, t)];
        break;
    }
  }
  return out;
}

void GarmentControlNet::addRule(const ControlPointRule& rule) {
  rules_.push_back(rule);
  world_.push_back(Eigen::Vector3d::Zero());
}

std::uint32_t GarmentControlNet::addShape(const ShapeAttachment& attachment, const std::string& piece) {
  if (!attachment.local.allFinite() || !attachment.lower_vector.allFinite() ||
      !std::isfinite(attachment.lower_weight)) {
    throw std::invalid_argument("garment control net: non-finite shape point in " + piece);
  }
  ControlPointRule rule;
  rule.kind = ControlPointKind::kShape;
  rule.attachment = attachment;
  rule.piece = piece;
  addRule(rule);
  return static_cast<std::uint32_t>(rules_.size() - 1);
}

std::uint32_t GarmentControlNet::addMidpoint(ControlPointKind kind, std::uint32_t a, std::uint32_t b,
                                             const std::string& piece) {
  if (kind != ControlPointKind::kBoundaryMidpoint && kind != ControlPointKind::kCornerMidpoint) {
    throw std::invalid_argument("garment control net: addMidpoint needs a midpoint kind");
  }
  if (a >= rules_.size() || b >= rules_.size()) {
    throw std::invalid_argument("garment control net: midpoint source does not exist yet");
  }
  ControlPointRule rule;
  rule.kind = kind;
  rule.sources = {a, b};
  rule.piece = piece;
  addRule(rule);
  return static_cast<std::uint32_t>(rules_.size() - 1);
}

std::uint32_t GarmentControlNet::addTangentProjection(std::uint32_t point, std::uint32_t plane_point, int plane_frame,
                                                      const std::string& piece) {
  if (point >= rules_.size() || plane_point >= rules_.size()) {
    throw std::invalid_argument("garment control net: projection source does not exist yet");
  }
  ControlPointRule rule;
  rule.kind = ControlPointKind::kTangentProjection;
  rule.sources = {point, plane_point};
  rule.plane_frame = plane_frame;
  rule.piece = piece;
  addRule(rule);
  return static_cast<std::uint32_t>(rules_.size() - 1);
}

std::uint32_t GarmentControlNet::addPatch(const PatchIndices& indices, const std::string& piece) {
  for (std::uint32_t index : indices) {
    if (index >= rules_.size()) throw std::invalid_argument("garment control net: patch uses an unknown point");
  }
  patch_indices_.push_back(indices);
  patch_pieces_.push_back(piece);
  finished_ = false;
  return static_cast<std::uint32_t>(patch_indices_.size() - 1);
}

void GarmentControlNet::finish() {
  topology_ = PatchTopology(patch_indices_.size());
  // Key: the edge's point indices in ascending-parameter order; an edge meeting the same points
  // reversed is the same curve run backwards.
  std::map<std::array<std::uint32_t, 4>, std::pair<std::uint32_t, PatchEdge>> open;
  constexpr PatchEdge kEdges[4] = {PatchEdge::kV0, PatchEdge::kU1, PatchEdge::kV1, PatchEdge::kU0};
  for (std::uint32_t p = 0; p < patch_indices_.size(); ++p) {
    for (PatchEdge edge : kEdges) {
      const std::array<std::uint32_t, 4> key = edgeIndices(patch_indices_[p], edge);
      if (key[0] == key[1] && key[1] == key[2] && key[2] == key[3]) continue;  // a pole
      const std::array<std::uint32_t, 4> reversed = {key[3], key[2], key[1], key[0]};
      auto same = open.find(key);
      auto back = open.find(reversed);
      if (same != open.end()) {
        topology_.link(same->second.first, same->second.second, p, edge, false);
        open.erase(same);
      } else if (back != open.end()) {
        topology_.link(back->second.first, back->second.second, p, edge, true);
        open.erase(back);
      } else {
        open[key] = {p, edge};
      }
    }
  }
  finished_ = true;
}

int GarmentControlNet::bone(std::uint32_t point) const {
  const std::vector<std::uint32_t> shapes = shapeSources(point);
  int common = rules_.at(shapes.front()).attachment.bone;
  for (std::uint32_t s : shapes) {
    const ShapeAttachment& a = rules_[s].attachment;
    if (a.bone != common || (a.lower_weight != 0.0 && a.lower_bone != common && shapes.size() > 1)) {
      return kSeveralBones;
    }
  }
  return common;
}

std::vector<std::uint32_t> GarmentControlNet::shapeSources(std::uint32_t point) const {
  std::set<std::uint32_t> found;
  std::vector<std::uint32_t> stack = {point};
  while (!stack.empty()) {
    const std::uint32_t p = stack.back();
    stack.pop_back();
    const ControlPointRule& rule = rules_.at(p);
    if (rule.kind == ControlPointKind::kShape) {
      found.insert(p);
    } else {
      stack.push_back(rule.sources[0]);
      stack.push_back(rule.sources[1]);
    }
  }
  return std::vector<std::uint32_t>(found.begin(), found.end());
}

std::vector<std::uint32_t> GarmentControlNet::shapePoints() const {
  std::vector<std::uint32_t> out;
  for (std::uint32_t p = 0; p < rules_.size(); ++p) {
    if (rules_[p].kind == ControlPointKind::kShape) out.push_back(p);
  }
  return out;
}

void GarmentControlNet::setShapeLocal(std::uint32_t point, const Eigen::Vector3d& local) {
  if (point >= rules_.size() || rules_[point].kind != ControlPointKind::kShape) {
    throw std::invalid_argument("garment control net: point " + std::to_string(point) +
                                " is not a shape point; only shape points can be set");
  }
  if (!local.allFinite()) throw std::invalid_argument("garment control net: non-finite shape point");
  rules_[point].attachment.local = local;
}

void GarmentControlNet::pose(const SkeletonPose& pose) {
  if (!finished_) finish();
  auto frame = [&](int bone) -> const RigidTransform& {
    return bone == kRootFrame ? pose.root : pose.bone_in_world.at(static_cast<std::size_t>(bone));
  };
  for (std::size_t p = 0; p < rules_.size(); ++p) {
    const ControlPointRule& rule = rules_[p];
    switch (rule.kind) {
      case ControlPointKind::kShape: {
        const ShapeAttachment& a = rule.attachment;
        const RigidTransform& t = frame(a.bone);
        Eigen::Vector3d w = t.rotation * a.local + t.translation;
        if (a.lower_weight != 0.0) w += a.lower_weight * (frame(a.lower_bone).rotation * a.lower_vector);
        world_[p] = w;
        break;
      }
      case ControlPointKind::kTangentProjection: {
        const Eigen::Vector3d n = frame(rule.plane_frame).rotation * Eigen::Vector3d::UnitZ();
        const Eigen::Vector3d& x = world_[rule.sources[0]];
        world_[p] = x - (x - world_[rule.sources[1]]).dot(n) * n;
        break;
      }
      default:
        world_[p] = 0.5 * (world_[rule.sources[0]] + world_[rule.sources[1]]);
        break;
    }
  }
  patches_.clear();
  patches_.reserve(patch_indices_.size());
  for (const PatchIndices& indices : patch_indices_) {
    BezierPatch::ControlPoints points;
    for (int k = 0; k < 16; ++k) points[k] = world_[indices[k]];
    patches_.emplace_back(points);
  }
}

}  // namespace dressed_human
