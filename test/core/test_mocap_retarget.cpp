// Retargeting: a BVH written from our own skeleton (our rest pose in BVH's Y-up axes, a rotation
// order unlike ours) comes back as exactly the joint angles that made it; the CMU walk retargets
// to a walk; joint maps name what is missing.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <functional>
#include <random>
#include <sstream>
#include <string>

#include "dressed_human/core/motion/bvh_file.h"
#include "dressed_human/core/motion/fit_accuracy.h"
#include "dressed_human/core/motion/motion_fit.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/motion/mocap_joint_map.h"
#include "dressed_human/core/motion/mocap_retarget.h"
#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/motion/motion.h"
#include "bvh_test_support.h"

namespace dressed_human {
namespace {

const std::string kSource = DRESSED_HUMAN_SOURCE_DIR;
constexpr double kPi = 3.14159265358979323846;

TEST(MocapRetarget, OwnSkeletonRoundTripsExactly) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(kSource + "/urdf/human.urdf");
  std::mt19937 random(11);
  std::uniform_real_distribution<double> angle(-0.6, 0.6);  // away from the gimbal of the x DOF
  std::vector<std::pair<RigidTransform, JointAngles>> poses;
  for (int k = 0; k < 5; ++k) {
    RigidTransform root;
    root.translation = Eigen::Vector3d(0.3 * k, 0.05, 0.95);
    root.rotation = Eigen::AngleAxisd(angle(random), Eigen::Vector3d::UnitZ()) *
                    Eigen::AngleAxisd(0.2 * angle(random), Eigen::Vector3d::UnitX());
    JointAngles angles{};
    for (double& a : angles) a = angle(random);
    poses.emplace_back(root, angles);
  }
  const BvhClip clip = parseBvh(bvhOfOurSkeleton(skeleton, poses), "own.bvh");
  const SampledMotion motion = retargetBvh(clip, chooseBvhJointMap(clip, "own.bvh"), skeleton, "own.bvh");
  ASSERT_EQ(motion.angles.size(), poses.size());
  EXPECT_NEAR(motion.reference_scale, 1.0, 1e-9);
  EXPECT_NEAR(motion.root_scale, 1.0, 1e-9);
  const ForwardKinematics kinematics(skeleton);
  // A foot's pitch is set where the capture's foot stands flat (its stillest frames: footAim in
  // mocap_retarget.cpp; FootOfTheCmuWalkStandsFlatWhereTheCaptureStandsStill), so our own feet
  // come back with the same heading only. Every other DOF comes back as it was.
  const std::array<int, 2> feet = {skeleton.findBone("l_ankle"), skeleton.findBone("r_ankle")};
  const auto onFoot = [&](std::size_t dof) {
    const int bone = skeleton.joint(dof / kDofsPerJoint).bone;
    return bone == feet[0] || bone == feet[1];
  };
  for (std::size_t f = 0; f < poses.size(); ++f) {
    for (std::size_t i = 0; i < kDofCount; ++i) {
      if (onFoot(i)) continue;
      EXPECT_NEAR(motion.angles[f][i], poses[f].second[i], 1e-9) << "frame " << f << " " << Motion().seriesName(i);
    }
    SkeletonPose written, read;
    kinematics.compute(poses[f].first, poses[f].second, written);
    kinematics.compute(motion.root[f], motion.angles[f], read);
    for (int foot : feet) {
      const Eigen::Vector3d before =
          written.bone_in_world[static_cast<std::size_t>(foot)].rotation * Eigen::Vector3d::UnitZ();
      const Eigen::Vector3d after =
          read.bone_in_world[static_cast<std::size_t>(foot)].rotation * Eigen::Vector3d::UnitZ();
      EXPECT_NEAR(std::atan2(after.y(), after.x()), std::atan2(before.y(), before.x()), 1e-9)
          << "frame " << f << " foot " << foot;
    }
    EXPECT_LT(motion.root[f].rotation.angularDistance(poses[f].first.rotation), 1e-9);
    EXPECT_LT((motion.root[f].translation - poses[f].first.translation).norm(), 1e-9);
    SkeletonPose pose;
    RigidTransform root = poses[f].first;
    root.translation.setZero();
    kinematics.compute(root, poses[f].second, pose);
    for (std::size_t j = 0; j < kJointCount; ++j) {
      const Eigen::Vector3d& ours = pose.bone_in_world[static_cast<std::size_t>(skeleton.joint(j).bone)].translation;
      EXPECT_LT((motion.reference_joint_positions[f][j] - ours).norm(), 1e-9) << humanJointNames()[j];
    }
  }
}

// Issue 39: where the capture's foot stands flat (its ankle still: slower than a tenth of the
// walk's speed), our drawn foot stands flat too: heel and ball level, and the two sides of the
// ball level, at the median within 3 mm, nine frames in ten within the 1 cm in which issue 39
// counts a sole point down. (Aimed at the capture's toe tip itself, every stance rode on the toes,
// the heel 4 cm up; rolled as the capture's foot joint is, the feet stood 20 deg on their edges.)
TEST(MocapRetarget, FootOfTheCmuWalkStandsFlatWhereTheCaptureStandsStill) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(kSource + "/urdf/human.urdf");
  const BodyDescription body = loadBodyDescriptionFile(kSource + "/config/bodies/default.yaml", skeleton);
  const std::string path = kSource + "/data/motion/cmu_02_01_walk.bvh";
  const BvhClip clip = loadBvhFile(path);
  RetargetOptions options;
  options.body = std::make_shared<const BodyDescription>(body);
  const SampledMotion motion = retargetBvh(clip, chooseBvhJointMap(clip, path), skeleton, path, options);
  const FootSoles soles = motion.soles(skeleton);
  const ForwardKinematics kinematics(skeleton);
  const double dt = motion.frameTime();
  const double walk_speed = (motion.root.back().translation - motion.root.front().translation).head<2>().norm() /
                            (dt * static_cast<double>(motion.root.size() - 1));
  std::vector<SkeletonPose> poses(motion.angles.size());
  for (std::size_t f = 0; f < poses.size(); ++f) kinematics.compute(motion.root[f], motion.angles[f], poses[f]);
  for (std::size_t side = 0; side < 2; ++side) {
    const std::size_t ankle = static_cast<std::size_t>(skeleton.findBone(side == 0 ? "l_ankle" : "r_ankle"));
    std::vector<double> tilts;  // ball above heel, m
    std::vector<double> sides;  // one side of the ball above the other, m
    const auto segment = std::find_if(body.segments.begin(), body.segments.end(),
                                      [&](const SkinSegmentSpec& s) { return s.bone == skeleton.bone(ankle).name; });
    ASSERT_NE(segment, body.segments.end());
    const double ball_width = 2.0 * segment->sections.back().radius_y;
    for (std::size_t f = 1; f + 1 < poses.size(); ++f) {
      const double speed =
          (poses[f + 1].bone_in_world[ankle].translation - poses[f - 1].bone_in_world[ankle].translation)
              .head<2>()
              .norm() /
          (2.0 * dt);
      if (speed > 0.1 * walk_speed) continue;
      tilts.push_back(soles.point(poses[f], soles.ball(side)).z() - soles.point(poses[f], soles.heel(side)).z());
      sides.push_back(ball_width * (poses[f].bone_in_world[ankle].rotation * Eigen::Vector3d::UnitY()).z());
    }
    ASSERT_GE(tilts.size(), 30u) << "side " << side;
    std::sort(tilts.begin(), tilts.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
    EXPECT_LT(std::abs(tilts[tilts.size() / 2]), 0.003) << "side " << side << ": median, m";
    EXPECT_LT(std::abs(tilts[tilts.size() * 9 / 10]), 0.01) << "side " << side << ": 90 %, m";
    std::cout << "side " << side << ": " << tilts.size() << " still frames, ball above heel median "
              << 1000.0 * tilts[tilts.size() / 2] << " mm, 90 % within "
              << 1000.0 * std::abs(tilts[tilts.size() * 9 / 10]) << " mm\n";
    std::sort(sides.begin(), sides.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
    EXPECT_LT(std::abs(sides[sides.size() / 2]), 0.003) << "side " << side << ": median, m";
    EXPECT_LT(std::abs(sides[sides.size() * 9 / 10]), 0.01) << "side " << side << ": 90 %, m";
    std::cout << "side " << side << ": one side of the ball above the other, median "
              << 1000.0 * sides[sides.size() / 2] << " mm, 90 % within "
              << 1000.0 * std::abs(sides[sides.size() * 9 / 10]) << " mm\n";
  }
}

TEST(MocapRetarget, CmuWalkBendsKneesForward) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(kSource + "/urdf/human.urdf");
  const std::string path = kSource + "/data/motion/cmu_02_01_walk.bvh";
  const BvhClip clip = loadBvhFile(path);
  const BvhJointMap map = chooseBvhJointMap(clip, path);
  EXPECT_EQ(map.name, "CMU BVH");
  const SampledMotion motion = retargetBvh(clip, map, skeleton, path);
  double max_knee = -10.0;
  double min_knee = 10.0;
  for (std::size_t f = 1; f < motion.angles.size(); ++f) {  // frame 0 is the capture's bind pose
    for (const std::size_t knee : {11u, 14u}) {
      max_knee = std::max(max_knee, motion.angles[f][knee * kDofsPerJoint]);
      min_knee = std::min(min_knee, motion.angles[f][knee * kDofsPerJoint]);
    }
  }
  EXPECT_GT(max_knee, 50.0 * kPi / 180.0);  // swing-phase flexion, +y
  EXPECT_GT(min_knee, -5.0 * kPi / 180.0);  // never bends backwards
}

TEST(MocapJointMap, MissingJointsAreNamed) {
  const std::string path = kSource + "/data/motion/cmu_02_01_walk.bvh";
  BvhClip clip = loadBvhFile(path);
  clip.joints[static_cast<std::size_t>(clip.findJoint("LeftLeg"))].name = "LeftShin";
  clip.joints[static_cast<std::size_t>(clip.findJoint("Head"))].name = "Skull";
  try {
    chooseBvhJointMap(clip, path);
    FAIL() << "a renamed joint must be reported";
  } catch (const JointMapError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("LeftLeg"), std::string::npos) << message;
    EXPECT_NE(message.find("Head"), std::string::npos) << message;
    EXPECT_NE(message.find("--map"), std::string::npos) << message;
  }
}

TEST(MocapJointMap, YamlMapForOtherNames) {
  const JointMapFile file = parseJointMapYaml(
      "kind: bvh\nroot: pelvis\njoints: {waist: s1, torso: s2, neck: n, head: h, l_shoulder: la, l_elbow: lf,"
      " l_wrist: ~, r_shoulder: ra, r_elbow: rf, r_wrist: ~, l_hip: lt, l_knee: ls, l_ankle: lfoot,"
      " r_hip: rt, r_knee: rs, r_ankle: rfoot}\n",
      "map.yaml");
  EXPECT_EQ(file.kind, "bvh");
  EXPECT_EQ(file.bvh.root, "pelvis");
  EXPECT_EQ(file.bvh.joints[11], "ls");
  EXPECT_TRUE(file.bvh.joints[6].empty());
  EXPECT_THROW(parseJointMapYaml("kind: bvh\nroot: p\njoints: {waist: s}\n", "m.yaml"), JointMapError);
  EXPECT_THROW(parseJointMapYaml("kind: bvh\nroot: p\njoints: {elbow: s}\n", "m.yaml"), JointMapError);
  EXPECT_THROW(parseJointMapYaml("kind: c3d\n", "m.yaml"), JointMapError);
  const JointMapFile coordinates = parseJointMapYaml(
      "kind: coordinates\nroot: {translation: [tx, ty, ~], rotation: [[tilt, 0, 0, 1]]}\n"
      "joints: {waist: ~, torso: ~, neck: ~, head: ~, l_shoulder: ~, l_elbow: ~, l_wrist: ~, r_shoulder: ~,"
      " r_elbow: ~, r_wrist: ~, l_hip: [[hip_l, 0, 0, 2]], l_knee: ~, l_ankle: ~, r_hip: ~, r_knee: ~, r_ankle: ~}\n",
      "coordinates.yaml");
  ASSERT_EQ(coordinates.coordinates.joints[10].size(), 1u);
  EXPECT_NEAR(coordinates.coordinates.joints[10][0].axis.z(), 1.0, 1e-12);  // normalised
  EXPECT_TRUE(coordinates.coordinates.root_translation[2].empty());
}

// An arm raised through the y-x-z split's singularity (the shoulder's x crosses 90 degrees twice a
// cycle, as a reaching or strutting arm does): the retarget gives back the angles that made it,
// continuous, and the Fourier order that made them fits them to the capture within a millimetre.
// decomposeYxz's principal branch turned y and z by half a turn and mirrored x while x > 90
// degrees, and the smooth series then cut the corner (issue 39).
TEST(MocapRetarget, AnArmThroughTheGimbalKeepsItsAngles) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(kSource + "/urdf/human.urdf");
  const auto& names = humanJointNames();
  const auto shoulder = static_cast<std::size_t>(
      std::find_if(names.begin(), names.end(), [](const char* name) { return std::string(name) == "l_shoulder"; }) -
      names.begin());
  ASSERT_LT(shoulder, kJointCount);
  std::vector<std::pair<RigidTransform, JointAngles>> poses;
  int beyond_the_singularity = 0;
  for (int f = 0; f < 200; ++f) {  // two cycles of 1 s at the BVH's 0.01 s per frame
    const double phase = 2.0 * kPi * 0.01 * f;
    RigidTransform root;
    root.translation = Eigen::Vector3d(0.0, 0.0, 0.95);
    JointAngles angles{};
    angles[shoulder * kDofsPerJoint] = 0.3 * std::sin(phase);
    angles[shoulder * kDofsPerJoint + 1] = 1.25 + 0.55 * std::sin(phase);
    angles[shoulder * kDofsPerJoint + 2] = 0.4 * std::cos(phase);
    beyond_the_singularity += angles[shoulder * kDofsPerJoint + 1] > 0.5 * kPi ? 1 : 0;
    poses.emplace_back(root, angles);
  }
  ASSERT_GT(beyond_the_singularity, 40);
  const BvhClip clip = parseBvh(bvhOfOurSkeleton(skeleton, poses), "arm.bvh");
  const SampledMotion motion = retargetBvh(clip, chooseBvhJointMap(clip, "arm.bvh"), skeleton, "arm.bvh");
  ASSERT_EQ(motion.angles.size(), poses.size());
  for (std::size_t f = 0; f < poses.size(); ++f) {
    for (std::size_t d = 0; d < kDofsPerJoint; ++d) {
      const std::size_t i = shoulder * kDofsPerJoint + d;
      ASSERT_NEAR(motion.angles[f][i], poses[f].second[i], 1e-6) << "frame " << f << " " << Motion().seriesName(i);
    }
  }
  MotionFitOptions options;
  options.fixed_order = 1;
  options.period = 1.0;
  const MotionFit fit = fitMotion(motion, options);
  const FitAccuracy accuracy = measureFitAccuracy(skeleton, motion, fit, fit.motion);
  std::cout << "[ figure   ] arm through x = 90 degrees, order 1: joints against the retarget mean "
            << accuracy.against_samples.mean_cm << " cm, max " << accuracy.against_samples.max_cm << " cm\n";
  ASSERT_GT(accuracy.against_samples.samples, 0u);
  EXPECT_LT(accuracy.against_samples.max_cm, 0.1);
}

TEST(MocapRetarget, EulerSplitsInverseTheirCompositions) {
  const Eigen::Vector3d yxz(0.3, -0.4, 2.9);
  const Eigen::Matrix3d r =
      (Eigen::AngleAxisd(yxz[0], Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(yxz[1], Eigen::Vector3d::UnitX()) *
       Eigen::AngleAxisd(yxz[2], Eigen::Vector3d::UnitZ()))
          .toRotationMatrix();
  EXPECT_LT((decomposeYxz(r) - yxz).norm(), 1e-12);
  // Beyond x = 90 degrees, and at it: the branch nearest the angles a frame before.
  const auto compose = [](const Eigen::Vector3d& a) {
    return (Eigen::AngleAxisd(a[0], Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(a[1], Eigen::Vector3d::UnitX()) *
            Eigen::AngleAxisd(a[2], Eigen::Vector3d::UnitZ()))
        .toRotationMatrix();
  };
  const Eigen::Vector3d beyond(0.3, 2.0, -0.5);
  EXPECT_GT((decomposeYxz(compose(beyond)) - beyond).norm(), 1.0);  // the principal branch's other angles
  EXPECT_LT((decomposeYxzNear(compose(beyond), beyond + Eigen::Vector3d::Constant(0.05)) - beyond).norm(), 1e-12);
  EXPECT_LT((decomposeYxzNear(compose(yxz), yxz + Eigen::Vector3d(0.1, -0.1, 2.0 * kPi)) -
             (yxz + Eigen::Vector3d(0.0, 0.0, 2.0 * kPi)))
                .norm(),
            1e-12);  // whole turns kept
  const Eigen::Vector3d gimbal(0.7, 0.5 * kPi, 0.2);
  EXPECT_LT((decomposeYxzNear(compose(gimbal), Eigen::Vector3d(0.65, 1.5, 0.2)) - gimbal).norm(), 1e-7);
  const Eigen::Vector3d rpy(-0.2, 0.5, -3.0);
  const Eigen::Matrix3d q =
      (Eigen::AngleAxisd(rpy[2], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy[1], Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(rpy[0], Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  EXPECT_LT((decomposeRollPitchYaw(q) - rpy).norm(), 1e-12);
}

}  // namespace
}  // namespace dressed_human
