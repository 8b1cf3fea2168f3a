// Garments (SPEC §3): C1 across every internal patch boundary, measured on the patches, in
// 120 walk poses for each outfit; the one-piece's waist; editing a shape point; the explicit
// classification of control points.
#include <gtest/gtest.h>

#include "dressed_human/core/patch_continuity.h"
#include "garment_test_support.h"

#include <set>

namespace dressed_human {
namespace {

using namespace garment_test;
constexpr double kTangentTolerance = 1e-9;
constexpr int kPoses = 120;

TEST(GarmentContinuity, EveryOutfitIsC1AcrossEveryInternalBoundaryOverTheWalk) {
  const std::vector<SkeletonPose> poses = walkPoses(kPoses, body().shape);
  for (const auto& [outfit, files] : outfits()) {
    for (const std::string& file : files) {
      Garment garment(garmentFile(file), skeleton(), body().shape);
      ASSERT_GT(garment.topology().links().size(), 0u) << file;
      double worst = 0.0, worst_gap = 0.0;
      for (const SkeletonPose& pose : poses) {
        garment.pose(pose);
        for (const EdgeContinuity& e : measureContinuity(garment.patches(), garment.topology(), 9)) {
          worst = std::max(worst, e.tangent_mismatch);
          worst_gap = std::max(worst_gap, e.position_gap);
        }
      }
      EXPECT_LE(worst, kTangentTolerance) << outfit << " / " << file;
      EXPECT_LE(worst_gap, 1e-12) << outfit << " / " << file;
      std::cout << "[ C1      ] " << outfit << " / " << file << ": " << garment.patches().size() << " patches, "
                << garment.topology().links().size() << " internal boundaries, max tangent mismatch " << worst
                << " over " << kPoses << " walk poses\n";
    }
  }
}

TEST(GarmentContinuity, PatchCountsFollowTheSeed) {
  EXPECT_EQ(Garment(garmentFile("jacket"), skeleton()).patches().size(), 12u);
  EXPECT_EQ(Garment(garmentFile("skirt"), skeleton()).patches().size(), 8u);
  EXPECT_EQ(Garment(garmentFile("pants"), skeleton()).patches().size(), 8u);
  EXPECT_EQ(Garment(garmentFile("one_piece"), skeleton()).patches().size(), 20u);  // 8 + 8 + 2 x 2
}

TEST(GarmentContinuity, OnePieceWaistIsAnInternalC1Boundary) {
  Garment dress(garmentFile("one_piece"), skeleton(), body().shape);
  const std::vector<SkeletonPose> poses = walkPoses(100, body().shape);
  std::size_t waist_links = 0;
  double worst = 0.0;
  for (const SkeletonPose& pose : poses) {
    dress.pose(pose);
    const std::vector<EdgeContinuity> edges = measureContinuity(dress.patches(), dress.topology(), 17);
    waist_links = 0;
    for (const EdgeContinuity& e : edges) {
      const EdgeLink& link = dress.topology().links()[e.link];
      const std::string a = dress.net().patchPiece(link.patch_a), b = dress.net().patchPiece(link.patch_b);
      if ((a == "bodice" && b == "skirt") || (a == "skirt" && b == "bodice")) {
        ++waist_links;
        worst = std::max(worst, e.tangent_mismatch);
      }
    }
  }
  EXPECT_EQ(waist_links, 4u);  // all the way around the waist
  EXPECT_LE(worst, kTangentTolerance);
}

TEST(GarmentContinuity, EditingOneShapePointKeepsC1) {
  const std::vector<SkeletonPose> poses = walkPoses(10, body().shape);
  for (const std::string file : {"skirt", "pants", "jacket", "one_piece"}) {
    Garment garment(garmentFile(file), skeleton(), body().shape);
    const std::vector<std::uint32_t> shapes = garment.net().shapePoints();
    ASSERT_FALSE(shapes.empty());
    // Move several single shape points far (5 cm) in their own bone frame.
    for (std::size_t k = 0; k < shapes.size(); k += 7) {
      const std::uint32_t p = shapes[k];
      const Eigen::Vector3d before = garment.net().rule(p).attachment.local;
      garment.net().setShapeLocal(p, before + Eigen::Vector3d(0.05, -0.03, 0.04));
      for (const SkeletonPose& pose : poses) {
        garment.pose(pose);
        EXPECT_LE(maxTangentMismatch(measureContinuity(garment.patches(), garment.topology())), kTangentTolerance)
            << file << " point " << p;
      }
      garment.net().setShapeLocal(p, before);
    }
  }
}

TEST(GarmentContinuity, EveryControlPointKnowsItsKindAndBone) {
  Garment skirt(garmentFile("skirt"), skeleton(), body().shape);
  const GarmentControlNet& net = skirt.net();
  std::map<ControlPointKind, int> kinds;
  for (std::uint32_t p = 0; p < net.pointCount(); ++p) {
    ++kinds[net.kind(p)];
    const ControlPointRule& rule = net.rule(p);
    if (rule.kind == ControlPointKind::kShape) {
      EXPECT_EQ(net.bone(p), rule.attachment.bone);
      EXPECT_EQ(net.shapeSources(p), std::vector<std::uint32_t>{p});
    } else {
      EXPECT_GE(net.shapeSources(p).size(), 2u);  // derived from at least two shape points
    }
  }
  // 12 around x 7 rows: 8 shape points on each of the 6 non-boundary rows, the rest derived.
  EXPECT_EQ(kinds[ControlPointKind::kShape], 48);
  EXPECT_EQ(kinds[ControlPointKind::kBoundaryMidpoint], 6 * 4 + 8);
  EXPECT_EQ(kinds[ControlPointKind::kCornerMidpoint], 4);
  EXPECT_EQ(kinds[ControlPointKind::kCollapsed], 0);
  // Hem points of the left half ride on the left thigh (Eq. 8' adds the shank for c > c_k).
  const int l_hip = skeleton().findBone("l_hip");
  const int r_hip = skeleton().findBone("r_hip");
  std::set<int> bones;
  for (std::uint32_t p : net.shapePoints()) bones.insert(net.bone(p));
  EXPECT_TRUE(bones.count(l_hip) && bones.count(r_hip) && bones.count(kRootFrame));
  EXPECT_THROW(skirt.net().setShapeLocal(static_cast<std::uint32_t>(net.pointCount() - 1), Eigen::Vector3d::Zero()),
               std::invalid_argument);

  Garment pants(garmentFile("pants"), skeleton(), body().shape);
  int collapsed = 0;
  for (std::uint32_t p = 0; p < pants.net().pointCount(); ++p) collapsed += pants.net().kind(p) == ControlPointKind::kCollapsed;
  EXPECT_EQ(collapsed, 8);
}

}  // namespace
}  // namespace dressed_human
