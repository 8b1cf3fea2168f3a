// Wrinkle placement (issue 6): compression measured on the posed garment against its rest pose,
// alpha -> pattern and amplitude, the per-pose wrinkle map and the per-vertex API.
#include "dressed_human/core/relief/vertex_compression.h"
#include "dressed_human/core/relief/wrinkle_placement.h"

#include "dressed_human/core/surfaces/tessellation.h"
#include "garment_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace dressed_human {
namespace {

using namespace garment_test;

constexpr double kPi = 3.14159265358979323846;

Garment makeGarment(const std::string& name) { return Garment(garmentFile(name), skeleton(), body().shape); }

JointAngles zeroAngles() {
  JointAngles angles{};
  angles.fill(0.0);
  return angles;
}

SkeletonPose poseOf(const JointAngles& angles, const RigidTransform& root = RigidTransform()) {
  ForwardKinematics fk(skeleton(), body().shape);
  SkeletonPose pose;
  fk.compute(root, angles, pose);
  return pose;
}

std::size_t dofOf(const char* joint, JointAxis axis) {
  const int j = skeleton().findJoint(joint);
  EXPECT_GE(j, 0) << joint;
  return static_cast<std::size_t>(j) * kDofsPerJoint + static_cast<std::size_t>(axis);
}

// Sign of the y angle that flexes `joint` anatomically: it swings the distal bone `tip`
// `towards` (backwards for a knee, forwards for an elbow), read from forward kinematics.
double flexionSign(const char* joint, const char* tip, const Eigen::Vector3d& towards) {
  const std::size_t bone = static_cast<std::size_t>(skeleton().findBone(tip));
  const Eigen::Vector3d rest = poseOf(zeroAngles()).bone_in_world[bone].translation;
  JointAngles angles = zeroAngles();
  angles[dofOf(joint, JointAxis::kY)] = 0.3;
  const Eigen::Vector3d moved = poseOf(angles).bone_in_world[bone].translation;
  return (moved - rest).dot(towards) > 0.0 ? 1.0 : -1.0;
}

SkeletonPose kneeBent(double radians, const char* joint = "l_knee") {
  JointAngles angles = zeroAngles();
  angles[dofOf(joint, JointAxis::kY)] =
      radians * flexionSign(joint, joint[0] == 'l' ? "l_ankle" : "r_ankle", -Eigen::Vector3d::UnitX());
  return poseOf(angles);
}

SkeletonPose elbowBent(double radians) {
  JointAngles angles = zeroAngles();
  angles[dofOf("l_elbow", JointAxis::kY)] = radians * flexionSign("l_elbow", "l_wrist", Eigen::Vector3d::UnitX());
  return poseOf(angles);
}

std::vector<BezierPatch> posedPatches(Garment garment, const SkeletonPose& pose) {
  garment.pose(pose);
  return garment.patches();
}

BezierPatch flatPatch(double scale_u, double scale_v, double shear = 0.0) {
  BezierPatch::ControlPoints points;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      const double u = i / 3.0, v = j / 3.0;
      points[BezierPatch::index(i, j)] = Eigen::Vector3d(0.3 * scale_u * u + 0.2 * shear * v, 0.2 * scale_v * v, 0.0);
    }
  }
  return BezierPatch(points);
}

TEST(WrinklePlacement, StretchOfAKnownPatchPair) {
  const std::vector<BezierPatch> rest{flatPatch(1.0, 1.0)};
  // Uniform scale 0.8 along u: alpha = 0.8, along u; v keeps its length.
  const std::vector<BezierPatch> shortened{flatPatch(0.8, 1.0)};
  for (double u : {0.0, 0.3, 1.0}) {
    for (double v : {0.0, 0.7, 1.0}) {
      const PrincipalStretch s = measureStretch(rest, shortened, SurfacePoint{0, u, v});
      EXPECT_NEAR(s.alpha, 0.8, 1e-12);
      EXPECT_NEAR(s.smallest, 0.8, 1e-12);
      EXPECT_NEAR(s.largest, 1.0, 1e-12);
      EXPECT_NEAR(std::abs(s.direction.x()), 1.0, 1e-12);
      EXPECT_NEAR(std::abs(s.direction_uv.x()), 1.0 / 0.3, 1e-9);  // unit in the rest metric: |F_u| = 0.3
      EXPECT_NEAR(s.direction_uv.y(), 0.0, 1e-12);
    }
  }
  // Stretched everywhere: no compression.
  const PrincipalStretch stretched = measureStretch(rest, {flatPatch(1.2, 1.1)}, SurfacePoint{0, 0.5, 0.5});
  EXPECT_DOUBLE_EQ(stretched.alpha, 1.0);
  EXPECT_NEAR(stretched.smallest, 1.1, 1e-12);
  // Simple shear x += gamma y: principal stretches sqrt(1 + g^2/2 -+ g sqrt(1 + g^2/4)), the
  // compression along a diagonal.
  const double gamma = 0.4;
  const PrincipalStretch sheared = measureStretch(rest, {flatPatch(1.0, 1.0, gamma)}, SurfacePoint{0, 0.5, 0.5});
  EXPECT_NEAR(sheared.smallest, std::sqrt(1.0 + gamma * gamma / 2.0 - gamma * std::sqrt(1.0 + gamma * gamma / 4.0)),
              1e-12);
  EXPECT_NEAR(sheared.largest, std::sqrt(1.0 + gamma * gamma / 2.0 + gamma * std::sqrt(1.0 + gamma * gamma / 4.0)),
              1e-12);
  EXPECT_GT(std::abs(sheared.direction.x()), 0.4);
  EXPECT_GT(std::abs(sheared.direction.y()), 0.4);
  // A rigid motion changes nothing.
  BezierPatch::ControlPoints moved = rest[0].controlPoints();
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (Eigen::Vector3d& point : moved) point = rotation * point + Eigen::Vector3d(1, -2, 0.5);
  EXPECT_NEAR(measureStretch(rest, {BezierPatch(moved)}, SurfacePoint{0, 0.2, 0.9}).alpha, 1.0, 1e-12);
  EXPECT_THROW(measureStretch(rest, shortened, SurfacePoint{1, 0.5, 0.5}), std::invalid_argument);
  EXPECT_THROW(measureStretch(rest, {}, SurfacePoint{0, 0.5, 0.5}), std::invalid_argument);
}

TEST(WrinklePlacement, RestPoseHasNoCompressionAndNoWrinkles) {
  RigidTransform moved;  // a root motion is rigid: still the rest shape
  moved.translation = Eigen::Vector3d(1.0, -0.5, 0.1);
  moved.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(1.1, Eigen::Vector3d::UnitZ()));
  for (const char* name : {"jacket", "pants", "skirt", "one_piece"}) {
    SCOPED_TRACE(name);
    Garment garment = makeGarment(name);
    const WrinklePlacement placement(garment, skeleton(), body().shape);
    for (const RigidTransform& root : {RigidTransform(), moved}) {
      const SkeletonPose pose = poseOf(zeroAngles(), root);
      const std::vector<BezierPatch> posed = posedPatches(garment, pose);
      double worst = 0.0;
      for (std::uint32_t p = 0; p < posed.size(); ++p) {
        for (int j = 0; j <= 10; ++j) {
          for (int i = 0; i <= 10; ++i) {
            const PrincipalStretch s = placement.stretchAt(posed, SurfacePoint{p, i / 10.0, j / 10.0});
            if (s.degenerate) continue;
            worst = std::max({worst, std::abs(s.smallest - 1.0), std::abs(s.largest - 1.0)});
          }
        }
      }
      EXPECT_LT(worst, 1e-9);
      for (const RegionCompression& region : placement.measureRegions(posed, pose)) {
        EXPECT_NEAR(region.alpha, 1.0, 1e-9) << region.name;
        EXPECT_FALSE(region.wrinkles.wrinkled) << region.name;
        EXPECT_EQ(region.wrinkles.amplitude, 0.0) << region.name;
      }
      const PoseWrinkleMap map = makePoseWrinkleMap(placement, posed, pose, 16);
      EXPECT_EQ(map.atlas.maximumHeight(), 0.0f);
      EXPECT_EQ(map.atlas.minimumHeight(), 0.0f);
    }
  }
}

TEST(WrinklePlacement, RegionsOfEachGarment) {
  auto names = [](const WrinklePlacement& placement) {
    std::vector<std::string> result;
    for (const CompressionRegion& region : placement.regions()) {
      EXPECT_FALSE(region.samples.empty()) << region.name;
      result.push_back(region.name);
    }
    return result;
  };
  using Names = std::vector<std::string>;
  EXPECT_EQ(names(WrinklePlacement(makeGarment("pants"), skeleton(), body().shape)),
            (Names{"l_knee_back", "r_knee_back", "waist"}));
  EXPECT_EQ(names(WrinklePlacement(makeGarment("jacket"), skeleton(), body().shape)),
            (Names{"l_elbow_inside", "r_elbow_inside", "waist"}));
  EXPECT_EQ(names(WrinklePlacement(makeGarment("skirt"), skeleton(), body().shape)), (Names{"waist"}));
  const WrinklePlacement pants(makeGarment("pants"), skeleton(), body().shape);
  EXPECT_THROW(pants.region("l_elbow_inside"), std::invalid_argument);
}

TEST(WrinklePlacement, KneeBendCompressesBehindTheKneeOnly) {
  Garment pants = makeGarment("pants");
  const WrinklePlacement placement(pants, skeleton(), body().shape);
  const SkeletonPose pose = kneeBent(70.0 * kPi / 180.0);
  const std::vector<BezierPatch> posed = posedPatches(pants, pose);
  const RegionCompression left = placement.measureRegion(posed, pose, placement.region("l_knee_back"));
  const RegionCompression right = placement.measureRegion(posed, pose, placement.region("r_knee_back"));
  std::cout << "knee 70 deg: l_knee_back alpha " << left.alpha << " (min " << left.alpha_minimum << ", "
            << chainText(left.wrinkles.chain) << ", h1 " << left.wrinkles.amplitude << " m), local " << left.alpha_local
            << ", r_knee_back " << right.alpha << "\n";
  EXPECT_LT(left.alpha, 0.9);
  EXPECT_TRUE(left.wrinkles.wrinkled);
  EXPECT_GT(left.wrinkles.amplitude, 0.0);
  EXPECT_GT(right.alpha, 0.999);
  EXPECT_LT(left.alpha_local, 0.9);
  EXPECT_EQ(left.alpha, left.alpha_span);
  EXPECT_GE(placement.region("l_knee_back").spans.size(), 4u);
  // The compression runs mostly along the leg (the thigh axis at rest, the bent leg's axes in
  // the pose: measured against the rest directions carried by the material, i.e. in uv).
  const std::size_t thigh = static_cast<std::size_t>(skeleton().findBone("l_hip"));
  const Eigen::Vector3d thigh_axis = poseOf(zeroAngles()).bone_in_world[thigh].rotation * Eigen::Vector3d::UnitZ();
  int compressed = 0, along_leg = 0;
  for (const SurfacePoint& at : placement.region("l_knee_back").samples) {
    const PrincipalStretch s = placement.stretchAt(posed, at);
    if (s.alpha > WrinklePlacementOptions().alpha_threshold) continue;
    const PatchDerivatives rest = placement.restPatches()[at.patch].derivatives(at.u, at.v);
    const Eigen::Vector3d rest_direction =
        (rest.d_du * s.direction_uv.x() + rest.d_dv * s.direction_uv.y()).normalized();
    ++compressed;
    if (std::abs(rest_direction.dot(thigh_axis)) > 0.7) ++along_leg;
  }
  std::cout << "knee 70 deg: " << along_leg << " of " << compressed << " compressed samples compress along the leg\n";
  EXPECT_GT(along_leg, compressed / 2);
  // The front of the thigh (centre front strip, more than 10 cm above the knee) stays nearly
  // uncompressed, and the back of the leg far from the knee (more than 25 cm along the thigh
  // axis) much less compressed than behind it (not necessarily alpha = 1: the knee's bend
  // reaches as far as the leg patch that spans the knee).
  const SkeletonPose rest = poseOf(zeroAngles());
  const Eigen::Vector3d knee = rest.bone_in_world[static_cast<std::size_t>(skeleton().findBone("l_knee"))].translation;
  const std::vector<BezierPatch>& rest_patches = placement.restPatches();
  double front_min = 1.0, far_back_min = 1.0;
  int front_samples = 0, far_back_samples = 0;
  for (std::uint32_t p = 0; p < rest_patches.size(); ++p) {
    if (pants.net().patchPiece(p) != "l_leg") continue;
    for (int j = 0; j <= 16; ++j) {
      for (int i = 0; i <= 16; ++i) {
        const PatchSample sample = rest_patches[p].sample(i / 16.0, j / 16.0);
        const double along = (sample.position - knee).dot(thigh_axis);
        const double alpha = placement.stretchAt(posed, SurfacePoint{p, i / 16.0, j / 16.0}).alpha;
        if (sample.normal.x() >= 0.9 && along < -0.10) {
          front_min = std::min(front_min, alpha);
          ++front_samples;
        }
        if (sample.normal.x() <= -0.5 && std::abs(along) > 0.25) {
          far_back_min = std::min(far_back_min, alpha);
          ++far_back_samples;
        }
      }
    }
  }
  std::cout << "knee 70 deg: front of thigh min alpha " << front_min << " (" << front_samples
            << " samples), back of leg far from the knee " << far_back_min << " (" << far_back_samples << ")\n";
  EXPECT_GT(front_samples, 10);
  EXPECT_GT(far_back_samples, 10);
  EXPECT_GT(front_min, 0.9);
  EXPECT_GT(front_min, left.alpha + 0.5);
  EXPECT_GT(far_back_min, left.alpha + 0.15);
}

TEST(WrinklePlacement, BehindKneeAlphaFallsMonotonicallyWithFlexion) {
  Garment pants = makeGarment("pants");
  const WrinklePlacement placement(pants, skeleton(), body().shape);
  // alpha (the span measure, RegionCompression::alpha_span) falls strictly until the garment's
  // back meets itself behind the knee (the most compressed spans close), then stays 0; it must
  // stay above 0 over the walk's range (< 75 degrees).
  double previous = 1.0 + 1e-12;
  for (int degrees = 5; degrees <= 120; degrees += 5) {
    const SkeletonPose pose = kneeBent(degrees * kPi / 180.0);
    const RegionCompression region =
        placement.measureRegion(posedPatches(pants, pose), pose, placement.region("l_knee_back"));
    const double alpha = region.alpha;
    std::cout << "knee " << degrees << " deg: l_knee_back alpha " << alpha << " (local " << region.alpha_local << ")\n";
    if (previous > 0.0) {
      EXPECT_LT(alpha, previous) << degrees << " degrees";
    } else {
      EXPECT_EQ(alpha, 0.0) << degrees << " degrees";
    }
    if (degrees <= 75) {
      EXPECT_GT(alpha, 0.0) << degrees << " degrees";
    }
    previous = alpha;
  }
}

TEST(WrinklePlacement, ElbowBendCompressesInsideTheElbow) {
  Garment jacket = makeGarment("jacket");
  const WrinklePlacement placement(jacket, skeleton(), body().shape);
  const SkeletonPose pose = elbowBent(80.0 * kPi / 180.0);
  const std::vector<BezierPatch> posed = posedPatches(jacket, pose);
  const RegionCompression inside = placement.measureRegion(posed, pose, placement.region("l_elbow_inside"));
  const RegionCompression other = placement.measureRegion(posed, pose, placement.region("r_elbow_inside"));
  std::cout << "elbow 80 deg: l_elbow_inside alpha " << inside.alpha << " (" << chainText(inside.wrinkles.chain)
            << "), r_elbow_inside " << other.alpha << "\n";
  EXPECT_LT(inside.alpha, 0.9);
  EXPECT_GT(other.alpha, 0.999);
  // The outside of the elbow (facing backwards) is stretched, not compressed.
  const std::vector<BezierPatch>& rest = placement.restPatches();
  const Eigen::Vector3d elbow =
      poseOf(zeroAngles()).bone_in_world[static_cast<std::size_t>(skeleton().findBone("l_elbow"))].translation;
  double outside_min = 1.0;
  for (std::uint32_t p = 0; p < rest.size(); ++p) {
    if (jacket.net().patchPiece(p) != "l_sleeve") continue;
    for (int j = 0; j <= 16; ++j) {
      for (int i = 0; i <= 16; ++i) {
        const PatchSample sample = rest[p].sample(i / 16.0, j / 16.0);
        if (sample.normal.x() > -0.7 || std::abs(sample.position.z() - elbow.z()) > 0.05) continue;
        outside_min = std::min(outside_min, placement.stretchAt(posed, SurfacePoint{p, i / 16.0, j / 16.0}).alpha);
      }
    }
  }
  EXPECT_GT(outside_min, inside.alpha + 0.05);
}

TEST(WrinklePlacement, WaistTwistCompressesTheWaistDiagonally) {
  for (const char* name : {"jacket", "pants"}) {
    SCOPED_TRACE(name);
    Garment garment = makeGarment(name);
    const WrinklePlacement placement(garment, skeleton(), body().shape);
    JointAngles angles = zeroAngles();
    angles[dofOf("waist", JointAxis::kZ)] = 0.4;
    const RegionCompression waist =
        placement.measureRegion(posedPatches(garment, poseOf(angles)), poseOf(angles), placement.region("waist"));
    std::cout << name << " waist twist 0.4 rad: alpha " << waist.alpha << " direction " << waist.direction.transpose()
              << "\n";
    EXPECT_LT(waist.alpha, 0.97);
    EXPECT_TRUE(waist.wrinkles.wrinkled);
    // A shear's compression is diagonal: neither along the body axis nor around it.
    EXPECT_GT(std::abs(waist.direction.z()), 0.3);
    EXPECT_LT(std::abs(waist.direction.z()), 0.95);
    // Twisting the other way compresses the other diagonal: alpha about the same.
    angles[dofOf("waist", JointAxis::kZ)] = -0.4;
    const RegionCompression back =
        placement.measureRegion(posedPatches(garment, poseOf(angles)), poseOf(angles), placement.region("waist"));
    EXPECT_LT(back.alpha, 0.97);
  }
}

TEST(WrinklePlacement, WalkBehindKneeIsMostCompressedWhenTheKneeBendsMost) {
  Garment pants = makeGarment("pants");
  const WrinklePlacement placement(pants, skeleton(), body().shape);
  const std::vector<SkeletonPose> poses = walkPoses(60, body().shape);
  const std::size_t thigh = static_cast<std::size_t>(skeleton().findBone("l_hip"));
  const std::size_t shank = static_cast<std::size_t>(skeleton().findBone("l_knee"));
  std::vector<double> alpha, bend;
  for (const SkeletonPose& pose : poses) {
    alpha.push_back(placement.measureRegion(posedPatches(pants, pose), pose, placement.region("l_knee_back")).alpha);
    const Eigen::Vector3d a = pose.bone_in_world[thigh].rotation * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d b = pose.bone_in_world[shank].rotation * Eigen::Vector3d::UnitZ();
    bend.push_back(std::acos(std::clamp(a.dot(b), -1.0, 1.0)));
  }
  const auto lowest = std::min_element(alpha.begin(), alpha.end()) - alpha.begin();
  const auto most_bent = std::max_element(bend.begin(), bend.end()) - bend.begin();
  const auto least_bent = std::min_element(bend.begin(), bend.end()) - bend.begin();
  std::cout << "walk: lowest l_knee_back alpha " << alpha[lowest] << " at pose " << lowest << ", knee bent most ("
            << bend[most_bent] * 180.0 / kPi << " deg) at pose " << most_bent << "; least bent "
            << bend[least_bent] * 180.0 / kPi << " deg, alpha there " << alpha[least_bent] << "\n";
  const long n = static_cast<long>(poses.size());
  const long distance = std::min(std::labs(lowest - most_bent), n - std::labs(lowest - most_bent));
  EXPECT_LE(distance, 2);
  EXPECT_LT(alpha[lowest], alpha[least_bent] - 0.05);
  // More bend, more compression over the whole cycle: rank correlation strongly negative.
  auto ranks = [](const std::vector<double>& values) {
    std::vector<std::size_t> order(values.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    std::vector<double> rank(values.size());
    for (std::size_t k = 0; k < order.size(); ++k) rank[order[k]] = static_cast<double>(k);
    return rank;
  };
  const std::vector<double> ra = ranks(alpha), rb = ranks(bend);
  double d2 = 0.0;
  for (std::size_t k = 0; k < ra.size(); ++k) d2 += (ra[k] - rb[k]) * (ra[k] - rb[k]);
  const double spearman = 1.0 - 6.0 * d2 / (static_cast<double>(n) * (static_cast<double>(n) * n - 1.0));
  std::cout << "walk: Spearman(alpha, knee bend) = " << spearman << "\n";
  EXPECT_LT(spearman, -0.8);
}

TEST(WrinklePlacement, PoseMapReliefGrowsWithCompression) {
  // The relief behind the knee grows as alpha falls, towards its ceiling: h1 = sqrt(1 -
  // alpha^2) L_y <= L_y (and <= L_x for Y/X, where clampToDomainEdge stops it). Strictly at
  // every step until the ceiling: the rows behind the knee take the region's span measure,
  // which keeps falling where the local one stalls and recovers (40-75 degrees; before the map
  // used it, the height here only held near its 30-degree value).
  Garment pants = makeGarment("pants");
  const WrinklePlacement placement(pants, skeleton(), body().shape);
  double previous_alpha = 1.0, previous_height = 0.0, peak = 0.0;
  std::vector<std::uint32_t> patches;
  for (const SurfacePoint& at : placement.region("l_knee_back").samples) {
    if (std::find(patches.begin(), patches.end(), at.patch) == patches.end()) patches.push_back(at.patch);
  }
  double bound = 0.0;
  for (std::uint32_t p : patches) {
    bound =
        std::max(bound, std::min(placement.layouts()[p].cell.half_width_x, placement.layouts()[p].cell.half_length_y));
  }
  for (int degrees : {0, 4, 8, 12, 16, 30, 45, 60, 75}) {
    const SkeletonPose pose = kneeBent(degrees * kPi / 180.0);
    const std::vector<BezierPatch> posed = posedPatches(pants, pose);
    const double alpha = placement.measureRegion(posed, pose, placement.region("l_knee_back")).alpha;
    const PoseWrinkleMap map = makePoseWrinkleMap(placement, posed, pose, 64);
    EXPECT_EQ(map.atlas.width, 64 * static_cast<int>(posed.size()));
    double height = 0.0;
    for (std::uint32_t p : patches) {
      const int first = static_cast<int>(p) * map.tile_pixels;
      for (int row = 0; row < map.atlas.height; ++row) {
        for (int column = first; column < first + map.tile_pixels; ++column) {
          height = std::max(height, static_cast<double>(map.atlas.heights[map.atlas.index(column, row)]));
        }
      }
    }
    std::cout << "knee " << degrees << " deg: alpha " << alpha << ", max wrinkle height behind the knee "
              << height * 1000.0 << " mm\n";
    if (degrees > 0) {
      EXPECT_LT(alpha, previous_alpha) << degrees;
    }
    if (alpha >= placement.options().alpha_threshold) {
      EXPECT_EQ(height, 0.0) << degrees;  // within the cloth's ease: smooth
    } else {
      if (previous_height < bound * (1.0 - 1e-6)) {
        EXPECT_GT(height, previous_height) << degrees;
      } else {
        EXPECT_GE(height, previous_height * (1.0 - 1e-6)) << degrees;
      }
    }
    EXPECT_LE(height, bound * (1.0 + 1e-6)) << degrees;
    previous_alpha = alpha;
    previous_height = height;
    peak = std::max(peak, height);
  }
  EXPECT_GT(peak, 0.8 * bound);
}

TEST(WrinklePlacement, PatternRuleAndAmplitude) {
  WrinklePlacementOptions options;
  const BucklingCell cell{0.03, 0.025};
  // No wrinkles above the threshold; the relief starts from zero below it.
  const WrinkleChoice none = chooseWrinkles(0.99, FoldChain::kX, cell, options);
  EXPECT_FALSE(none.wrinkled);
  EXPECT_EQ(none.amplitude, 0.0);
  const WrinkleChoice just = chooseWrinkles(options.alpha_threshold - 0.001, FoldChain::kI, cell, options);
  EXPECT_TRUE(just.wrinkled);
  EXPECT_LT(just.amplitude, 0.1 * cell.half_length_y);
  const WrinkleChoice some = chooseWrinkles(0.8, FoldChain::kI, cell, options);
  const double effective = 0.8 / options.alpha_threshold;
  EXPECT_DOUBLE_EQ(some.alpha_effective, effective);
  EXPECT_NEAR(some.amplitude, std::sqrt(1.0 - effective * effective) * cell.half_length_y, 1e-15);
  // Y/X beyond their domain (h1 > L_x): clamped by the default policy, or as the policy says.
  const BucklingCell narrow{0.01, 0.025};
  const WrinkleChoice clamped = chooseWrinkles(0.3, FoldChain::kX, narrow, options);
  EXPECT_TRUE(clamped.solution.clamped);
  EXPECT_NEAR(clamped.amplitude, narrow.half_width_x, 1e-12);
  options.out_of_domain = OutOfDomainPolicy::throwError;
  EXPECT_THROW(chooseWrinkles(0.3, FoldChain::kX, narrow, options), std::domain_error);
  options = WrinklePlacementOptions();
  EXPECT_THROW(chooseWrinkles(1.5, FoldChain::kX, cell, options), std::invalid_argument);
  // The rule: the chain whose curl per cell is nearest the surface's turn per cell.
  const double bend = solveBuckling(PatternKind::X, options.reference_alpha, cell).bend_angle;
  EXPECT_EQ(chooseChain(0.0, cell, options), FoldChain::kI);
  EXPECT_EQ(chooseChain(0.2 * bend, cell, options), FoldChain::kI);
  EXPECT_EQ(chooseChain(0.5 * bend, cell, options), FoldChain::kYY);
  EXPECT_EQ(chooseChain(bend, cell, options), FoldChain::kX);
  // On the garments: tubes (sleeves, trouser legs) get a curling chain, never I.
  for (const char* name : {"jacket", "pants"}) {
    Garment garment = makeGarment(name);
    const WrinklePlacement placement(garment, skeleton(), body().shape);
    for (std::size_t p = 0; p < garment.patches().size(); ++p) {
      const std::string& piece = garment.net().patchPiece(p);
      const PatchWrinkleLayout& layout = placement.layouts()[p];
      std::cout << name << " patch " << p << " (" << piece << "): " << layout.rows << " x " << layout.cells_around
                << " cells " << 2000.0 * layout.cell.half_length_y << " x " << 2000.0 * layout.cell.half_width_x
                << " mm, turn/cell " << layout.turn_per_cell << " rad -> " << chainText(layout.chain) << "\n";
      if (piece.find("sleeve") != std::string::npos || piece.find("_leg") != std::string::npos) {
        EXPECT_NE(layout.chain, FoldChain::kI) << p;
      }
    }
  }
  WrinklePlacementOptions bad;
  bad.cells_around = 3;
  EXPECT_THROW(WrinklePlacement(makeGarment("pants"), skeleton(), body().shape, bad), std::invalid_argument);
  bad = WrinklePlacementOptions();
  bad.alpha_threshold = 0.0;
  EXPECT_THROW(VertexCompression{bad}, std::invalid_argument);
}

TEST(WrinklePlacement, PerVertexApiEqualsTheDirectComputation) {
  for (const char* name : {"jacket", "pants"}) {
    for (int level : {4, 8}) {
      SCOPED_TRACE(std::string(name) + " level " + std::to_string(level));
      Garment garment = makeGarment(name);
      const WrinklePlacement placement(garment, skeleton(), body().shape);
      const std::vector<SkeletonPose> poses = walkPoses(8, body().shape);
      Tessellator tessellator;
      VertexCompression compression;
      std::vector<float> alpha, strength;
      for (std::size_t k = 0; k < poses.size(); ++k) {
        garment.pose(poses[k]);
        const TriangleMesh& mesh = tessellator.tessellateUniform(garment.patches(), garment.topology(), level);
        if (k == 0) {
          EXPECT_FALSE(compression.preparedFor(mesh));
          compression.prepare(mesh, placement.restPatches());
        }
        ASSERT_TRUE(compression.preparedFor(mesh));
        alpha.assign(mesh.vertexCount(), -1.0f);
        strength.assign(mesh.vertexCount(), -1.0f);
        compression.evaluate(mesh, alpha.data(), strength.data());
        double worst = 0.0, worst_tangent = 0.0, lowest = 1.0;
        for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
          const SurfacePoint at{compression.vertexPatches()[i], mesh.uv[i].x(), mesh.uv[i].y()};
          // The vertex's tangents are its patch's at its uv (the ownership rule prepare() relies on).
          const PatchDerivatives d = garment.patches()[at.patch].derivatives(at.u, at.v);
          worst_tangent = std::max({worst_tangent, (mesh.tangents_u[i].cast<double>() - d.d_du).norm() / d.d_du.norm(),
                                    (mesh.tangents_v[i].cast<double>() - d.d_dv).norm() / d.d_dv.norm()});
          const PrincipalStretch direct = placement.stretchAt(garment.patches(), at);
          worst = std::max(worst, std::abs(direct.alpha - alpha[i]));
          lowest = std::min(lowest, direct.alpha);
          const double effective = std::min(1.0, direct.alpha / WrinklePlacementOptions().alpha_threshold);
          const double expected = std::min(1.0, std::sqrt(1.0 - effective * effective) / std::sqrt(1.0 - 0.36));
          EXPECT_NEAR(strength[i], expected, 2e-3) << i;
          ASSERT_GE(strength[i], 0.0f);
          ASSERT_LE(strength[i], 1.0f);
        }
        EXPECT_LT(worst_tangent, 1e-5);
        EXPECT_LT(worst, 1e-3);  // float: the renderer's precision
        if (k == 0)
          std::cout << name << " level " << level << ": " << mesh.vertexCount() << " vertices, lowest alpha " << lowest
                    << "\n";
      }
      // update(): same result, prepares only when the layout changes.
      std::vector<float> updated;
      compression.update(tessellator.mesh(), placement.restPatches(), updated);
      for (std::size_t i = 0; i < updated.size(); ++i) ASSERT_FLOAT_EQ(updated[i], strength[i]);
      const TriangleMesh& finer = tessellator.tessellateUniform(garment.patches(), garment.topology(), level + 1);
      EXPECT_FALSE(compression.preparedFor(finer));
      EXPECT_THROW(compression.evaluate(finer, nullptr, updated.data()), std::invalid_argument);
      compression.update(finer, placement.restPatches(), updated);
      EXPECT_EQ(updated.size(), finer.vertexCount());
    }
  }
  // Rest pose through the per-vertex path: alpha 1 to float precision, strength 0.
  Garment jacket = makeGarment("jacket");
  const WrinklePlacement placement(jacket, skeleton(), body().shape);
  Tessellator tessellator;
  const TriangleMesh& mesh = tessellator.tessellateUniform(placement.restPatches(), jacket.topology(), 4);
  VertexCompression compression;
  std::vector<float> strength;
  compression.update(mesh, placement.restPatches(), strength);
  std::vector<float> alpha(mesh.vertexCount());
  compression.evaluate(mesh, alpha.data(), nullptr);
  for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
    ASSERT_NEAR(alpha[i], 1.0f, 1e-5f) << i;
    ASSERT_EQ(strength[i], 0.0f) << i;
  }
}

}  // namespace
}  // namespace dressed_human

namespace dressed_human {
namespace {

// Issue 21, part 3: the strength the renderer shows behind the knee (vertexStretchAt at the
// region's samples) is zero on a straight leg, grows with the bend and never jumps: a frame of
// a walk moves the knee by a few degrees at most, so one degree may change it little.
TEST(WrinklePlacement, ShownStrengthGrowsWithTheKneeBendWithoutJumps) {
  Garment pants = makeGarment("pants");
  const WrinklePlacement placement(pants, skeleton(), body().shape);
  const WrinkleStrengthConstants constants = VertexCompression(placement.options()).strengthConstants();
  const CompressionRegion& knee = placement.region("l_knee_back");
  double previous = 0.0;
  for (int degrees = 0; degrees <= 80; ++degrees) {
    const std::vector<BezierPatch> posed = posedPatches(pants, kneeBent(degrees * kPi / 180.0));
    double sum = 0.0;
    for (const SurfacePoint& at : knee.samples) {
      const PatchDerivatives rest = placement.restPatches()[at.patch].derivatives(at.u, at.v);
      const PatchDerivatives now = posed[at.patch].derivatives(at.u, at.v);
      sum += vertexStretchAt(inverseRestMetric(rest.d_du, rest.d_dv), now.d_du.cast<float>(), now.d_dv.cast<float>(),
                             constants)
                 .strength;
    }
    const double mean = sum / static_cast<double>(knee.samples.size());
    EXPECT_LT(std::abs(mean - previous), 0.04) << "a jump at " << degrees << " deg";
    if (degrees == 0) {
      EXPECT_EQ(mean, 0.0);
    } else if (degrees <= 60) {
      EXPECT_GE(mean, previous - 1e-3) << "fading while bending at " << degrees << " deg";
    }
    if (degrees == 60) {
      EXPECT_GT(mean, 0.6);
    }
    previous = mean;
  }
}

}  // namespace
}  // namespace dressed_human
