// Body shape by limb group (the display's Body Shape properties), and bone frames composed from
// TF's unshaped joint transforms with the shape applied (the display's TF path) against FK.
#include <gtest/gtest.h>

#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/body_shape_groups.h"

namespace dressed_human {
namespace {

const std::string kUrdfPath = std::string(DRESSED_HUMAN_SOURCE_DIR) + "/urdf/human.urdf";

std::size_t boneIndex(const Skeleton& skeleton, const std::string& name) {
  return static_cast<std::size_t>(skeleton.findBone(name));
}

TEST(BodyShapeGroups, GroupsMultiplyTheShapeOfTheirBonesInOrder) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(kUrdfPath);
  BodyShape base;
  base.scale[boneIndex(skeleton, "l_knee")] = {1.0, 1.0, 2.0};
  const BodyShape shape = scaleBodyShapeGroups(
      base, skeleton, {{"all", {2.0, 1.0, 1.0}}, {"legs", {1.0, 1.5, 0.5}}, {"no_such_group", {3.0, 3.0, 3.0}}});
  EXPECT_EQ(shape.scale[boneIndex(skeleton, "l_knee")], Eigen::Vector3d(2.0, 1.5, 1.0));
  EXPECT_EQ(shape.scale[boneIndex(skeleton, "r_hip")], Eigen::Vector3d(2.0, 1.5, 0.5));
  EXPECT_EQ(shape.scale[boneIndex(skeleton, "head")], Eigen::Vector3d(2.0, 1.0, 1.0));
  EXPECT_EQ(scaleBodyShapeGroups(base, skeleton, {}).scale[boneIndex(skeleton, "l_knee")],
            Eigen::Vector3d(1.0, 1.0, 2.0));
}

// The body file's shape on a fitted person's (the display's composition): scales multiply bone
// by bone, joint offsets add; on the identity it is itself.
TEST(BodyShape, AppliedOnABaseMultipliesScalesAndAddsOffsets) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(kUrdfPath);
  const std::size_t shank = boneIndex(skeleton, "l_knee"), head = boneIndex(skeleton, "head");
  BodyShape file, fitted;
  file.scale[shank] = {1.1, 1.0, 0.5};
  file.offset[head] = {0.0, 0.01, 0.0};
  fitted.scale[shank] = {1.0, 2.0, 1.2};
  fitted.offset[head] = {0.02, 0.0, -0.01};
  const BodyShape combined = file.appliedOn(fitted);
  EXPECT_TRUE(combined.scale[shank].isApprox(Eigen::Vector3d(1.1, 2.0, 0.6)));
  EXPECT_TRUE(combined.offset[head].isApprox(Eigen::Vector3d(0.02, 0.01, -0.01)));
  EXPECT_EQ(combined.scale[head], Eigen::Vector3d::Ones());
  const BodyShape alone = file.appliedOn(BodyShape());
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    EXPECT_EQ(alone.scale[b], file.scale[b]);
    EXPECT_EQ(alone.offset[b], file.offset[b]);
  }
}

TEST(BodyShapeGroups, AFactorOutOfRangeNamesItsEntryAndAxis) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(kUrdfPath);
  try {
    scaleBodyShapeGroups(BodyShape(), skeleton, {{"trunk", {1.0, 1.0, 1.0}}, {"legs", {1.0, 0.1f, 1.0}}});
    FAIL() << "no error";
  } catch (const ShapeGroupScaleError& error) {
    EXPECT_EQ(error.entry, 1u);
    EXPECT_STREQ(error.what(), "b = 0.100000 is outside [0.2, 5]");
  }
  EXPECT_THROW(scaleBodyShapeGroups(BodyShape(), skeleton, {{"arms", {5.5, 1.0, 1.0}}}), ShapeGroupScaleError);
  EXPECT_NO_THROW(scaleBodyShapeGroups(BodyShape(), skeleton, {{"arms", {0.2f, 5.0, 1.0}}}));
}

TEST(BodyShapeGroups, UnshapedJointTransformsComposeToTheShapedPose) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(kUrdfPath);
  const BodyShape shape =
      scaleBodyShapeGroups(BodyShape(), skeleton, {{"legs", {1.2, 0.9, 1.3}}, {"trunk", {1.0, 1.0, 0.8}}});
  JointAngles angles{};
  for (std::size_t a = 0; a < angles.size(); ++a) angles[a] = 0.05 * static_cast<double>(a % 7) - 0.1;
  RigidTransform root;
  root.translation = {1.0, -2.0, 0.9};
  root.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()));
  SkeletonPose unshaped, shaped;
  ForwardKinematics(skeleton).compute(root, angles, unshaped);  // what TF carries: the URDF's skeleton
  const ForwardKinematics kinematics(skeleton, shape);
  kinematics.compute(root, angles, shaped);
  std::array<RigidTransform, kBoneCount> composed;
  kinematics.composeFromTf(root, unshaped.bone_in_parent, composed);
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    EXPECT_LT((composed[b].translation - shaped.bone_in_world[b].translation).norm(), 1e-12) << skeleton.bone(b).name;
    EXPECT_LT(composed[b].rotation.angularDistance(shaped.bone_in_world[b].rotation), 1e-12) << skeleton.bone(b).name;
  }
}

}  // namespace
}  // namespace dressed_human
