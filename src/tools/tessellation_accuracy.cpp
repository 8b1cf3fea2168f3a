// Prints CSV: for uniform and adaptive (geometric error bound) tessellation of two test surfaces,
// the measured max geometric error (mm) against triangle count and tessellation time.
// scripts/chart_tessellation.py turns it into docs/tessellation_speed_vs_accuracy.png.
//
// Surfaces:
//   capsule  one closed generalized cylinder with a bulge, a waist and two domes (16 patches,
//            the test surface of test_tessellation): curvature varies, patch sizes are similar.
//   body     body-like set: a torso-sized capsule, an arm-sized one and five finger-sized ones
//            (112 patches): patch sizes and curvatures vary as much as on the skin.
//   skin     the real skin (config/bodies/default.yaml on urdf/human.urdf) posed at 30 % of the
//            walk (config/motions/walk.yaml): the surface the renderer draws.
// Error: for sample points of every triangle, the distance to the closest point of the
// triangle's patch (Gauss-Newton from the parametric guess). Also printed: the parametric error
// |F(x) - L(x)|, the upper bound that the adaptive criterion controls.
#include "dressed_human/core/surfaces/generalized_cylinder.h"
#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"
#include "dressed_human/core/surfaces/skin.h"
#include "dressed_human/core/surfaces/tessellation.h"
#include "dressed_human/core/surfaces/triangle_samples.h"

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace dressed_human;

namespace {

struct NamedSurface {
  std::string name;
  std::vector<BezierPatch> patches;
  PatchTopology topology;
};

void append(NamedSurface& target, const PatchSurface& part) {
  const auto offset = static_cast<std::uint32_t>(target.patches.size());
  PatchTopology merged(target.patches.size() + part.patches.size());
  for (const EdgeLink& l : target.topology.links()) merged.link(l.patch_a, l.edge_a, l.patch_b, l.edge_b, l.reversed);
  for (const EdgeLink& l : part.topology.links()) {
    merged.link(l.patch_a + offset, l.edge_a, l.patch_b + offset, l.edge_b, l.reversed);
  }
  target.patches.insert(target.patches.end(), part.patches.begin(), part.patches.end());
  target.topology = merged;
}

PatchSurface shiftedCapsule(const std::vector<CylinderRing>& rings, double bottom, double top,
                            const Eigen::Vector3d& offset) {
  const PatchSurface surface = makeGeneralizedCylinder(rings, bottom, top);
  PatchSurface moved{{}, surface.topology};
  for (const BezierPatch& patch : surface.patches) {
    BezierPatch::ControlPoints points = patch.controlPoints();
    for (Eigen::Vector3d& p : points) p += offset;
    moved.patches.emplace_back(points);
  }
  return moved;
}

NamedSurface capsule() {
  NamedSurface s{"capsule", {}, PatchTopology(0)};
  append(s, makeBulgingCapsule());
  return s;
}

NamedSurface body() {
  NamedSurface s{"body", {}, PatchTopology(0)};
  // Torso: 0.55 m, chest and waist.
  append(s, shiftedCapsule({{0.00, 0.16, 0.11},
                            {0.12, 0.17, 0.12},
                            {0.22, 0.14, 0.10},
                            {0.30, 0.13, 0.09},
                            {0.40, 0.15, 0.10},
                            {0.48, 0.17, 0.11},
                            {0.55, 0.15, 0.10}},
                           0.06, 0.05, Eigen::Vector3d::Zero()));
  // Arm: 0.55 m, elbow and wrist.
  append(s, shiftedCapsule({{0.00, 0.045, 0.045},
                            {0.10, 0.05, 0.045},
                            {0.18, 0.04, 0.04},
                            {0.27, 0.035, 0.035},
                            {0.35, 0.04, 0.035},
                            {0.45, 0.03, 0.025},
                            {0.55, 0.025, 0.02}},
                           0.02, 0.02, Eigen::Vector3d(0.3, 0.0, 0.0)));
  // Fingers: 8 cm, 8-10 mm radius.
  for (int f = 0; f < 5; ++f) {
    const double r = 0.008 + 0.0005 * f;
    append(s, shiftedCapsule({{0.00, r, r},
                              {0.02, 1.1 * r, r},
                              {0.04, 0.9 * r, 0.9 * r},
                              {0.05, r, 0.95 * r},
                              {0.06, 0.95 * r, 0.9 * r},
                              {0.07, 0.9 * r, 0.85 * r},
                              {0.08, 0.85 * r, 0.8 * r}},
                             0.004, 0.007, Eigen::Vector3d(0.45 + 0.03 * f, 0.0, 0.0)));
  }
  return s;
}

// The default skin in a walk pose; `root` is the package directory.
NamedSurface skin(const std::string& root) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(root + "/urdf/human.urdf");
  const BodyDescription body = loadBodyDescriptionFile(root + "/config/bodies/default.yaml", skeleton);
  MotionEvaluator walk(loadMotionFile(root + "/config/motions/walk.yaml"));
  JointAngles angles;
  RigidTransform pelvis;
  walk.evaluate(0.3 * walk.motion().period, angles, pelvis);
  SkeletonPose pose;
  ForwardKinematics(skeleton, body.shape).compute(pelvis, angles, pose);
  Skin posed(skeleton, body);
  posed.pose(pose);
  return NamedSurface{"skin", posed.patches(), posed.topology()};
}

// Closest point of the patch to p, from the parametric guess; returns the distance.
double distanceToPatch(const BezierPatch& patch, const Eigen::Vector3d& p, Eigen::Vector2d uv) {
  double best = (patch.position(uv.x(), uv.y()) - p).norm();
  for (int iteration = 0; iteration < 4; ++iteration) {
    const PatchDerivatives d = patch.derivatives(uv.x(), uv.y());
    const Eigen::Vector3d r = d.position - p;
    Eigen::Matrix2d normal_matrix;
    normal_matrix << d.d_du.dot(d.d_du) + r.dot(d.d2_du2), d.d_du.dot(d.d_dv) + r.dot(d.d2_dudv),
        d.d_du.dot(d.d_dv) + r.dot(d.d2_dudv), d.d_dv.dot(d.d_dv) + r.dot(d.d2_dv2);
    const Eigen::Vector2d gradient(d.d_du.dot(r), d.d_dv.dot(r));
    if (std::abs(normal_matrix.determinant()) < 1e-18) break;
    const Eigen::Vector2d next = (uv - normal_matrix.ldlt().solve(gradient)).cwiseMax(0.0).cwiseMin(1.0);
    const double distance = (patch.position(next.x(), next.y()) - p).norm();
    if (!(distance < best)) break;
    best = distance;
    uv = next;
  }
  return best;
}

struct Errors {
  double closest = 0.0;
  double parametric = 0.0;
};

Errors measure(const TriangleMesh& mesh, const Tessellator& tessellator, const std::vector<BezierPatch>& patches) {
  constexpr int kSteps = 3;  // 10 sample points per triangle; the 3 corners carry no error
  Errors errors;
  forEachTriangleSample(mesh, tessellator.triangleCornerParameters(), kSteps, [&](const TriangleSample& sample) {
    if (sample.corner) return;
    const BezierPatch& patch = patches[mesh.triangle_patch[sample.triangle]];
    const double parametric = (sample.on_mesh - patch.position(sample.uv.x(), sample.uv.y())).norm();
    errors.parametric = std::max(errors.parametric, parametric);
    errors.closest = std::max(errors.closest, std::min(parametric, distanceToPatch(patch, sample.on_mesh, sample.uv)));
  });
  return errors;
}

using Clock = std::chrono::steady_clock;

template <typename Tessellate>
void report(const NamedSurface& surface, const char* method, double parameter, Tessellate tessellate) {
  // Layout build: a fresh tessellator.
  const auto build_start = Clock::now();
  Tessellator tessellator;
  tessellate(tessellator);
  const double build_us = std::chrono::duration<double, std::micro>(Clock::now() - build_start).count();
  // Per frame: layout reused; best of several rounds of repeated calls (the machine is shared).
  double frame_us = 1e300;
  for (int round = 0; round < 5; ++round) {
    int calls = 0;
    const auto start = Clock::now();
    double elapsed = 0.0;
    do {
      tessellate(tessellator);
      ++calls;
      elapsed = std::chrono::duration<double, std::micro>(Clock::now() - start).count();
    } while (elapsed < 4000.0);
    frame_us = std::min(frame_us, elapsed / calls);
  }
  const TriangleMesh& mesh = tessellator.mesh();
  const Errors errors = measure(mesh, tessellator, surface.patches);
  std::printf("%s,%s,%.6g,%zu,%zu,%.6g,%.6g,%.3f,%.3f\n", surface.name.c_str(), method, parameter, mesh.triangleCount(),
              mesh.vertexCount(), 1e3 * errors.closest, 1e3 * errors.parametric, frame_us, build_us);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string root = argc > 1 ? argv[1] : ".";
  std::printf(
      "surface,method,parameter,triangles,vertices,max_error_mm,max_parametric_error_mm,"
      "tessellate_us,layout_build_us\n");
  for (const NamedSurface& surface : {capsule(), body(), skin(root)}) {
    for (int level : {1, 2, 3, 4, 5, 6, 8, 10, 12, 16, 20, 24, 32, 40, 48, 64}) {
      if (surface.name == "skin" && level > 32) break;  // ~1/2 M triangles: enough, and slow to measure
      report(surface, "uniform", level,
             [&](Tessellator& t) { t.tessellateUniform(surface.patches, surface.topology, level); });
    }
    // Down to where the finest patches reach Tessellator::kMaxLevel (the uniform sweep's end).
    for (double tolerance_mm : {10.0, 5.0, 2.0, 1.0, 0.5, 0.2, 0.1, 0.05}) {
      if (surface.name == "skin" && tolerance_mm < 0.1) break;
      report(surface, "adaptive", tolerance_mm,
             [&](Tessellator& t) { t.tessellateToError(surface.patches, surface.topology, 1e-3 * tolerance_mm); });
    }
  }
  return 0;
}
