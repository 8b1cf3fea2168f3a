// CalibratedErrorBound (tessellation.h), checked against what the display draws: the mesh
// HumanModel hands the renderer (the tessellator's output with its stitched, crack-free edges
// between patches of different levels, at the levels automatic level of detail picks), measured
// densely against the exact Bezier surface -- not with measuredTessellationError, the ideal-grid
// measurement the bound is calibrated with, which would only check the calibration against itself.
// What README states and this asserts, over the skin and every garment of the three outfits, at
// automatic levels from three distances and two screen heights and at fixed levels 1..8: never
// below any patch's drawn error, and each part's largest bound within 2x of its largest drawn
// error. Calibrated as the display calibrates (at rest and in the shipped walk at 8 phases),
// in poses the calibration has not seen: the walk at other phases, two other walks (the fitted
// CMU capture, the hand-made walk) and the speed gait at its fastest; calibrated at rest alone, in
// four poses of the walk. Single patches' ratios are printed, not asserted against 2x: measured up
// to 4.3x (a level of detail is bounded by a part's worst patches).
#include "dressed_human/core/surfaces/tessellation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dressed_human/core/locomotion/speed_gait.h"
#include "dressed_human/core/model/calibration_poses.h"
#include "dressed_human/core/model/human_model.h"
#include "dressed_human/core/surfaces/skin.h"
#include "garment_test_support.h"
#include "locomotion_test_support.h"

namespace dressed_human {
namespace {

using namespace garment_test;

// One patch as drawn: the largest distance between its drawn triangles and the exact patch, and
// the level those triangles realize.
struct DrawnPatch {
  double error = 0.0;
  // floor(1 / the widest u or v span of its triangles): what the bound's level means (triangles
  // spanning at most 1/n). Not Tessellator::levels(): a level-1 patch promoted to 2 for its
  // stitched edges keeps whole-edge triangles along its unstitched edges.
  int level = Tessellator::kMaxLevel;
};

// Every patch of a drawn part, from what the renderer is handed: the part's mesh, with each
// triangle corner's (u, v) in the triangle's own patch (PatchCornerSplit), so ring triangles
// stitched to a neighbour's finer edge and fans at welded poles are measured where they lie.
// The distance is to the exact patch at the same (u, v), not to the closest surface point: the
// bound bounds that distance (the interpolation error of the patch over a triangle of its
// parameter domain), the relief and normals are mapped by that (u, v), and it is at least the
// closest-point distance, so a bound that holds for it holds for what the eye sees.
// Every triangle is sampled at barycentric steps of 1 / samples_per_side (the calibration's
// measurement takes 4 steps per cell side on the ideal grid): the error in a triangle is a bump
// that vanishes at its corners, and at 12 steps every bound / error ratio of the test below is
// within 1 % of what 24 steps give (measured: the printed ratios change by at most 0.01).
std::vector<DrawnPatch> measureDrawnPatches(const SurfacePart& part, int samples_per_side) {
  const std::vector<BezierPatch>& patches = *part.patches;
  const TriangleMesh& mesh = *part.mesh;
  const PatchCornerSplit& corners = *part.corners;
  std::vector<DrawnPatch> drawn(patches.size());
  std::vector<double> widest_span(patches.size(), 0.0);
  const double step = 1.0 / samples_per_side;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const std::uint32_t k = mesh.triangle_patch[t];
    std::array<Eigen::Vector3d, 3> position;
    std::array<Eigen::Vector2d, 3> uv;
    for (std::size_t c = 0; c < 3; ++c) {
      const std::uint32_t split = corners.indices[3 * t + c];
      position[c] = mesh.positions[corners.source[split]].cast<double>();
      uv[c] = corners.uv[split].cast<double>();
    }
    const Eigen::Vector2d span = uv[0].cwiseMax(uv[1]).cwiseMax(uv[2]) - uv[0].cwiseMin(uv[1]).cwiseMin(uv[2]);
    widest_span[k] = std::max(widest_span[k], span.maxCoeff());
    for (int i = 0; i <= samples_per_side; ++i) {
      for (int j = 0; i + j <= samples_per_side; ++j) {
        const double a = i * step, b = j * step, c = 1.0 - a - b;
        const Eigen::Vector2d at = a * uv[0] + b * uv[1] + c * uv[2];
        const Eigen::Vector3d on_triangle = a * position[0] + b * position[1] + c * position[2];
        drawn[k].error = std::max(drawn[k].error, (patches[k].position(at.x(), at.y()) - on_triangle).norm());
      }
    }
  }
  for (std::size_t k = 0; k < drawn.size(); ++k) {
    // The corners' (u, v) are floats: 1/3 reads 0.33333334.
    if (widest_span[k] > 0.0) drawn[k].level = static_cast<int>(std::floor(1.0 / widest_span[k] + 1e-3));
  }
  return drawn;
}

constexpr int kSamplesPerSide = 12;

HumanModelSettings settingsFor(Outfit outfit, bool posed_calibration) {
  HumanModelSettings settings;
  settings.outfit = outfit;
  settings.garment_directory = sourcePath("config/garments");
  if (posed_calibration) settings.calibration_poses = calibrationPosesFromFile(sourcePath("config/motions/walk.yaml"));
  return settings;
}

// The crowd's walker at its fastest, where knees and hips bend furthest.
std::vector<SkeletonPose> fastGaitPoses(int count) {
  SpeedGait gait = locomotion_test::gait();
  const ForwardKinematics fk(skeleton(), body().shape);
  std::vector<SkeletonPose> poses(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    JointAngles angles{};
    Eigen::Quaterniond pelvis;
    gait.evaluate(static_cast<double>(k) / count, gait.fastestSpeed(), 1.0, angles, pelvis);
    RigidTransform root;
    root.rotation = pelvis;
    root.translation = Eigen::Vector3d(0.0, 0.0, 1.0);
    fk.compute(root, angles, poses[static_cast<std::size_t>(k)]);
  }
  return poses;
}

// Levels of detail as the display sets them: automatic, from a camera at a few distances and
// screen heights (mixed levels up to the default max_level 16, so stitched edges), and fixed levels.
std::vector<std::pair<std::string, LevelOfDetail>> levelsOfDetail() {
  std::vector<std::pair<std::string, LevelOfDetail>> lods;
  for (const double distance : {1.5, 4.0, 12.0}) {
    for (const double screen_height : {600.0, 1440.0}) {
      LevelOfDetail automatic;
      automatic.automatic = true;
      automatic.camera = CameraView{Eigen::Vector3d(distance, 0.5 * distance, 1.4), 0.8, screen_height};
      char name[64];
      std::snprintf(name, sizeof name, "auto %.1f m %.0f px", distance, screen_height);
      lods.emplace_back(name, automatic);
    }
  }
  for (const int level : {1, 2, 3, 4, 6, 8}) {
    LevelOfDetail fixed;
    fixed.level = level;
    lods.emplace_back("level " + std::to_string(level), fixed);
  }
  return lods;
}

// Under a micrometre the drawn error is float rounding of the vertices, not tessellation.
constexpr double kMeasurableError = 1e-6;

struct PartRatios {
  double lowest = 1e300;  // bound / drawn error, over patches with a measurable error
  double highest = 0.0;
  std::size_t patches = 0;
  std::size_t within_two = 0;
  double part_worst_ratio = 0.0;  // in the worst pose: the part's largest bound / its largest drawn error
};

// Adds one pose of one part to `ratios`; every patch's bound must hold.
void compareWithDrawn(const HumanModel& model, std::size_t p, const std::string& lod_name, PartRatios& ratios) {
  const SurfacePart& part = model.parts()[p];
  const std::vector<DrawnPatch> drawn = measureDrawnPatches(part, kSamplesPerSide);
  double worst_drawn = 0.0, worst_bound = 0.0;
  for (std::size_t k = 0; k < drawn.size(); ++k) {
    const double bound = model.partErrorBound(p).bound(k, (*part.patches)[k], drawn[k].level);
    EXPECT_GE(bound + kMeasurableError, drawn[k].error) << part.name << " patch " << k << " level " << drawn[k].level
                                                        << ", " << lod_name << ": bound below the drawn error";
    worst_drawn = std::max(worst_drawn, drawn[k].error);
    worst_bound = std::max(worst_bound, bound);
    if (drawn[k].error < kMeasurableError) continue;
    const double ratio = bound / drawn[k].error;
    ratios.lowest = std::min(ratios.lowest, ratio);
    ratios.highest = std::max(ratios.highest, ratio);
    ++ratios.patches;
    if (ratio <= 2.0) ++ratios.within_two;
  }
  if (worst_drawn > kMeasurableError)
    ratios.part_worst_ratio = std::max(ratios.part_worst_ratio, worst_bound / worst_drawn);
}

// Every part's ratios over `poses`, each outfit and level of detail; every patch's bound must hold.
std::size_t checkOverPoses(const std::vector<SkeletonPose>& poses, bool posed_calibration) {
  std::size_t checked = 0;
  for (const Outfit outfit : {Outfit::kJacketSkirt, Outfit::kJacketPants, Outfit::kOnePiece}) {
    HumanModel model(skeleton(), body(), settingsFor(outfit, posed_calibration));
    EXPECT_EQ(model.partErrorBound(0).margin(), posed_calibration ? CalibratedErrorBound::kPosedMargin
                                                                  : CalibratedErrorBound::kRestMargin);
    for (const auto& [lod_name, lod] : levelsOfDetail()) {
      std::vector<PartRatios> ratios(model.parts().size());
      for (const SkeletonPose& pose : poses) {
        model.update(pose.root, pose.bone_in_world, lod);
        for (std::size_t p = 0; p < model.parts().size(); ++p) compareWithDrawn(model, p, lod_name, ratios[p]);
      }
      for (std::size_t p = 0; p < ratios.size(); ++p) {
        const PartRatios& r = ratios[p];
        const std::string& name = model.parts()[p].name;
        std::printf("%-9s %-19s bound/drawn %.2f..%.2f (%zu of %zu within 2x), part's largest %.2f\n", name.c_str(),
                    lod_name.c_str(), r.lowest, r.highest, r.within_two, r.patches, r.part_worst_ratio);
        // The figure a level of detail lives by: the part's largest bound against its largest error.
        EXPECT_LE(r.part_worst_ratio, 2.0) << name << ", " << lod_name;
        checked += r.patches;
      }
    }
  }
  return checked;
}

// README: the bound "never below the drawn error; each part's largest within 2x of its largest".
TEST(CalibratedErrorBound, CalibratedInTheWalkHoldsForTheDrawnMeshInPosesItHasNotSeen) {
  // Phases k / 2: no calibration pose of the walk, which sit at (k + 1/2) / 8.
  std::vector<SkeletonPose> poses = walkPoses(2, body().shape);
  for (const char* file : {"config/motions/cmu_02_01_fitted.yaml", "config/motions/hand_made_walk.yaml"}) {
    const std::vector<SkeletonPose> other = motionPoses(file, 2, body().shape);
    poses.insert(poses.end(), other.begin(), other.end());
  }
  const std::vector<SkeletonPose> fast = fastGaitPoses(2);
  poses.insert(poses.end(), fast.begin(), fast.end());
  EXPECT_GT(checkOverPoses(poses, true), 40000u);  // patch-poses with a measurable error
}

TEST(CalibratedErrorBound, CalibratedAtRestHoldsForTheDrawnMeshOverAWalk) {
  EXPECT_GT(checkOverPoses(walkPoses(4, body().shape), false), 20000u);
}

TEST(CalibratedErrorBound, BadQueriesThrowAndEqualBodiesShareOneCalibrationKeptPastItsHolders) {
  Skin skin(skeleton(), body());
  const std::vector<BezierPatch> rest = skin.patches();
  const CalibratedErrorBound calibrated(rest);
  EXPECT_THROW(calibrated.bound(0, rest[0], 0), std::invalid_argument);
  EXPECT_THROW(calibrated.bound(rest.size(), rest[0], 1), std::out_of_range);
  EXPECT_THROW(measuredTessellationError(rest[0], 0), std::invalid_argument);
  std::vector<int> levels;
  const CameraView camera{Eigen::Vector3d(5.0, 0.0, 1.0), 0.8, 700.0};
  const std::vector<BezierPatch> fewer(rest.begin(), rest.begin() + 3);
  EXPECT_THROW(calibrated.levelsForScreenError(fewer, camera, 1.0, 16, levels), std::invalid_argument);
  EXPECT_NO_THROW(calibrated.levelsForScreenError(rest, camera, 1.0, 16, levels));
  EXPECT_THROW(CalibratedErrorBound(rest, {rest, fewer}), std::invalid_argument);
  EXPECT_EQ(calibrationPosesFromFile(sourcePath("config/motions/walk.yaml")).size(), kCalibrationPoseCount);
  EXPECT_TRUE(calibrationPosesFromFile(sourcePath("config/motions/walk.yaml"), 0).empty());
  EXPECT_ANY_THROW(calibrationPosesFromFile(sourcePath("config/motions/no_such_walk.yaml")));
  EXPECT_EQ(levels.size(), rest.size());

  // Two humans of one body: one calibration; another body: another one.
  std::shared_ptr<const CalibratedErrorBound> first = CalibratedErrorBound::shared(rest);
  EXPECT_EQ(CalibratedErrorBound::shared(Skin(skeleton(), body()).patches()), first);
  BodyShape wider = body().shape;
  for (Eigen::Vector3d& factors : wider.scale) factors.x() *= 1.1;
  EXPECT_NE(CalibratedErrorBound::shared(Skin(skeleton(), body(), wider).patches()), first);
  // Nobody holds it any more: it is kept (a display rebuilding its humans finds it again).
  const std::weak_ptr<const CalibratedErrorBound> released = first;
  first.reset();
  ASSERT_FALSE(released.expired());
  EXPECT_EQ(CalibratedErrorBound::shared(rest), released.lock());
}

}  // namespace
}  // namespace dressed_human
