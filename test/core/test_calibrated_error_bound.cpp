// CalibratedErrorBound (tessellation.h): calibrated at rest, the bound stays above the error the
// triangulation really has in every pose of a walk, and within 2x of it, for the skin and every
// garment of the default outfits -- where the a-priori bound is up to 10x the error. Level of
// detail chosen from it therefore draws about the triangles the screen error asks for.
#include "dressed_human/core/surfaces/tessellation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "dressed_human/core/garments/garment.h"
#include "dressed_human/core/surfaces/skin.h"
#include "garment_test_support.h"

namespace dressed_human {
namespace {

using namespace garment_test;

struct Ratios {
  double lowest = 1e300;   // calibrated / measured, over patches with a measurable error
  double highest = 0.0;
  double apriori_highest = 0.0;  // the a-priori bound / measured, for the record
  double part_worst_ratio = 0.0;  // the part's largest calibrated bound / its largest measured error
  std::size_t patches = 0;
  std::size_t within_two = 0;
};

// Calibrated on `rest`, checked on each of `posed` at `level`.
Ratios compare(const std::vector<BezierPatch>& rest, const std::vector<std::vector<BezierPatch>>& posed, int level) {
  const CalibratedErrorBound calibrated(rest);
  Ratios ratios;
  for (const std::vector<BezierPatch>& patches : posed) {
    double worst_measured = 0.0, worst_bound = 0.0;
    for (std::size_t p = 0; p < patches.size(); ++p) {
      const double measured = measuredTessellationError(patches[p], level);
      const double bound = calibrated.bound(p, patches[p], level);
      worst_measured = std::max(worst_measured, measured);
      worst_bound = std::max(worst_bound, bound);
      if (measured < 1e-5) {  // under 0.01 mm: no meaningful ratio, but the bound must not be below it
        EXPECT_GE(bound + 1e-9, measured);
        continue;
      }
      const double ratio = bound / measured;
      ratios.lowest = std::min(ratios.lowest, ratio);
      ratios.highest = std::max(ratios.highest, ratio);
      ratios.apriori_highest = std::max(ratios.apriori_highest, geometricErrorBound(patches[p], level) / measured);
      ++ratios.patches;
      if (ratio <= 2.0) ++ratios.within_two;
    }
    ratios.part_worst_ratio = std::max(ratios.part_worst_ratio, worst_bound / worst_measured);
  }
  return ratios;
}

void expectTight(const std::string& name, const std::vector<BezierPatch>& rest,
                 const std::vector<std::vector<BezierPatch>>& posed) {
  for (const int level : {1, 2, 3, 4, 6, 8}) {
    const Ratios r = compare(rest, posed, level);
    std::printf("%-8s level %d: calibrated/measured %.2f..%.2f (%zu of %zu within 2x), part max %.2f; a-priori up to %.1fx\n",
                name.c_str(), level, r.lowest, r.highest, r.within_two, r.patches, r.part_worst_ratio, r.apriori_highest);
    EXPECT_GE(r.lowest, 1.0) << name << " level " << level << ": the calibrated bound is below the measured error";
    // The figure a level of detail lives by: the part's largest bound against its largest error.
    EXPECT_LE(r.part_worst_ratio, 2.0) << name << " level " << level;
    EXPECT_GE(r.within_two, r.patches * 8 / 10) << name << " level " << level << ": most patches within 2x";
  }
}

std::vector<SkeletonPose> poses() { return walkPoses(16, body().shape); }

TEST(CalibratedErrorBound, SkinBoundHoldsAndIsTightOverAWalk) {
  Skin skin(skeleton(), body());
  const std::vector<BezierPatch> rest = skin.patches();
  std::vector<std::vector<BezierPatch>> posed;
  for (const SkeletonPose& pose : poses()) {
    skin.pose(pose);
    posed.push_back(skin.patches());
  }
  expectTight("skin", rest, posed);
}

TEST(CalibratedErrorBound, GarmentBoundsHoldAndAreTightOverAWalk) {
  for (const std::string name : {"jacket", "skirt", "pants", "one_piece"}) {
    Garment garment(garmentFile(name), skeleton(), body().shape);
    const std::vector<BezierPatch> rest = garment.patches();
    std::vector<std::vector<BezierPatch>> posed;
    for (const SkeletonPose& pose : poses()) {
      garment.pose(pose);
      posed.push_back(garment.patches());
    }
    expectTight(name, rest, posed);
  }
}

TEST(CalibratedErrorBound, BadQueriesThrowAndEqualBodiesShareOneCalibration) {
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
  EXPECT_EQ(levels.size(), rest.size());

  // Two humans of one body: one calibration; another body: another one.
  const std::shared_ptr<const CalibratedErrorBound> first = CalibratedErrorBound::shared(rest);
  EXPECT_EQ(CalibratedErrorBound::shared(Skin(skeleton(), body()).patches()), first);
  BodyShape wider = body().shape;
  for (Eigen::Vector3d& factors : wider.scale) factors.x() *= 1.1;
  EXPECT_NE(CalibratedErrorBound::shared(Skin(skeleton(), body(), wider).patches()), first);
}

}  // namespace
}  // namespace dressed_human
