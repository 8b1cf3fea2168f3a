// Stability of the skirt length map (Eq. 6-8 made continuous, skirt_length_map.h) at the ends and
// at knee length, where the piecewise map switches branches (issue #8, docs/stability.md): the
// weights at exactly 0, c_k and 1 and just either side of c_k, and real garments built at those
// lengths -- finite patches and meshes, a hem that only goes down as c grows, no jump at c_k.
#include <gtest/gtest.h>

#include "dressed_human/core/garments/skirt_length_map.h"
#include "dressed_human/core/surfaces/tessellation.h"
#include "garment_test_support.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace dressed_human {
namespace {

using namespace garment_test;

std::vector<double> lengthsAround(double ck) {
  return {0.0,
          std::numeric_limits<double>::denorm_min(),
          1e-9,
          0.5 * ck,
          ck - 1e-6,
          ck - 1e-12,
          std::nextafter(ck, 0.0),
          ck,
          std::nextafter(ck, 1.0),
          ck + 1e-12,
          ck + 1e-6,
          0.5 * (ck + 1.0),
          1.0 - 1e-9,
          std::nextafter(1.0, 0.0),
          1.0};
}

TEST(StabilityGarment, SkirtWeightsAtTheEndsAndEitherSideOfKneeLength) {
  for (const auto& [di, dj] :
       std::vector<std::pair<double, double>>{{0.42, 0.41}, {0.45, 0.30}, {1e-3, 1.0}, {1.0, 1e-3}}) {
    const double ck = kneeLength(di, dj);
    SkirtLengthWeights previous{1.0, 0.0, 0.0};
    for (double c : lengthsAround(ck)) {
      const SkirtLengthWeights w = skirtLengthWeights(c, di, dj);
      ASSERT_TRUE(std::isfinite(w.a0) && std::isfinite(w.ai) && std::isfinite(w.aj)) << c;
      EXPECT_GE(w.ai, 0.0);
      EXPECT_LE(w.ai, 1.0);
      EXPECT_GE(w.aj, 0.0);
      EXPECT_LE(w.aj, 1.0);
      EXPECT_NEAR(w.a0 + w.ai, 1.0, 1e-15) << "P(c) must stay a point (w = 1)";
      // Non-decreasing, and never faster than the slopes 1/c_k and 1/(1 - c_k) allow.
      EXPECT_GE(w.ai, previous.ai) << c;
      EXPECT_GE(w.aj, previous.aj) << c;
      if (c < ck) {
        EXPECT_EQ(w.aj, 0.0) << c;
      } else {
        EXPECT_EQ(w.ai, 1.0) << c;
      }
      previous = w;
    }
    // Exactly at c_k: knee length, A_i = 1, A_j = 0, whichever branch the rounding picks.
    const SkirtLengthWeights knee = skirtLengthWeights(ck, di, dj);
    EXPECT_NEAR(knee.ai, 1.0, 1e-15);
    EXPECT_EQ(knee.aj, 0.0);
    // Either side by one ulp: within a few ulps of the knee values.
    for (double c : {std::nextafter(ck, 0.0), std::nextafter(ck, 1.0)}) {
      const SkirtLengthWeights w = skirtLengthWeights(c, di, dj);
      EXPECT_NEAR(w.ai, 1.0, 1e-12);
      EXPECT_NEAR(w.aj, 0.0, 1e-12);
    }
  }
  for (double bad :
       {-1e-300, 1.0 + 1e-15, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(skirtLengthWeights(bad, 0.4, 0.4), std::invalid_argument) << bad;
  }
}

SkeletonPose restPose() {
  JointAngles zero{};
  RigidTransform root;
  root.translation = Eigen::Vector3d(0.0, 0.0, 1.0);
  SkeletonPose pose;
  ForwardKinematics(skeleton(), body().shape).compute(root, zero, pose);
  return pose;
}

double lowestPoint(const Garment& garment) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& p : garment.net().worldPoints()) lowest = std::min(lowest, p.z());
  return lowest;
}

// A garment built at each length: every control point finite, the hem going only down as c grows
// with no jump at c_k, and the tessellation over the walk finite with unit normals.
void checkGarmentAtLengths(const char* name, const std::vector<double>& lengths) {
  const SkeletonPose rest = restPose();
  const std::vector<SkeletonPose> walk = walkPoses(4, body().shape);
  GarmentDescription d = garmentFile(name);
  d.legs.at_knee = false;
  double previous_hem = std::numeric_limits<double>::infinity();
  double previous_c = 0.0;
  double first_hem = 0.0;
  Tessellator tessellator;
  for (double c : lengths) {
    std::ostringstream trace;
    trace << name << " c = " << c;
    SCOPED_TRACE(trace.str());
    d.legs.length = c;
    Garment garment(d, skeleton(), body().shape);
    garment.pose(rest);
    for (const Eigen::Vector3d& p : garment.net().worldPoints()) ASSERT_TRUE(p.allFinite());
    const double hem = lowestPoint(garment);
    if (c == lengths.front()) first_hem = hem;
    if (c == 1.0 && lengths.front() == 0.0) {
      EXPECT_LT(hem, first_hem - 0.3) << "a full-length hem lies far below the hips";
    }
    EXPECT_LE(hem, previous_hem + 1e-12) << "the hem went up";
    // Continuity: the hem moves at most (d_i + d_j) |dc| and a bit (the legs are not vertical).
    if (std::isfinite(previous_hem)) {
      EXPECT_LE(previous_hem - hem, 1.2 * 0.9 * (c - previous_c) + 1e-9);
    }
    previous_hem = hem;
    previous_c = c;
    for (const SkeletonPose& pose : walk) {
      garment.pose(pose);
      try {
        const TriangleMesh& mesh = tessellator.tessellateUniform(garment.patches(), garment.topology(), 6);
        ASSERT_GT(mesh.triangleCount(), 0u);
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
          ASSERT_TRUE(mesh.positions[v].allFinite());
          ASSERT_TRUE(mesh.normals[v].allFinite());
          ASSERT_NEAR(mesh.normals[v].norm(), 1.0f, 1e-5f);
        }
      } catch (const std::exception& error) {
        ADD_FAILURE() << "tessellation refused: " << error.what();
        break;
      }
    }
  }
}

double kneeLengthOf(const char* name) {
  GarmentDescription d = garmentFile(name);
  d.legs.at_knee = false;
  return Garment(d, skeleton(), body().shape).kneeLength();
}

TEST(StabilityGarment, SkirtAtZeroKneeAndFullLength) {
  checkGarmentAtLengths("skirt", lengthsAround(kneeLengthOf("skirt")));
}

// Pants at c = 0 (or a denormal c) would have leg patches whose rows all coincide -- a curve
// the tessellator cannot give a normal; Garment makes such legs kShortestPantsLeg long.
TEST(StabilityGarment, PantsAtZeroKneeAndFullLength) {
  checkGarmentAtLengths("pants", lengthsAround(kneeLengthOf("pants")));
}

}  // namespace
}  // namespace dressed_human
