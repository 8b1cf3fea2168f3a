// The skeleton read from urdf/human.urdf, and forward kinematics against hand-computed poses.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "dressed_human/core/skeleton/crowd_human_body.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/skeleton/urdf_body_shape.h"

namespace dressed_human {
namespace {

const std::string kUrdfPath = std::string(DRESSED_HUMAN_SOURCE_DIR) + "/urdf/human.urdf";
constexpr double kPi = 3.14159265358979323846;
constexpr double kTolerance = 1e-12;

std::string urdfText() {
  std::ifstream file(kUrdfPath);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string skeletonErrorOf(const std::string& urdf) {
  try {
    Skeleton::fromUrdf(urdf);
  } catch (const SkeletonError& error) {
    return error.what();
  }
  return "(no error)";
}

void replaceOnce(std::string& text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

class SkeletonTest : public ::testing::Test {
 protected:
  SkeletonTest() : skeleton(Skeleton::fromUrdfFile(kUrdfPath)), kinematics(skeleton) {}

  // World position of a bone's proximal joint with the root at the standing pelvis height.
  Eigen::Vector3d jointPosition(const std::string& bone, const JointAngles& angles,
                                const RigidTransform& root = standingRoot()) {
    kinematics.compute(root, angles, pose);
    return pose.bone_in_world[static_cast<std::size_t>(skeleton.findBone(bone))].translation;
  }
  static RigidTransform standingRoot() {
    RigidTransform root;
    root.translation = {0.0, 0.0, 0.96};
    return root;
  }
  double& angle(JointAngles& angles, const std::string& joint, JointAxis axis) {
    return angles[static_cast<std::size_t>(skeleton.findJoint(joint)) * kDofsPerJoint + static_cast<std::size_t>(axis)];
  }

  Skeleton skeleton;
  ForwardKinematics kinematics;
  SkeletonPose pose;
  JointAngles zero{};
};

TEST_F(SkeletonTest, HasTwentyBonesAndSixteenThreeDofJoints) {
  EXPECT_EQ(skeleton.bones().size(), 20u);
  EXPECT_EQ(skeleton.joints().size(), 16u);
  EXPECT_EQ(skeleton.suffix(), "");
  EXPECT_EQ(skeleton.rootFrame(), "body");
  const ArticulatedJoint& knee = skeleton.joint(static_cast<std::size_t>(skeleton.findJoint("l_knee")));
  EXPECT_EQ(knee.urdf_joints[0], "l_knee_ry");
  EXPECT_EQ(knee.urdf_joints[1], "l_knee_rx");
  EXPECT_EQ(knee.urdf_joints[2], "l_knee_rz");
  EXPECT_EQ(skeleton.bone(static_cast<std::size_t>(knee.bone)).anatomical, "left shank");
  int fixed = 0;
  for (const Bone& bone : skeleton.bones()) fixed += bone.joint < 0 ? 1 : 0;
  EXPECT_EQ(fixed, 4);  // clavicles and hip bones
}

TEST_F(SkeletonTest, EveryBoneFrameHasZAlongTheBone) {
  // A child's proximal joint lies on its parent's z axis at the parent's length, wherever the
  // child continues the parent (not for the clavicles and hip bones branching off the trunk).
  for (const Bone& bone : skeleton.bones()) {
    if (bone.parent < 0 || bone.name.find("clavicle") != std::string::npos) continue;
    const Bone& parent = skeleton.bone(static_cast<std::size_t>(bone.parent));
    EXPECT_NEAR(bone.rest_translation.x(), 0.0, 1e-9) << bone.name;
    EXPECT_NEAR(bone.rest_translation.y(), 0.0, 1e-9) << bone.name;
    EXPECT_NEAR(bone.rest_translation.z(), parent.length, 1e-9) << bone.name;
  }
}

TEST_F(SkeletonTest, StandingPoseMatchesTheAdultProportions) {
  EXPECT_NEAR(jointPosition("l_hip", zero).z(), 0.90, kTolerance);
  EXPECT_NEAR(jointPosition("l_knee", zero).z(), 0.48, kTolerance);
  EXPECT_NEAR(jointPosition("l_ankle", zero).z(), 0.07, kTolerance);
  EXPECT_NEAR(jointPosition("r_ankle", zero).y(), -0.09, kTolerance);
  EXPECT_NEAR(jointPosition("l_shoulder", zero).z(), 1.43, kTolerance);
  EXPECT_NEAR(jointPosition("l_shoulder", zero).y(), 0.19, kTolerance);
  const std::size_t head = static_cast<std::size_t>(skeleton.findBone("head"));
  kinematics.compute(standingRoot(), zero, pose);
  const Eigen::Vector3d head_top =
      pose.bone_in_world[head].translation +
      pose.bone_in_world[head].rotation * Eigen::Vector3d(0, 0, skeleton.bone(head).length);
  EXPECT_NEAR(head_top.z(), 1.75, kTolerance);  // stature
}

TEST_F(SkeletonTest, KneeFlexionSwingsTheShankBackward) {
  JointAngles angles{};
  angle(angles, "l_knee", JointAxis::kY) = kPi / 2;
  const Eigen::Vector3d ankle = jointPosition("l_ankle", angles);
  EXPECT_NEAR(ankle.x(), -0.41, kTolerance);
  EXPECT_NEAR(ankle.y(), 0.09, kTolerance);
  EXPECT_NEAR(ankle.z(), 0.48, kTolerance);
}

TEST_F(SkeletonTest, HipFlexionRaisesTheThighForward) {
  JointAngles angles{};
  angle(angles, "l_hip", JointAxis::kY) = -kPi / 2;
  const Eigen::Vector3d knee = jointPosition("l_knee", angles);
  EXPECT_NEAR(knee.x(), 0.42, kTolerance);
  EXPECT_NEAR(knee.z(), 0.90, kTolerance);
}

TEST_F(SkeletonTest, TwistTurnsTheNextFlexionAxis) {
  // Thigh twisted a quarter turn about itself: the knee now flexes sideways, to the left.
  JointAngles angles{};
  angle(angles, "l_hip", JointAxis::kZ) = kPi / 2;
  angle(angles, "l_knee", JointAxis::kY) = kPi / 2;
  const Eigen::Vector3d ankle = jointPosition("l_ankle", angles);
  EXPECT_NEAR(ankle.x(), 0.0, kTolerance);
  EXPECT_NEAR(ankle.y(), 0.09 + 0.41, kTolerance);
  EXPECT_NEAR(ankle.z(), 0.48, kTolerance);
}

TEST_F(SkeletonTest, AbductionAboutXMovesTheArmSideways) {
  JointAngles angles{};
  angle(angles, "l_shoulder", JointAxis::kX) = -kPi / 2;  // x points backward: -x abducts the left arm
  const Eigen::Vector3d elbow = jointPosition("l_elbow", angles);
  EXPECT_NEAR(elbow.y(), 0.19 + 0.29, kTolerance);
  EXPECT_NEAR(elbow.z(), 1.43, kTolerance);
}

TEST_F(SkeletonTest, RootPoseMovesEverything) {
  RigidTransform root;
  root.translation = {1.0, 2.0, 0.96};
  root.rotation = Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d hip = jointPosition("l_hip", zero, root);  // left of the pelvis: +y -> -x
  EXPECT_NEAR(hip.x(), 1.0 - 0.09, kTolerance);
  EXPECT_NEAR(hip.y(), 2.0, kTolerance);
  EXPECT_NEAR(hip.z(), 0.90, kTolerance);
}

TEST_F(SkeletonTest, BoneLengthScaleFollowsEquationFive) {
  BodyShape shape;
  const std::size_t thigh = static_cast<std::size_t>(skeleton.findBone("l_hip"));
  shape.scale[thigh] = {1.3, 1.3, 1.1};  // thicker (a, b) does not move joints; longer (c) does
  ForwardKinematics scaled(skeleton, shape);
  scaled.compute(standingRoot(), zero, pose);
  EXPECT_NEAR(pose.bone_in_world[static_cast<std::size_t>(skeleton.findBone("l_knee"))].translation.z(),
              0.90 - 0.42 * 1.1, kTolerance);
  EXPECT_NEAR(pose.bone_in_world[static_cast<std::size_t>(skeleton.findBone("l_ankle"))].translation.z(),
              0.90 - 0.42 * 1.1 - 0.41, kTolerance);
  shape.scale[thigh] = {1.0, 0.0, 1.0};
  EXPECT_THROW(ForwardKinematics(skeleton, shape), SkeletonError);
}

TEST_F(SkeletonTest, PublishedJointTransformsComposeToTheBonePoses) {
  JointAngles angles{};
  for (std::size_t i = 0; i < kDofCount; ++i) angles[i] = 0.3 * std::sin(1.7 * static_cast<double>(i) + 0.2);
  kinematics.compute(standingRoot(), angles, pose);
  for (const ArticulatedJoint& joint : skeleton.joints()) {
    const std::size_t first = static_cast<std::size_t>(&joint - skeleton.joints().data()) * kDofsPerJoint;
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    for (std::size_t d = 0; d < kDofsPerJoint; ++d) rotation = rotation * pose.dof_transforms[first + d].rotation;
    const RigidTransform& local = pose.bone_in_parent[static_cast<std::size_t>(joint.bone)];
    EXPECT_LT(rotation.angularDistance(local.rotation), 1e-12) << joint.name;
    EXPECT_LT((pose.dof_transforms[first].translation - local.translation).norm(), 1e-15) << joint.name;
  }
}

TEST(SkeletonSuffix, IsDetectedFromTheRootLink) {
  const std::string suffixed = std::regex_replace(urdfText(), std::regex("(link|name)=\"([a-z_]+)\""), "$1=\"$2_7\"");
  const Skeleton skeleton = Skeleton::fromUrdf(suffixed);
  EXPECT_EQ(skeleton.suffix(), "_7");
  EXPECT_EQ(skeleton.rootFrame(), "body_7");
  EXPECT_EQ(skeleton.joint(0).urdf_joints[0], "waist_ry_7");
  EXPECT_EQ(skeleton.findBone("l_knee"), Skeleton::fromUrdf(urdfText()).findBone("l_knee"));
}

TEST(SkeletonSuffix, AnotherHumanOfTheTreeIsTheSuffixedUrdfsSkeleton) {
  const Skeleton plain = Skeleton::fromUrdf(urdfText());
  const std::string suffixed = std::regex_replace(urdfText(), std::regex("(link|name)=\"([a-z_]+)\""), "$1=\"$2_7\"");
  const Skeleton parsed = Skeleton::fromUrdf(suffixed);
  for (const Skeleton& renamed : {plain.withSuffix("_7"), parsed.withSuffix("_7")}) {
    EXPECT_EQ(renamed.rootFrame(), "body_7");
    for (std::size_t j = 0; j < kJointCount; ++j) {
      EXPECT_EQ(renamed.joint(j).urdf_joints, parsed.joint(j).urdf_joints);
      EXPECT_EQ(renamed.joint(j).intermediate_links, parsed.joint(j).intermediate_links);
    }
  }
  const Skeleton back = parsed.withSuffix("");
  EXPECT_EQ(back.frameName("l_knee"), "l_knee");
  EXPECT_EQ(back.joint(3).urdf_joints, plain.joint(3).urdf_joints);
  for (const char* bad : {"7", "_", "_a-b", "_7/x"}) {
    EXPECT_THROW(plain.withSuffix(bad), SkeletonError) << bad;
  }
}

TEST(SkeletonSuffix, HumansAmongFramesNeedTheirRootAndFirstBone) {
  const std::vector<std::string> frames = {"world",    "body",      "waist",  "body_3",   "waist_3", "body_12",
                                           "waist_12", "body_link", "body_9", "waist_x9", "body_-1", "waist_-1"};
  EXPECT_EQ(humanSuffixesAmong(frames), (std::vector<std::string>{"", "_12", "_3"}));
  EXPECT_TRUE(humanSuffixesAmong({"world", "map"}).empty());
}

TEST(SkeletonErrors, NameWhatDoesNotFit) {
  EXPECT_NE(skeletonErrorOf("").find("the URDF text is empty"), std::string::npos);
  EXPECT_NE(skeletonErrorOf("<robot name='x'><link name='a'/>").find("could not be parsed"), std::string::npos);
  EXPECT_NE(skeletonErrorOf("<robot name='x'><link name='pelvis'/></robot>").find("root link must be 'body'"),
            std::string::npos);

  std::string text = urdfText();
  replaceOnce(text, "<axis xyz=\"1.0 0.0 0.0\"/>", "<axis xyz=\"0.0 0.0 1.0\"/>");  // the first rx joint: waist_rx
  EXPECT_NE(skeletonErrorOf(text).find("URDF joint 'waist_rx' must turn about the x axis"), std::string::npos)
      << skeletonErrorOf(text);

  text = urdfText();
  text = std::regex_replace(text, std::regex("\"l_wrist\""), "\"l_hand\"");
  EXPECT_NE(skeletonErrorOf(text).find("the URDF has no link 'l_wrist' (the left hand"), std::string::npos)
      << skeletonErrorOf(text);

  text = urdfText();
  replaceOnce(text, "<joint name=\"l_clavicle_fixed\" type=\"fixed\">",
              "<joint name=\"l_clavicle_fixed\" type=\"continuous\"><axis xyz=\"0 0 1\"/>");
  EXPECT_NE(skeletonErrorOf(text).find("'l_clavicle' (the left clavicle) must hang from a fixed joint"),
            std::string::npos)
      << skeletonErrorOf(text);

  EXPECT_THROW(Skeleton::fromUrdfFile("/nonexistent/human.urdf"), SkeletonError);
}

}  // namespace
}  // namespace dressed_human

namespace dressed_human {
namespace {

// A crowd human's stature, as the crowd publisher walks it and the display draws it: whole
// bones scaled by it, nothing for a stature within 0.5 % of 1 or a URDF carrying a person's
// proportions of its own.
TEST(CrowdStature, ScalesTheBonesUnlessNegligibleOrAlreadyAPersons) {
  std::ifstream file(kUrdfPath);
  std::stringstream text;
  text << file.rdbuf();
  const std::string urdf = text.str();
  const Skeleton plain = Skeleton::fromUrdf(urdf);
  // The knee's offset in the thigh as the URDF puts it (rest offset times the URDF's own shape).
  const auto thigh = [](const Skeleton& s) {
    return shapedRestTranslation(s, s.bodyShape(), static_cast<std::size_t>(s.findBone("l_knee"))).norm();
  };
  EXPECT_DOUBLE_EQ(drawnStature(plain, 1.003), 1.0);
  EXPECT_DOUBLE_EQ(drawnStature(plain, 1.1), 1.1);
  EXPECT_NEAR(thigh(skeletonAtStature(plain, 1.1)), 1.1 * thigh(plain), 1e-9);
  EXPECT_NEAR(thigh(skeletonAtStature(plain, 1.003)), thigh(plain), 1e-12);
  // Without a parse, the same skeleton as the URDF shaped by that stature gives: every bone's
  // shaped offset, length and radius.
  BodyShape tall;
  for (Eigen::Vector3d& scale : tall.scale) scale.setConstant(1.1);
  const Skeleton parsed = Skeleton::fromUrdf(shapedUrdf(urdf, tall));
  const Skeleton scaled = skeletonAtStature(plain, 1.1);
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    EXPECT_LT(
        (shapedRestTranslation(scaled, scaled.bodyShape(), b) - shapedRestTranslation(parsed, parsed.bodyShape(), b))
            .norm(),
        1e-9)
        << b;
    EXPECT_NEAR(scaled.bone(b).length, parsed.bone(b).length, 1e-9) << b;
    EXPECT_NEAR(scaled.bone(b).radius, parsed.bone(b).radius, 1e-9) << b;
    EXPECT_EQ(scaled.bodyShape().scale[b], parsed.bodyShape().scale[b]) << b;
  }
  BodyShape person;
  for (Eigen::Vector3d& scale : person.scale) scale.setConstant(0.9);
  const std::string fitted = shapedUrdf(urdf, person);
  const Skeleton fitted_skeleton = Skeleton::fromUrdf(fitted);
  EXPECT_DOUBLE_EQ(drawnStature(fitted_skeleton, 1.1), 1.0);
  EXPECT_NEAR(thigh(skeletonAtStature(fitted_skeleton, 1.1)), thigh(fitted_skeleton), 1e-12);
  EXPECT_TRUE(isHumanId("a7"));
  EXPECT_FALSE(isHumanId(""));
  EXPECT_FALSE(isHumanId("a b"));
}

// A crowd human's drawn body: its skeleton at the stature with the human's suffix, and the
// display's shape times the stature; unscaled within 0.5 % of 1.
TEST(CrowdStature, ACrowdHumansBodyIsTheDisplaysShapeTimesItsStature) {
  const Skeleton plain = Skeleton::fromUrdfFile(kUrdfPath);
  const BodyDescription body =
      loadBodyDescriptionFile(std::string(DRESSED_HUMAN_SOURCE_DIR) + "/config/bodies/default.yaml", plain);
  BodyShape shape;
  const std::size_t shank = static_cast<std::size_t>(plain.findBone("l_knee"));
  shape.scale[shank] = {1.0, 1.2, 1.0};
  const CrowdHumanBody tall = crowdHumanBody(plain, body, shape, "_7", 1.1);
  EXPECT_EQ(tall.skeleton.rootFrame(), "body_7");
  EXPECT_TRUE(tall.description.shape.scale[shank].isApprox(Eigen::Vector3d(1.1, 1.32, 1.1)));
  EXPECT_NEAR(tall.skeleton.bodyShape().scale[shank].z(), 1.1, 1e-12);
  EXPECT_EQ(tall.description.segments.size(), body.segments.size());
  const CrowdHumanBody same = crowdHumanBody(plain, body, shape, "_8", 1.003);
  EXPECT_EQ(same.description.shape.scale[shank], shape.scale[shank]);
  EXPECT_TRUE(same.skeleton.bodyShape().isIdentity());
}

}  // namespace
}  // namespace dressed_human
