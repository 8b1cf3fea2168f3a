// BVH parsing: the CMU walk reads completely; channel order is honoured; every kind of malformed
// input is rejected with a message naming the file and line.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "dressed_human/core/motion/bvh_file.h"

namespace dressed_human {
namespace {

const std::string kSource = DRESSED_HUMAN_SOURCE_DIR;
constexpr double kDegree = 3.14159265358979323846 / 180.0;

std::string tinyBvh(
    const std::string& leg_channels = "CHANNELS 3 Yrotation Xrotation Zrotation",
    const std::string& frames = "Frames: 2\nFrame Time: 0.01\n0 1 2 3 4 5 10 20 30\n1 2 3 4 5 6 7 8 9\n") {
  return "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation "
         "Xrotation\n"
         " JOINT Leg\n {\n  OFFSET 1 -2 0\n  " +
         leg_channels + "\n  End Site\n  {\n   OFFSET 0 -3 0\n  }\n }\n}\nMOTION\n" + frames;
}

std::string errorOf(const std::string& text) {
  try {
    parseBvh(text, "test.bvh");
  } catch (const BvhError& error) {
    return error.what();
  }
  return "(no error)";
}

// Position channels replace the offset, as Blender reads them: a joint whose file keys its
// position (Bandai-Namco's rig keys every joint's, LAFAN1's root repeats its first place as its
// OFFSET) stands where its channels say, not twice as far.
TEST(BvhFile, PositionChannelsReplaceTheOffset) {
  const std::string text =
      "HIERARCHY\nROOT Hips\n{\n OFFSET 1 90 3\n CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation "
      "Xrotation\n JOINT Spine\n {\n  OFFSET 0 10 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation "
      "Yrotation Xrotation\n  End Site\n  {\n   OFFSET 0 5 0\n  }\n }\n}\nMOTION\nFrames: 1\nFrame Time: 0.01\n"
      "-2 91 4 0 0 0 0 10 0 0 0 0\n";
  const BvhPose pose = bvhForwardKinematics(parseBvh(text, "keyed.bvh"), 0);
  EXPECT_LT((pose.position[0] - Eigen::Vector3d(-2, 91, 4)).norm(), 1e-12);
  EXPECT_LT((pose.position[1] - Eigen::Vector3d(-2, 101, 4)).norm(), 1e-12);
}

TEST(BvhFile, CmuWalkReadsCompletely) {
  const BvhClip clip = loadBvhFile(kSource + "/data/motion/cmu_02_01_walk.bvh");
  EXPECT_EQ(clip.joints.size(), 31u);
  EXPECT_EQ(clip.frames.size(), 344u);
  EXPECT_NEAR(clip.frame_time, 0.0083333, 1e-9);
  EXPECT_EQ(clip.joints[0].name, "Hips");
  EXPECT_EQ(clip.joints[0].channels.size(), 6u);
  EXPECT_EQ(clip.channel_count, 6u + 30u * 3u);
  const int leg = clip.findJoint("LeftLeg");
  ASSERT_GE(leg, 0);
  EXPECT_EQ(clip.joints[static_cast<std::size_t>(clip.joints[static_cast<std::size_t>(leg)].parent)].name, "LeftUpLeg");
  EXPECT_NEAR(clip.frames[1][0], 10.4194, 1e-12);
  EXPECT_EQ(clip.findJoint("Tail"), -1);
}

TEST(BvhFile, ChannelsComposeInFileOrder) {
  const BvhClip clip = parseBvh(tinyBvh(), "tiny.bvh");
  ASSERT_EQ(clip.joints.size(), 2u);
  const Eigen::Matrix3d expected = Eigen::AngleAxisd(10 * kDegree, Eigen::Vector3d::UnitY()).toRotationMatrix() *
                                   Eigen::AngleAxisd(20 * kDegree, Eigen::Vector3d::UnitX()).toRotationMatrix() *
                                   Eigen::AngleAxisd(30 * kDegree, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_LT((clip.localRotation(0, 1) - expected).norm(), 1e-12);
  const Eigen::Matrix3d root = Eigen::AngleAxisd(3 * kDegree, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
                               Eigen::AngleAxisd(4 * kDegree, Eigen::Vector3d::UnitY()).toRotationMatrix() *
                               Eigen::AngleAxisd(5 * kDegree, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_LT((clip.localRotation(0, 0) - root).norm(), 1e-12);
  EXPECT_LT((clip.localTranslation(0, 0) - Eigen::Vector3d(0, 1, 2)).norm(), 1e-12);
  const BvhPose pose = bvhForwardKinematics(clip, 0);
  EXPECT_LT((pose.position[1] - (Eigen::Vector3d(0, 1, 2) + root * Eigen::Vector3d(1, -2, 0))).norm(), 1e-12);
  const BvhPose rest = bvhRestPose(clip);
  EXPECT_LT((rest.position[1] - Eigen::Vector3d(1, -2, 0)).norm(), 1e-12);
}

TEST(BvhFile, AnyRotationOrderAndChannelCount) {
  const BvhClip clip = parseBvh(
      tinyBvh("CHANNELS 2 Xrotation Zrotation", "Frames: 1\nFrame Time: 0.01\n0 0 0 0 0 0 40 50\n"), "tiny.bvh");
  const Eigen::Matrix3d expected = Eigen::AngleAxisd(40 * kDegree, Eigen::Vector3d::UnitX()).toRotationMatrix() *
                                   Eigen::AngleAxisd(50 * kDegree, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_LT((clip.localRotation(0, 1) - expected).norm(), 1e-12);
}

struct BadBvh {
  std::string text;
  std::string expected;
};

class BadBvhFile : public ::testing::TestWithParam<BadBvh> {};

TEST_P(BadBvhFile, IsRejectedWithItsMessage) {
  const std::string message = errorOf(GetParam().text);
  EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
  EXPECT_EQ(message.rfind("test.bvh:", 0), 0u) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, BadBvhFile,
    ::testing::Values(
        BadBvh{"", "unexpected end of file"}, BadBvh{"HIERARCHY\nJOINT x", "expected ROOT"},
        BadBvh{tinyBvh("CHANNELS 3 Yrotation Xrotation Wrotation"), "unknown channel 'Wrotation'"},
        BadBvh{tinyBvh("CHANNELS 3 Yrotation Yrotation Zrotation"), "same channel twice"},
        BadBvh{tinyBvh("CHANNELS 7 Yrotation Xrotation Zrotation"), "channel count 7 is more than"},
        BadBvh{tinyBvh("CHANNELS 3 Yrotation Xrotation Zrotation", "Frames: 3\nFrame Time: 0.01\n0 1 2 3 4 5 6 7 8\n"),
               "needs 3 x 9 numbers"},
        BadBvh{
            tinyBvh("CHANNELS 3 Yrotation Xrotation Zrotation", "Frames: 1\nFrame Time: 0.01\n0 1 2 3 4 5 6 7 8 9\n"),
            "more numbers than"},
        BadBvh{
            tinyBvh("CHANNELS 3 Yrotation Xrotation Zrotation", "Frames: 1\nFrame Time: 0.01\n0 1 2 3 nan 5 6 7 8\n"),
            "must be a finite number"},
        BadBvh{tinyBvh("CHANNELS 3 Yrotation Xrotation Zrotation", "Frames: 1\nFrame Time: 0.01\n0 1 2 3 4x 5 6 7 8\n"),
               "got '4x'"},
        BadBvh{tinyBvh("CHANNELS 3 Yrotation Xrotation Zrotation", "Frames: 1\nFrame Time: 0\n0 1 2 3 4 5 6 7 8\n"),
               "Frame Time must be > 0"},
        BadBvh{tinyBvh("CHANNELS 3 Yrotation Xrotation Zrotation", "Frames: -1\n"), "non-negative whole number"},
        BadBvh{
            "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 0\n JOINT Hips\n {\n OFFSET 0 0 0\n CHANNELS 0\n }\n}\n",
            "appears twice"},
        BadBvh{"HIERARCHY\nROOT Hips\n{\n OFFSET 0 0\n", "unexpected end of file, expected OFFSET component"},
        BadBvh{"HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 CHANNELS\n",
               "expected a number (OFFSET component), got 'CHANNELS'"},
        BadBvh{
            "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 1 Xrotation\n End Site\n {\n OFFSET 0 1 0\n JOINT x\n",
            "End Site block holds only its OFFSET"},
        BadBvh{"HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 0\n}\nMOTION\nFrames: 100000000\nFrame Time: 0.01\n",
               "no channels"}));

TEST(BvhFile, ErrorsNameTheLine) {
  const std::string message = errorOf(
      tinyBvh("CHANNELS 3 Yrotation Xrotation Zrotation", "Frames: 1\nFrame Time: 0.01\n0 1 2 3 4 5 6 7 bad\n"));
  EXPECT_NE(message.find("test.bvh:19:"), std::string::npos) << message;
}

TEST(BvhFile, DeepNestingIsRefusedNotOverflowed) {
  std::string text = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 1 Xrotation\n";
  for (int i = 0; i < 5000; ++i) text += "JOINT j" + std::to_string(i) + "\n{\nOFFSET 0 0 0\nCHANNELS 0\n";
  EXPECT_NE(errorOf(text).find("nested deeper"), std::string::npos);
}

TEST(BvhFile, MissingFileIsNamed) { EXPECT_THROW(loadBvhFile("/nonexistent/walk.bvh"), BvhError); }

}  // namespace
}  // namespace dressed_human
