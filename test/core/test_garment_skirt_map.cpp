// Skirt length across thigh and shank (SPEC §3, Eq. 6-8 made continuous: skirt_length_map.h):
// the map is continuous at knee length, has the right end values, the printed A_j is not; the
// hem goes monotonically down the leg as c grows; the long skirt follows the bending knee; body
// shape changes carry through.
#include <gtest/gtest.h>

#include "dressed_human/core/garments/skirt_length_map.h"
#include "garment_test_support.h"

#include <cmath>

namespace dressed_human {
namespace {

using namespace garment_test;

TEST(SkirtLengthMap, ContinuousAtKneeLengthWithTheRightEndValues) {
  for (const auto& [di, dj] :
       std::vector<std::pair<double, double>>{{0.42, 0.41}, {0.45, 0.30}, {0.3, 0.5}, {1.0, 1.0}}) {
    const double ck = kneeLength(di, dj);
    EXPECT_DOUBLE_EQ(ck, di / (di + dj));
    const SkirtLengthWeights at0 = skirtLengthWeights(0.0, di, dj);
    const SkirtLengthWeights atk = skirtLengthWeights(ck, di, dj);
    const SkirtLengthWeights at1 = skirtLengthWeights(1.0, di, dj);
    EXPECT_EQ(at0.ai, 0.0);
    EXPECT_EQ(at0.a0, 1.0);
    EXPECT_EQ(at0.aj, 0.0);
    EXPECT_NEAR(atk.ai, 1.0, 1e-15);
    EXPECT_EQ(atk.aj, 0.0);           // A_j = 0 at c_k
    EXPECT_NEAR(at1.aj, 1.0, 1e-15);  // A_j = 1 at c = 1
    EXPECT_EQ(at1.ai, 1.0);
    const SkirtLengthWeights below = skirtLengthWeights(std::nextafter(ck, 0.0), di, dj);
    const SkirtLengthWeights above = skirtLengthWeights(std::nextafter(ck, 1.0), di, dj);
    EXPECT_LE(std::abs(above.ai - below.ai), 1e-12);
    EXPECT_LE(std::abs(above.aj - below.aj), 1e-12);
    EXPECT_LE(std::abs(above.a0 - below.a0), 1e-12);
    // The printed A_j jumps by (d_i - d_j) / d_j there.
    EXPECT_NEAR(printedLowerWeight(ck, di, dj), (di - dj) / dj, 1e-12);
  }
  EXPECT_THROW(skirtLengthWeights(1.1, 0.4, 0.4), std::invalid_argument);
  EXPECT_THROW(skirtLengthWeights(0.5, 0.0, 0.4), std::invalid_argument);
}

// Hem length measured along the leg: below c_k its z in the thigh frame; above, the knee-length
// hem's z (P^i) plus the distance beyond P^i along the shank's axis.
double hemDepth(const Garment& skirt, const SkeletonPose& pose, std::uint32_t point, int thigh, int shank) {
  const Eigen::Vector3d x = skirt.net().worldPoints()[point];
  const ShapeAttachment& a = skirt.net().rule(point).attachment;
  const RigidTransform& t = pose.bone_in_world[static_cast<std::size_t>(thigh)];
  if (a.lower_weight == 0.0) return (t.rotation.conjugate() * (x - t.translation)).z();
  const Eigen::Vector3d pivot = t.rotation * a.local + t.translation;  // P^i (A_i = 1 above c_k)
  const Eigen::Vector3d shank_axis =
      pose.bone_in_world[static_cast<std::size_t>(shank)].rotation * Eigen::Vector3d::UnitZ();
  return a.local.z() + shank_axis.dot(x - pivot);
}

TEST(SkirtLengthMap, HemMovesMonotonicallyDownTheLegAndIsContinuousAtTheKnee) {
  const Skeleton& sk = skeleton();
  const int thigh = sk.findBone("l_hip"), shank = sk.findBone("l_knee");
  const std::vector<SkeletonPose> poses = walkPoses(8, BodyShape());
  GarmentDescription d = garmentFile("skirt");
  d.legs.at_knee = false;
  const double di = sk.bone(static_cast<std::size_t>(thigh)).length;
  // The hem's left shape points: the last shape points created on the thigh frame.
  auto hemPoints = [&](const Garment& g) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t p : g.net().shapePoints()) {
      const ShapeAttachment& a = g.net().rule(p).attachment;
      if (a.bone == thigh) out.push_back(p);
    }
    return std::vector<std::uint32_t>(out.end() - 4, out.end());  // last row: the hem
  };
  for (const SkeletonPose& pose : poses) {
    std::vector<double> previous;
    for (int k = 0; k <= 100; ++k) {
      d.legs.length = k / 100.0;
      Garment skirt(d, sk);
      skirt.pose(pose);
      const std::vector<std::uint32_t> hem = hemPoints(skirt);
      for (std::size_t h = 0; h < hem.size(); ++h) {
        const double depth = hemDepth(skirt, pose, hem[h], thigh, shank);
        if (previous.size() == hem.size()) {
          EXPECT_GE(depth, previous[h] - 1e-12) << "c = " << d.legs.length;
        }
        if (previous.size() < hem.size()) {
          previous.push_back(depth);
        } else {
          previous[h] = depth;
        }
      }
    }
  }
  // Continuity of the posed hem at c_k itself.
  GarmentDescription below = d, above = d;
  const double ck = kneeLength(di, sk.bone(static_cast<std::size_t>(shank)).length);
  below.legs.length = std::nextafter(ck, 0.0);
  above.legs.length = std::nextafter(ck, 1.0);
  Garment a(below, sk), b(above, sk);
  double jump = 0.0;
  for (const SkeletonPose& pose : poses) {
    a.pose(pose);
    b.pose(pose);
    for (std::size_t p = 0; p < a.net().pointCount(); ++p)
      jump = std::max(jump, (a.net().worldPoints()[p] - b.net().worldPoints()[p]).norm());
  }
  EXPECT_LE(jump, 1e-12);
}

TEST(SkirtLengthMap, LongSkirtHemFollowsTheBendingKnee) {
  const Skeleton& sk = skeleton();
  const int shank = sk.findBone("l_knee");
  GarmentDescription d = garmentFile("skirt");
  d.legs.at_knee = false;
  d.legs.length = 1.0;
  Garment skirt(d, sk);
  ForwardKinematics fk(sk);
  JointAngles angles{};
  SkeletonPose straight, bent;
  fk.compute(RigidTransform(), angles, straight);
  angles[static_cast<std::size_t>(sk.findJoint("l_knee")) * 3] = 1.0;  // knee flexion
  fk.compute(RigidTransform(), angles, bent);
  // At c = 1 a hem point is the knee-length hem P^i (thigh) + R_ij P^j: seen from the shank it
  // turns with the knee about the fixed P^i, and its offset from P^i keeps its shank-frame value.
  std::vector<std::uint32_t> lower;
  for (std::uint32_t p : skirt.net().shapePoints()) {
    if (skirt.net().rule(p).attachment.lower_bone == shank && skirt.net().rule(p).attachment.lower_weight == 1.0)
      lower.push_back(p);
  }
  ASSERT_EQ(lower.size(), 4u);
  for (std::uint32_t p : lower) {
    const ShapeAttachment& a = skirt.net().rule(p).attachment;
    skirt.pose(bent);
    const Eigen::Vector3d x = skirt.net().worldPoints()[p];
    const RigidTransform& thigh_frame = bent.bone_in_world[static_cast<std::size_t>(a.bone)];
    const Eigen::Vector3d pivot = thigh_frame.rotation * a.local + thigh_frame.translation;
    const RigidTransform& s = bent.bone_in_world[static_cast<std::size_t>(shank)];
    EXPECT_LE((s.rotation.conjugate() * (x - pivot) - a.lower_vector).norm(), 1e-12);
    skirt.pose(straight);
    EXPECT_GT((skirt.net().worldPoints()[p] - x).norm(), 0.1);  // it really moved with the shank
  }
}

TEST(SkirtLengthMap, BodyShapeCarriesThroughToTheGarment) {
  const Skeleton& sk = skeleton();
  BodyShape tall;
  const int l_hip = sk.findBone("l_hip"), r_hip = sk.findBone("r_hip");
  tall.scale[static_cast<std::size_t>(l_hip)] = Eigen::Vector3d(1.2, 1.2, 1.25);
  tall.scale[static_cast<std::size_t>(r_hip)] = Eigen::Vector3d(1.2, 1.2, 1.25);
  Garment normal(garmentFile("skirt"), sk), shaped(garmentFile("skirt"), sk, tall);
  EXPECT_NEAR(shaped.kneeLength(), 0.42 * 1.25 / (0.42 * 1.25 + 0.41), 1e-9);
  EXPECT_NEAR(shaped.length(), shaped.kneeLength(), 1e-15);  // "knee" tracks the shaped c_k
  // Knee-length hem points: z scaled by c, x and y by a and b, in the thigh frame.
  std::size_t checked = 0;
  for (std::uint32_t p : normal.net().shapePoints()) {
    const ShapeAttachment& a = normal.net().rule(p).attachment;
    const ShapeAttachment& b = shaped.net().rule(p).attachment;
    if (a.bone != l_hip) continue;
    EXPECT_NEAR(b.local.x(), 1.2 * a.local.x(), 1e-12);
    EXPECT_NEAR(b.local.y(), 1.2 * a.local.y(), 1e-12);
    EXPECT_NEAR(b.local.z(), 1.25 * a.local.z(), 1e-12);
    ++checked;
  }
  EXPECT_GT(checked, 0u);
}

}  // namespace
}  // namespace dressed_human
