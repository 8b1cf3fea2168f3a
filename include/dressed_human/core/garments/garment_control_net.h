// The control net of a garment (SPEC §3, seed paper 000 §3.1-3.2): every control point of every
// patch is one of
//   kShape             a shape-defining point, the only kind a designer sets; it rides on one
//                      bone frame (fixed in it: the garment follows the skeleton, no physics),
//                      or, for a skirt hem, on two (Eq. 8', skirt_length_map.h);
//   kBoundaryMidpoint  on a patch boundary: the midpoint of its two neighbours across the
//                      boundary (the seed's Fig. 3 (b)); this makes the boundary C1;
//   kCornerMidpoint    where two boundaries cross: the midpoint of two boundary midpoints
//                      (the seed's Fig. 3 (c)), so both boundaries stay C1 through the corner;
//   kTangentProjection a shape point (sources[0]) projected onto the plane through a point
//                      (sources[1]) normal to the z axis of frame `plane_frame`: the pants'
//                      8 twist points around the crotch, which makes the crotch G1 (garment.h).
// Derived points are recomputed in world space from their sources in every pose, so every
// internal boundary between regular (4-patch) vertices is C1 by construction, in every pose
// and for any shape points. The one exception is the pants' crotch, where 8 patches meet: there
// the lattice's corner point is a shape point (C) and its 8 diagonal neighbours are tangent
// projections (piece "crotch"); garment.h explains why and what continuity holds there.
#pragma once

#include "dressed_human/core/surfaces/bezier_patch.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/surfaces/tessellation.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace dressed_human {

// Bone index of the root frame "body" (the pelvis centre), which is not one of the 20 bones.
constexpr int kRootFrame = -1;
// "Rides on no single bone": a derived point whose sources ride on different bones.
constexpr int kSeveralBones = -2;

enum class ControlPointKind : std::uint8_t { kShape, kBoundaryMidpoint, kCornerMidpoint, kTangentProjection };
const char* controlPointKindName(ControlPointKind kind);

// Where a shape point sits: local in frame `bone` (Eq. 5 already applied), plus, for a skirt
// hem, lower_weight * (the vector lower_vector of frame lower_bone) (Eq. 8': A_j M P^j).
struct ShapeAttachment {
  int bone = kRootFrame;
  Eigen::Vector3d local = Eigen::Vector3d::Zero();
  int lower_bone = kRootFrame;
  Eigen::Vector3d lower_vector = Eigen::Vector3d::Zero();
  double lower_weight = 0.0;  // 0: fixed in `bone` alone
};

struct ControlPointRule {
  ControlPointKind kind = ControlPointKind::kShape;
  ShapeAttachment attachment;              // kShape only
  std::array<std::uint32_t, 2> sources{};  // midpoints: the two averaged; projection: point, plane point
  int plane_frame = kRootFrame;            // kTangentProjection: the plane's normal is this frame's z
  std::string piece;                       // "torso", "l_sleeve", "skirt", "l_leg", ...
};

class GarmentControlNet {
 public:
  using PatchIndices = std::array<std::uint32_t, 16>;  // BezierPatch::index(i, j) order

  // Building. Sources must already exist; shape points come before anything derived from them.
  std::uint32_t addShape(const ShapeAttachment& attachment, const std::string& piece);
  std::uint32_t addMidpoint(ControlPointKind kind, std::uint32_t a, std::uint32_t b, const std::string& piece);
  // `point` projected onto the plane through `plane_point` normal to frame plane_frame's z axis.
  std::uint32_t addTangentProjection(std::uint32_t point, std::uint32_t plane_point, int plane_frame,
                                     const std::string& piece);
  // Adds a patch; patches whose edges use the same four points (either order) get linked.
  std::uint32_t addPatch(const PatchIndices& indices, const std::string& piece);
  // Links the patches (call once after the last addPatch; pose() calls it if needed).
  void finish();

  // Reading the classification.
  std::size_t pointCount() const { return rules_.size(); }
  const ControlPointRule& rule(std::uint32_t point) const { return rules_.at(point); }
  ControlPointKind kind(std::uint32_t point) const { return rules_.at(point).kind; }
  // The bone a point rides on: its own for shape points (kRootFrame for "body"); for derived
  // points the common bone of the shape points it comes from, or kSeveralBones.
  int bone(std::uint32_t point) const;
  // All shape points a point depends on (itself for a shape point), sorted.
  std::vector<std::uint32_t> shapeSources(std::uint32_t point) const;
  std::vector<std::uint32_t> shapePoints() const;

  // Editing: move a shape point (local coordinates of its bone). Throws std::invalid_argument
  // for a point that is not a shape point.
  void setShapeLocal(std::uint32_t point, const Eigen::Vector3d& local);

  // Posing: world positions of all points, then the patches.
  void pose(const SkeletonPose& pose);
  const std::vector<Eigen::Vector3d>& worldPoints() const { return world_; }
  const std::vector<BezierPatch>& patches() const { return patches_; }
  const std::vector<PatchIndices>& patchIndices() const { return patch_indices_; }
  const std::string& patchPiece(std::size_t patch) const { return patch_pieces_.at(patch); }
  const PatchTopology& topology() const { return topology_; }

 private:
  void addRule(const ControlPointRule& rule);

  std::vector<ControlPointRule> rules_;  // in evaluation order: sources before the points
  std::vector<PatchIndices> patch_indices_;
  std::vector<std::string> patch_pieces_;
  PatchTopology topology_;
  bool finished_ = false;
  std::vector<Eigen::Vector3d> world_;
  std::vector<BezierPatch> patches_;
};

// The indices of an edge's four points, by increasing edge parameter (as edgeControlPoints).
std::array<std::uint32_t, 4> edgeIndices(const GarmentControlNet::PatchIndices& patch, PatchEdge edge);

}  // namespace dressed_human
