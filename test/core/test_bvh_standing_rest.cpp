// A BVH whose pelvis hangs below a still root and whose zero pose is folded (Bandai-Namco's rig)
// is re-expressed on a standing frame of its own: the same world poses, and the same fit as the
// capture in a standing zero pose.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "capture_fit_test_support.h"
#include "dressed_human/core/motion/bvh_file.h"
#include "dressed_human/core/motion/bvh_standing_rest.h"
#include "dressed_human/core/motion/mocap_joint_map.h"

namespace dressed_human {
namespace {

const std::string kSource = DRESSED_HUMAN_SOURCE_DIR;
const std::string kCmuWalk = kSource + "/data/motion/cmu_02_01_walk.bvh";

// Every joint's zero pose turned a quarter turn about z and more about x, by joint: each bone
// along a different, sideways direction, as a rig with bone-aligned local axes has them.
std::vector<Eigen::Matrix3d> foldingRest(const BvhClip& clip) {
  std::vector<Eigen::Matrix3d> rest;
  for (std::size_t j = 0; j < clip.joints.size(); ++j) {
    rest.push_back((Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()) *
                    Eigen::AngleAxisd(0.3 * static_cast<double>(j), Eigen::Vector3d::UnitX()))
                       .toRotationMatrix());
  }
  return rest;
}

// `clip` below a new root joint 'joint_Root' with six channels, all `value` (0: still).
BvhClip underRoot(const BvhClip& clip, double value) {
  BvhClip out = clip;
  BvhJoint root;
  root.name = "joint_Root";
  root.channels = {BvhChannel::kXposition, BvhChannel::kYposition, BvhChannel::kZposition,
                   BvhChannel::kZrotation, BvhChannel::kYrotation, BvhChannel::kXrotation};
  root.children = {1};
  for (BvhJoint& joint : out.joints) {
    joint.parent = joint.parent < 0 ? 0 : joint.parent + 1;
    for (int& child : joint.children) ++child;
    joint.first_channel += 6;
  }
  out.joints.insert(out.joints.begin(), root);
  out.channel_count += 6;
  for (std::size_t f = 0; f < out.frames.size(); ++f) {
    out.frames[f].insert(out.frames[f].begin(), 6, value * static_cast<double>(f % 2));
  }
  return out;
}

BvhClip foldedBelowStillRoot(const BvhClip& clip) { return underRoot(bvhOnZeroPose(clip, 0, foldingRest(clip)), 0.0); }

TEST(BvhStandingRest, AFoldedZeroPoseBelowAStillRootKeepsEveryWorldPose) {
  const BvhClip clip = loadBvhFile(kCmuWalk);
  const BvhClip folded = foldedBelowStillRoot(clip);
  const BvhJointMap map = chooseBvhJointMap(folded, "folded.bvh");
  // The folded zero pose does not stand: the head is not above the hips.
  const BvhPose folded_zero = bvhRestPose(folded);
  const Eigen::Vector3d up = folded_zero.position[static_cast<std::size_t>(folded.findJoint("Head"))] -
                             folded_zero.position[static_cast<std::size_t>(folded.findJoint("Hips"))];
  ASSERT_LT(up.y(), 0.7 * up.norm());
  const StandingRest standing = standingRest(folded, map, "folded.bvh");
  EXPECT_TRUE(standing.lifted);
  EXPECT_GE(standing.rest_frame, 0);
  ASSERT_EQ(standing.clip.joints.size(), clip.joints.size());
  EXPECT_EQ(standing.clip.joints[0].name, "Hips");
  const BvhPose zero = bvhRestPose(standing.clip);
  const Eigen::Vector3d head = zero.position[static_cast<std::size_t>(standing.clip.findJoint("Head"))];
  EXPECT_GT(head.y(), 0.7 * head.norm());
  double worst = 0.0;
  for (std::size_t f = 0; f < clip.frames.size(); f += 7) {
    const BvhPose original = bvhForwardKinematics(clip, f);
    const BvhPose again = bvhForwardKinematics(standing.clip, f);
    for (std::size_t j = 0; j < clip.joints.size(); ++j) {
      const auto k = static_cast<std::size_t>(standing.clip.findJoint(clip.joints[j].name));
      worst = std::max(worst, (again.position[k] - original.position[j]).norm());
    }
  }
  EXPECT_LT(worst, 1e-9);  // CMU units (~5.6 cm): a 1e-9 of them is far below any capture's noise
}

// The retarget on the folded capture: our skeleton on the unsmoothed angles as close to the
// capture (measured: 0.15 / 0.57 cm standing, 0.28 / 0.57 cm folded, whose rest is a walking frame;
// retargeted from the folded zero pose itself 8.09 / 19.95 cm).
TEST(BvhStandingRest, TheFoldedCaptureRetargetsAsCloselyAsTheStandingOne) {
  const BvhClip clip = loadBvhFile(kCmuWalk);
  const BvhClip folded = foldedBelowStillRoot(clip);
  const Skeleton skeleton = Skeleton::fromUrdfFile(kSource + "/urdf/human.urdf");
  const FitAccuracy standing = fitCmuCapture(skeleton, clip, kCmuWalk, true).accuracy;
  const FitAccuracy from_folded = fitCmuCapture(skeleton, folded, kCmuWalk, true).accuracy;
  expectUnsmoothedAsClose(standing, from_folded, "folded below a still root", 0.1, 0.2);
  EXPECT_LE(from_folded.against_capture.mean_cm, standing.against_capture.mean_cm + 0.1);
}

// A root above the pelvis that moves (Bandai's 'joint_Root' carries some walks' forward travel):
// its motion becomes the pelvis's.
TEST(BvhStandingRest, APelvisBelowAMovingRootKeepsItsWorldMotion) {
  const BvhClip clip = loadBvhFile(kCmuWalk);
  const BvhClip moving = underRoot(clip, 10.0);
  const StandingRest lifted = standingRest(moving, chooseBvhJointMap(moving, "m.bvh"), "m.bvh");
  EXPECT_TRUE(lifted.lifted);
  EXPECT_EQ(lifted.rest_frame, -1);  // CMU's zero pose stands
  double worst = 0.0;
  for (std::size_t f = 0; f < 4; ++f) {
    const BvhPose original = bvhForwardKinematics(moving, f);
    const BvhPose again = bvhForwardKinematics(lifted.clip, f);
    for (std::size_t j = 0; j < lifted.clip.joints.size(); ++j) {
      const auto k = static_cast<std::size_t>(moving.findJoint(lifted.clip.joints[j].name));
      worst = std::max(worst, (again.position[j] - original.position[k]).norm());
    }
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(BvhStandingRest, AClipThatNeverStandsIsRefused) {
  const BvhClip clip = loadBvhFile(kCmuWalk);
  BvhClip folded_still = bvhOnZeroPose(clip, 0, foldingRest(clip));
  for (std::vector<double>& frame : folded_still.frames) std::fill(frame.begin() + 3, frame.end(), 0.0);
  try {
    standingRest(folded_still, chooseBvhJointMap(folded_still, "f.bvh"), "f.bvh");
    FAIL() << "a clip that never stands was taken";
  } catch (const JointMapError& error) {
    EXPECT_NE(std::string(error.what()).find("nor any frame stands"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace dressed_human
