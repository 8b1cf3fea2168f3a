// Garments sit outside the skin (SPEC §3, issue 5): over >= 100 walk poses, sampled points of
// every default outfit (jacket, skirt at mini / knee / long, pants, one-piece) have clearance
// >= 0 over the REAL posed skin: the Skin's Bezier patches (skin.h) posed by Skin::pose and
// triangulated finely (SkinSurfaceClearance, skin_clearance.h), signed distance per closed skin
// part, negative inside.
// Layering: a garment piece is checked against the skin parts it covers. The jacket and bodice
// are closed tubes with no armholes: the arms leave them under the sleeves, whose tops are
// tucked inside the torso piece; so torso pieces are checked against the trunk and clavicles,
// sleeves against the arms, and the hips / skirt / legs pieces against the trunk and legs.
#include <gtest/gtest.h>

#include "dressed_human/core/surfaces/skin_clearance.h"
#include "garment_test_support.h"

#include <iostream>
#include <limits>
#include <map>

namespace dressed_human {
namespace {

using namespace garment_test;

std::vector<std::string> coveredSegments(const std::string& piece) {
  if (piece == "l_sleeve") return {"l_shoulder"};
  if (piece == "r_sleeve") return {"r_shoulder"};
  if (piece == "torso" || piece == "bodice") return {"body", "l_clavicle", "r_clavicle"};
  return {"body", "l_hip", "r_hip"};
}

struct Case {
  std::string name, file, length;  // length: "" (the file's), "knee" or a number
};

TEST(GarmentClearance, SkinSurfaceClearanceSignsInsideAndOutside) {
  SkinSurfaceClearance skin(skeleton(), body());
  const std::vector<SkeletonPose> poses = walkPoses(4, body().shape);
  for (const SkeletonPose& pose : poses) {
    skin.pose(pose);
    // The pelvis centre is inside the trunk; a point 1 m in front of it is outside.
    EXPECT_LT(skin.clearance(pose.root.translation), -0.05);
    EXPECT_GT(skin.clearance(pose.root.translation + pose.root.rotation * Eigen::Vector3d(1.0, 0.0, 0.0)), 0.3);
    // A thigh's axis is inside its leg part.
    const int thigh = skeleton().findBone("l_hip");
    const RigidTransform& t = pose.bone_in_world[static_cast<std::size_t>(thigh)];
    EXPECT_LT(skin.clearance(t.translation + t.rotation * Eigen::Vector3d(0, 0, 0.2)), -0.04);
  }
}

// The clearance goal is checked over 100 walk poses by the plain build. Under AddressSanitizer
// the same code runs 10-20x slower; 10 poses exercise every code path for memory errors.
#ifdef __SANITIZE_ADDRESS__
constexpr int kWalkPoses = 10;
#else
constexpr int kWalkPoses = 100;
#endif

// Minimum clearance of one garment over the real skin in `poses`, and where.
double minimumClearance(const std::string& file, const std::string& length, std::string& where) {
  static SkinSurfaceClearance skin(skeleton(), body());
  static const std::vector<SkeletonPose> poses = walkPoses(kWalkPoses, body().shape);
  constexpr int kSamples = 9;  // per patch and direction
  GarmentDescription d = garmentFile(file);
  if (length == "knee") {
    d.legs.at_knee = true;
  } else if (!length.empty()) {
    d.legs.at_knee = false;
    d.legs.length = std::stod(length);
  }
  Garment garment(d, skeleton(), body().shape);
  std::map<std::string, std::vector<std::size_t>> parts;
  double minimum = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < poses.size(); ++k) {
    skin.pose(poses[k]);
    garment.pose(poses[k]);
    for (std::size_t p = 0; p < garment.patches().size(); ++p) {
      const std::string& piece = garment.net().patchPiece(p);
      if (!parts.count(piece)) parts[piece] = skin.partsOf(coveredSegments(piece));
      for (int a = 0; a < kSamples; ++a) {
        for (int b = 0; b < kSamples; ++b) {
          const double u = static_cast<double>(a) / (kSamples - 1), v = static_cast<double>(b) / (kSamples - 1);
          std::size_t part = 0;
          const double c = skin.clearance(garment.patches()[p].position(u, v), parts[piece], part);
          if (c < minimum) {
            minimum = c;
            where = piece + " patch " + std::to_string(p) + " (u " + std::to_string(u) + ", v " + std::to_string(v) +
                    ") walk pose " + std::to_string(k) + "/" + std::to_string(kWalkPoses) + ", skin part " +
                    std::to_string(part);
          }
        }
      }
    }
  }
  std::cout << "[ clear   ] " << file << (length.empty() ? "" : " (length " + length + ")")
            << ": minimum clearance over the real skin " << minimum * 1000.0 << " mm at " << where << '\n';
  return minimum;
}

// One test per default outfit piece, 100 walk poses each (config/motions/walk.yaml).
TEST(GarmentClearance, JacketStaysOutsideTheRealSkin) {
  std::string where;
  EXPECT_GE(minimumClearance("jacket", "", where), 0.0) << where;
}
TEST(GarmentClearance, MiniSkirtStaysOutsideTheRealSkin) {
  std::string where;
  EXPECT_GE(minimumClearance("skirt", "0.2", where), 0.0) << where;
}
TEST(GarmentClearance, KneeSkirtStaysOutsideTheRealSkin) {
  std::string where;
  EXPECT_GE(minimumClearance("skirt", "knee", where), 0.0) << where;
}
TEST(GarmentClearance, LongSkirtStaysOutsideTheRealSkin) {
  std::string where;
  EXPECT_GE(minimumClearance("skirt", "1.0", where), 0.0) << where;
}
TEST(GarmentClearance, OnePieceStaysOutsideTheRealSkin) {
  std::string where;
  EXPECT_GE(minimumClearance("one_piece", "", where), 0.0) << where;
}
// Issue 5: with one cubic per leg from crotch to ankle the bent knee went 25 mm through the front;
// the legs now bend at the knee (garment.h). Tight spots left: the crotch and the passing knees.
TEST(GarmentClearance, PantsStayOutsideTheRealSkin) {
  std::string where;
  EXPECT_GE(minimumClearance("pants", "", where), 0.0) << where;
}

}  // namespace
}  // namespace dressed_human
