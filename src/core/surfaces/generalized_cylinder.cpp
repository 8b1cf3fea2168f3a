#include "dressed_human/core/surfaces/generalized_cylinder.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace dressed_human {

namespace {

// Inner control point offset of a quarter circle as a cubic Bezier: 4 (sqrt 2 - 1) / 3 makes the
// arc's midpoint exact (radial error 2.7e-4 of the radius elsewhere).
const double kQuarterCircleHandle = 4.0 * (std::sqrt(2.0) - 1.0) / 3.0;

// Exact axis directions, so neighbouring quarters share bit-identical end points.
const Eigen::Vector2d kAxisDirection[4] = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}};

// Control point i (0..3) of quarter q of an ellipse of semi-axes (rx, ry) at height z.
Eigen::Vector3d quarterArcPoint(int q, int i, double rx, double ry, double z) {
  const Eigen::Vector2d& start = kAxisDirection[q];
  const Eigen::Vector2d& end = kAxisDirection[(q + 1) % 4];
  Eigen::Vector2d unit;
  switch (i) {
    case 0:
      unit = start;
      break;
    case 1:
      unit = start + kQuarterCircleHandle * end;
      break;  // tangent at start points to end
    case 2:
      unit = end + kQuarterCircleHandle * start;
      break;
    default:
      unit = end;
      break;
  }
  return {rx * unit.x(), ry * unit.y(), z};
}

}  // namespace

PatchSurface makeGeneralizedCylinder(const std::vector<CylinderRing>& rings, double bottom_cap_height,
                                     double top_cap_height) {
  if (rings.size() < 4 || (rings.size() - 1) % 3 != 0) {
    throw std::invalid_argument("makeGeneralizedCylinder: needs 3k + 1 rings (k >= 1), got " +
                                std::to_string(rings.size()));
  }
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const CylinderRing& ring = rings[r];
    if (!std::isfinite(ring.z) || !(ring.radius_x > 0.0) || !(ring.radius_y > 0.0) || !std::isfinite(ring.radius_x) ||
        !std::isfinite(ring.radius_y)) {
      throw std::invalid_argument("makeGeneralizedCylinder: ring " + std::to_string(r) +
                                  " needs a finite z and finite radii > 0");
    }
  }
  for (double height : {bottom_cap_height, top_cap_height}) {
    if (!(height >= 0.0) || !std::isfinite(height)) {
      throw std::invalid_argument("makeGeneralizedCylinder: cap heights must be finite and >= 0");
    }
  }

  const int stacks = static_cast<int>(rings.size() - 1) / 3;
  const bool bottom_cap = bottom_cap_height > 0.0;
  const bool top_cap = top_cap_height > 0.0;
  std::vector<BezierPatch> patches;
  auto add_patch = [&](int q, const CylinderRing(&rows)[4]) {
    BezierPatch::ControlPoints points;
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) {
        points[BezierPatch::index(i, j)] = quarterArcPoint(q, i, rows[j].radius_x, rows[j].radius_y, rows[j].z);
      }
    }
    patches.emplace_back(points);
  };
  for (int s = 0; s < stacks; ++s) {
    const CylinderRing rows[4] = {rings[3 * s], rings[3 * s + 1], rings[3 * s + 2], rings[3 * s + 3]};
    for (int q = 0; q < 4; ++q) add_patch(q, rows);
  }
  // Domes: the rows next to the pole keep the pole's height, so the tangent plane there is flat
  // and the four cap patches share one limit normal at the pole. A zero radius collapses a row.
  const double k = kQuarterCircleHandle;
  auto collapsed_ring = [](double z) { return CylinderRing{z, 0.0, 0.0}; };
  if (bottom_cap) {
    const CylinderRing& end = rings.front();
    const double pole_z = end.z - bottom_cap_height;
    const CylinderRing rows[4] = {collapsed_ring(pole_z),
                                  {pole_z, k * end.radius_x, k * end.radius_y},
                                  {end.z - k * bottom_cap_height, end.radius_x, end.radius_y},
                                  end};
    for (int q = 0; q < 4; ++q) add_patch(q, rows);
  }
  if (top_cap) {
    const CylinderRing& end = rings.back();
    const double pole_z = end.z + top_cap_height;
    const CylinderRing rows[4] = {end,
                                  {end.z + k * top_cap_height, end.radius_x, end.radius_y},
                                  {pole_z, k * end.radius_x, k * end.radius_y},
                                  collapsed_ring(pole_z)};
    for (int q = 0; q < 4; ++q) add_patch(q, rows);
  }

  PatchTopology topology(patches.size());
  auto side = [](int s, int q) { return static_cast<std::uint32_t>(4 * s + q); };
  const std::uint32_t bottom_first = static_cast<std::uint32_t>(4 * stacks);
  const std::uint32_t top_first = bottom_first + (bottom_cap ? 4u : 0u);
  for (int q = 0; q < 4; ++q) {
    const int next = (q + 1) % 4;
    for (int s = 0; s < stacks; ++s) {
      topology.link(side(s, q), PatchEdge::kU1, side(s, next), PatchEdge::kU0, false);
      if (s + 1 < stacks) topology.link(side(s, q), PatchEdge::kV1, side(s + 1, q), PatchEdge::kV0, false);
    }
    if (bottom_cap) {
      topology.link(bottom_first + q, PatchEdge::kU1, bottom_first + next, PatchEdge::kU0, false);
      topology.link(bottom_first + q, PatchEdge::kV1, side(0, q), PatchEdge::kV0, false);
    }
    if (top_cap) {
      topology.link(top_first + q, PatchEdge::kU1, top_first + next, PatchEdge::kU0, false);
      topology.link(side(stacks - 1, q), PatchEdge::kV1, top_first + q, PatchEdge::kV0, false);
    }
  }
  return PatchSurface{std::move(patches), std::move(topology)};
}

PatchSurface makeBulgingCapsule() {
  return makeGeneralizedCylinder({{0.0, 0.10, 0.08},
                                  {0.10, 0.14, 0.10},
                                  {0.20, 0.05, 0.05},
                                  {0.30, 0.06, 0.05},
                                  {0.40, 0.07, 0.06},
                                  {0.50, 0.03, 0.035},
                                  {0.60, 0.04, 0.04}},
                                 0.08, 0.03);
}

}  // namespace dressed_human
