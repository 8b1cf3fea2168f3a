#include "dressed_human/core/motion/bvh_standing_rest.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "dressed_human/core/motion/mocap_retarget.h"

namespace dressed_human {
namespace {

using namespace human_joint;  // NOLINT: the joint indices by name

// A segment stands when it is within 45 degrees of the vertical (BVH is Y-up).
constexpr double kStandingCosine = 0.7;
constexpr double kDegrees = 180.0 / M_PI;  // BVH angles are degrees

double upCosine(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  const Eigen::Vector3d d = to - from;
  return d.norm() > 0.0 ? d.y() / d.norm() : -1.0;
}

// How upright `pose` is: the least of the head's cosine with the vertical above the pelvis and each
// ankle's below it.
double uprightness(const BvhPose& pose, std::size_t pelvis, std::size_t head, std::size_t left_ankle,
                   std::size_t right_ankle) {
  const std::vector<Eigen::Vector3d>& p = pose.position;
  return std::min({upCosine(p[pelvis], p[head]), upCosine(p[left_ankle], p[pelvis]),
                   upCosine(p[right_ankle], p[pelvis])});
}

bool hasPositionChannels(const BvhJoint& joint) {
  return std::any_of(joint.channels.begin(), joint.channels.end(), [](BvhChannel c) {
    return c == BvhChannel::kXposition || c == BvhChannel::kYposition || c == BvhChannel::kZposition;
  });
}

}  // namespace

BvhClip bvhOnZeroPose(const BvhClip& clip, std::size_t root, const std::vector<Eigen::Matrix3d>& rest) {
  std::vector<std::size_t> kept = bvhSubtree(clip, root);
  std::sort(kept.begin(), kept.end());  // parents before children, as the file has them
  std::map<std::size_t, int> new_index;
  for (std::size_t i = 0; i < kept.size(); ++i) new_index[kept[i]] = static_cast<int>(i);
  BvhClip out;
  out.frame_time = clip.frame_time;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const BvhJoint& old = clip.joints[kept[i]];
    BvhJoint joint;
    joint.name = old.name;
    joint.parent = i == 0 ? -1 : new_index.at(static_cast<std::size_t>(old.parent));
    if (joint.parent >= 0) out.joints[static_cast<std::size_t>(joint.parent)].children.push_back(static_cast<int>(i));
    const Eigen::Matrix3d& parent_rest =
        i == 0 ? Eigen::Matrix3d::Identity() : rest[static_cast<std::size_t>(old.parent)];
    joint.offset = i == 0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(parent_rest * old.offset);
    for (const Eigen::Vector3d& end : old.end_sites) joint.end_sites.push_back(rest[kept[i]] * end);
    if (i == 0 || hasPositionChannels(old)) {
      joint.channels = {BvhChannel::kXposition, BvhChannel::kYposition, BvhChannel::kZposition};
    }
    for (const BvhChannel c : {BvhChannel::kYrotation, BvhChannel::kXrotation, BvhChannel::kZrotation}) {
      joint.channels.push_back(c);
    }
    joint.first_channel = out.channel_count;
    out.channel_count += joint.channels.size();
    out.joints.push_back(joint);
  }
  out.frames.resize(clip.frames.size());
  for (std::size_t f = 0; f < clip.frames.size(); ++f) {
    const BvhPose pose = bvhForwardKinematics(clip, f);
    std::vector<double>& values = out.frames[f];
    values.reserve(out.channel_count);
    for (std::size_t i = 0; i < kept.size(); ++i) {
      const std::size_t old = kept[i];
      const int old_parent = clip.joints[old].parent;
      const Eigen::Matrix3d world = pose.rotation[old] * rest[old].transpose();
      Eigen::Matrix3d local = world;
      Eigen::Vector3d translation = pose.position[old];
      if (i > 0) {
        const auto parent = static_cast<std::size_t>(old_parent);
        local = (pose.rotation[parent] * rest[parent].transpose()).transpose() * world;
        translation = rest[parent] * clip.localTranslation(f, old);
      }
      if (out.joints[i].channels.size() == 6) values.insert(values.end(), translation.data(), translation.data() + 3);
      const Eigen::Vector3d yxz = decomposeYxz(local) * kDegrees;  // the channels' order
      values.insert(values.end(), yxz.data(), yxz.data() + 3);
    }
  }
  return out;
}

StandingRest standingRest(const BvhClip& clip, const BvhJointMap& map, const std::string& source_name) {
  StandingRest result{clip, false, -1};
  const int pelvis = clip.findJoint(map.root);
  const int head = clip.findJoint(map.joints[kHead]);
  const int left_ankle = clip.findJoint(map.joints[kLeftAnkle]);
  const int right_ankle = clip.findJoint(map.joints[kRightAnkle]);
  // Joints the map names but the clip lacks are the map check's to report.
  if (pelvis < 0 || clip.frames.empty()) return result;
  result.lifted = pelvis != 0;
  bool stands = true;
  std::size_t best_frame = 0;
  if (head >= 0 && left_ankle >= 0 && right_ankle >= 0) {
    const auto upright = [&](const BvhPose& pose) {
      return uprightness(pose, static_cast<std::size_t>(pelvis), static_cast<std::size_t>(head),
                         static_cast<std::size_t>(left_ankle), static_cast<std::size_t>(right_ankle));
    };
    stands = upright(bvhRestPose(clip)) >= kStandingCosine;
    double best = -std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; !stands && f < clip.frames.size(); ++f) {
      const double value = upright(bvhForwardKinematics(clip, f));
      if (value > best) {
        best = value;
        best_frame = f;
      }
    }
    if (!stands && best < kStandingCosine) {
      throw JointMapError(source_name + ": neither the zero pose nor any frame stands (head above the pelvis, " +
                          "ankles below it): a wrong joint map, or a clip that is not upright in Y?");
    }
  }
  if (!result.lifted && stands) return result;
  std::vector<Eigen::Matrix3d> rest(clip.joints.size(), Eigen::Matrix3d::Identity());
  if (!stands) {
    rest = bvhForwardKinematics(clip, best_frame).rotation;
    result.rest_frame = static_cast<int>(best_frame);
  }
  result.clip = bvhOnZeroPose(clip, static_cast<std::size_t>(pelvis), rest);
  return result;
}

}  // namespace dressed_human
