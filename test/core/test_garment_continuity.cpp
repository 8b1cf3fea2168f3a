// Garments (SPEC §3): C1 across every internal patch boundary, measured on the patches, in
// 120 walk poses for each outfit; the one-piece's waist; editing a shape point; the explicit
// classification of control points.
#include <gtest/gtest.h>

#include "dressed_human/core/surfaces/patch_continuity.h"
#include "garment_test_support.h"

#include <cmath>
#include <set>

namespace dressed_human {
namespace {

using namespace garment_test;
constexpr double kTangentTolerance = 1e-9;
constexpr int kPoses = 120;

// Links with an end at the pants' crotch C (garment.h: the one vertex of valence 8).
bool atCrotch(const Garment& garment, const EdgeLink& link) {
  if (garment.crotchPoint() < 0) return false;
  const auto e = edgeIndices(garment.net().patchIndices()[link.patch_a], link.edge_a);
  const auto c = static_cast<std::uint32_t>(garment.crotchPoint());
  return e[0] == c || e[3] == c;
}

// (u, v) at edge parameter t and the derivative leaving the patch across the edge.
Eigen::Vector3d across(const BezierPatch& patch, PatchEdge edge, double t, Eigen::Vector3d& position) {
  double u = t, v = t, sign = 1.0;
  bool along_u = true;
  switch (edge) {
    case PatchEdge::kV0:
      v = 0.0;
      along_u = false;
      sign = -1.0;
      break;
    case PatchEdge::kV1:
      v = 1.0;
      along_u = false;
      break;
    case PatchEdge::kU0:
      u = 0.0;
      sign = -1.0;
      break;
    case PatchEdge::kU1:
      u = 1.0;
      break;
  }
  const PatchDerivatives d = patch.derivatives(u, v);
  position = d.position;
  return sign * (along_u ? d.d_du : d.d_dv);
}

TEST(GarmentContinuity, EveryOutfitIsC1AcrossEveryInternalBoundaryOverTheWalk) {
  const std::vector<SkeletonPose> poses = walkPoses(kPoses, body().shape);
  for (const auto& [outfit, files] : outfits()) {
    for (const std::string& file : files) {
      Garment garment(garmentFile(file), skeleton(), body().shape);
      ASSERT_GT(garment.topology().links().size(), 0u) << file;
      double worst = 0.0, worst_gap = 0.0, crotch_at_c = 0.0;
      std::size_t crotch_links = 0;
      for (const SkeletonPose& pose : poses) {
        garment.pose(pose);
        crotch_links = 0;
        for (const EdgeContinuity& e : measureContinuity(garment.patches(), garment.topology(), 9)) {
          worst_gap = std::max(worst_gap, e.position_gap);
          const EdgeLink& link = garment.topology().links()[e.link];
          if (!atCrotch(garment, link)) {
            worst = std::max(worst, e.tangent_mismatch);
            continue;
          }
          // A boundary ending at the crotch: mismatch 3 (1 - t)^3 |2 C - E_{k-1} - E_{k+1}| (garment.h).
          ++crotch_links;
          const auto ids = edgeIndices(garment.net().patchIndices()[link.patch_a], link.edge_a);
          const bool c_first = ids[0] == static_cast<std::uint32_t>(garment.crotchPoint());
          auto mismatch = [&](double s) {  // s: distance in parameter from C
            const double ta = c_first ? s : 1.0 - s;
            const double tb = link.reversed ? 1.0 - ta : ta;
            Eigen::Vector3d pa, pb;
            const Eigen::Vector3d leaving = across(garment.patches()[link.patch_a], link.edge_a, ta, pa);
            const Eigen::Vector3d entering = -across(garment.patches()[link.patch_b], link.edge_b, tb, pb);
            return (leaving - entering).norm();
          };
          const double at_c = mismatch(0.0);
          crotch_at_c = std::max(crotch_at_c, at_c);
          for (double s : {0.25, 0.5, 0.75, 1.0}) {
            EXPECT_NEAR(mismatch(s), std::pow(1.0 - s, 3) * at_c, 1e-9) << file << " s = " << s;
          }
        }
      }
      if (garment.crotchPoint() >= 0) {
        EXPECT_EQ(crotch_links, 8u) << file;
        std::cout << "[ C1      ] " << outfit << " / " << file << ": the " << crotch_links
                  << " boundaries ending at the crotch: C0, cross-tangent mismatch 3 (1 - t)^3 |2C - E - E'|, at most "
                  << crotch_at_c << " at C\n";
      }
      EXPECT_LE(worst, kTangentTolerance) << outfit << " / " << file;
      EXPECT_LE(worst_gap, 1e-12) << outfit << " / " << file;
      std::cout << "[ C1      ] " << outfit << " / " << file << ": " << garment.patches().size() << " patches, "
                << garment.topology().links().size() << " internal boundaries, max tangent mismatch " << worst
                << " over " << kPoses << " walk poses\n";
    }
  }
}

// The crotch (garment.h): the 8 patches meeting there share one tangent plane at C, the crotch
// frame's xy plane, with one orientation, in every walk pose and after editing the twist ring.
TEST(GarmentContinuity, PantsAreG1AtTheCrotchPoint) {
  Garment pants(garmentFile("pants"), skeleton(), body().shape);
  const auto c = static_cast<std::uint32_t>(pants.crotchPoint());
  std::vector<std::uint32_t> twist;
  for (std::uint32_t p = 0; p < pants.net().pointCount(); ++p) {
    if (pants.net().kind(p) == ControlPointKind::kTangentProjection) twist.push_back(p);
  }
  ASSERT_EQ(twist.size(), 8u);
  const std::vector<SkeletonPose> poses = walkPoses(kPoses, body().shape);
  for (int edit = 0; edit < 2; ++edit) {
    if (edit == 1) {  // move a twist point's source (out of the plane too): still G1
      const std::uint32_t source = pants.net().rule(twist[3]).sources[0];
      pants.net().setShapeLocal(source,
                                pants.net().rule(source).attachment.local + Eigen::Vector3d(0.01, -0.003, 0.03));
    }
    double worst = 0.0;
    for (const SkeletonPose& pose : poses) {
      pants.pose(pose);
      const Eigen::Vector3d up = pose.root.rotation * Eigen::Vector3d::UnitZ();  // crotch frame: body
      int corners = 0;
      for (std::size_t p = 0; p < pants.patches().size(); ++p) {
        const auto& ids = pants.net().patchIndices()[p];
        for (const auto& [a, b] : {std::pair<int, int>{0, 0}, {0, 3}, {3, 0}, {3, 3}}) {
          if (ids[BezierPatch::index(a, b)] != c) continue;
          ++corners;
          const Eigen::Vector3d n = pants.patches()[p].normal(a / 3.0, b / 3.0);
          worst = std::max(worst, (n + up).norm());  // outward at the crotch: down
        }
      }
      EXPECT_EQ(corners, 8);
    }
    EXPECT_LE(worst, 1e-9) << (edit ? "after editing a twist point" : "");
    std::cout << "[ G1      ] pants: 8 patch normals at the crotch within " << worst
              << " of the crotch frame's -z over " << kPoses << " walk poses"
              << (edit ? " (one twist point edited)" : "") << '\n';
  }
}

TEST(GarmentContinuity, PatchCountsFollowTheSeed) {
  EXPECT_EQ(Garment(garmentFile("jacket"), skeleton()).patches().size(), 12u);
  EXPECT_EQ(Garment(garmentFile("skirt"), skeleton()).patches().size(), 8u);
  // Pants: the seed's 8 (hips row 4 + each leg front and back) with each leg split at the knee
  // into a thigh row and a shank row (garment.h): 4 + 2 x 2 x 2 = 12.
  EXPECT_EQ(Garment(garmentFile("pants"), skeleton()).patches().size(), 12u);
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
        double worst = 0.0;
        for (const EdgeContinuity& e : measureContinuity(garment.patches(), garment.topology())) {
          if (!atCrotch(garment, garment.topology().links()[e.link])) worst = std::max(worst, e.tangent_mismatch);
        }
        EXPECT_LE(worst, kTangentTolerance) << file << " point " << p;
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
  // Hem points of the left half ride on the left thigh (Eq. 8' adds the shank for c > c_k).
  const int l_hip = skeleton().findBone("l_hip");
  const int r_hip = skeleton().findBone("r_hip");
  std::set<int> bones;
  for (std::uint32_t p : net.shapePoints()) bones.insert(net.bone(p));
  EXPECT_TRUE(bones.count(l_hip) && bones.count(r_hip) && bones.count(kRootFrame));
  EXPECT_THROW(skirt.net().setShapeLocal(static_cast<std::uint32_t>(net.pointCount() - 1), Eigen::Vector3d::Zero()),
               std::invalid_argument);

  // Pants: the crotch C (shape point on the body frame), 8 twist sources (shape points on the
  // same frame) and their 8 tangent projections (the twist points).
  Garment pants(garmentFile("pants"), skeleton(), body().shape);
  ASSERT_GE(pants.crotchPoint(), 0);
  const auto c = static_cast<std::uint32_t>(pants.crotchPoint());
  EXPECT_EQ(pants.net().kind(c), ControlPointKind::kShape);
  EXPECT_EQ(pants.net().bone(c), kRootFrame);
  int shapes = 0, projections = 0;
  for (std::uint32_t p = 0; p < pants.net().pointCount(); ++p) {
    if (pants.net().rule(p).piece != "crotch" || p == c) continue;
    if (pants.net().kind(p) == ControlPointKind::kShape) {
      ++shapes;
      EXPECT_EQ(pants.net().bone(p), kRootFrame);
    } else {
      ++projections;
      EXPECT_EQ(pants.net().kind(p), ControlPointKind::kTangentProjection);
      EXPECT_EQ(pants.net().rule(p).sources[1], c);
      EXPECT_EQ(pants.net().bone(p), kRootFrame);  // both sources ride the body frame
    }
  }
  EXPECT_EQ(shapes, 8);
  EXPECT_EQ(projections, 8);
  EXPECT_EQ(Garment(garmentFile("skirt"), skeleton()).crotchPoint(), -1);
}

}  // namespace
}  // namespace dressed_human
