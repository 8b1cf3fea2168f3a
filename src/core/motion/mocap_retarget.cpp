#include "dressed_human/core/motion/mocap_retarget.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "dressed_human/core/motion/bvh_standing_rest.h"
#include "dressed_human/core/motion/capture_foot.h"
#include "dressed_human/core/motion/carried_joints.h"
#include "dressed_human/core/motion/motion.h"

namespace dressed_human {
namespace {

constexpr double kDegree = M_PI / 180.0;

using namespace human_joint;  // NOLINT: the joint indices by name

Eigen::Matrix3d toMatrix(const Eigen::Quaterniond& q) { return q.normalized().toRotationMatrix(); }

// Our skeleton at rest with the root at the origin: world rotation and proximal position per bone.
struct RestPose {
  std::array<Eigen::Matrix3d, kBoneCount> rotation;
  std::array<Eigen::Vector3d, kBoneCount> position;
};

RestPose ourRestPose(const Skeleton& skeleton) {
  const ForwardKinematics kinematics(skeleton);
  SkeletonPose pose;
  kinematics.compute(RigidTransform(), JointAngles{}, pose);
  RestPose rest;
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    rest.rotation[b] = toMatrix(pose.bone_in_world[b].rotation);
    rest.position[b] = pose.bone_in_world[b].translation;
  }
  return rest;
}

// Rest direction of a source segment: towards the middle of its children where it branches (an
// OpenSim torso carrying both arms, a hand with fingers and thumb), else towards the first
// descendant (joint or end site) that is not at the same place; zero-length helper joints (CMU's
// LHipJoint, LeftFingerBase) are skipped.
Eigen::Vector3d firstDistinctDescendant(const BvhClip& clip, const BvhPose& rest, int joint) {
  const Eigen::Vector3d& origin = rest.position[static_cast<std::size_t>(joint)];
  std::vector<Eigen::Vector3d> branches;
  for (const Eigen::Vector3d& end : clip.joints[static_cast<std::size_t>(joint)].end_sites) branches.push_back(end);
  for (const int child : clip.joints[static_cast<std::size_t>(joint)].children) {
    branches.push_back(rest.position[static_cast<std::size_t>(child)] - origin);
  }
  branches.erase(
      std::remove_if(branches.begin(), branches.end(), [](const Eigen::Vector3d& d) { return d.norm() < 1e-9; }),
      branches.end());
  if (branches.size() > 1) {
    Eigen::Vector3d middle = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& d : branches) middle += d / static_cast<double>(branches.size());
    if (middle.norm() > 1e-9) return middle;
  }
  std::vector<int> stack = {joint};
  while (!stack.empty()) {
    const auto j = static_cast<std::size_t>(stack.back());
    stack.pop_back();
    for (const Eigen::Vector3d& end : clip.joints[j].end_sites) {
      const Eigen::Vector3d d = rest.position[j] + end - origin;
      if (d.norm() > 1e-9) return d;
    }
    const std::vector<int>& children = clip.joints[j].children;
    for (auto child = children.rbegin(); child != children.rend(); ++child) {
      const Eigen::Vector3d d = rest.position[static_cast<std::size_t>(*child)] - origin;
      if (d.norm() > 1e-9) return d;
      stack.push_back(*child);
    }
  }
  return Eigen::Vector3d::Zero();
}

// Joint j's (y, x, z) of `angles`.
Eigen::Vector3d yxzOf(const JointAngles& angles, std::size_t j) {
  return {angles[j * kDofsPerJoint], angles[j * kDofsPerJoint + 1], angles[j * kDofsPerJoint + 2]};
}

// Our joint angles from target world orientations (nullptr: held at rest), walking the bones
// parents first so that every local rotation is taken relative to our own parent bone.
// Each joint's angles on the branch nearest `near` (the frame before; the rest pose, zeros, first).
JointAngles solveJointAngles(const Skeleton& skeleton, const Eigen::Matrix3d& body,
                             const std::array<const Eigen::Matrix3d*, kJointCount>& target, const JointAngles& near) {
  JointAngles angles{};
  std::array<Eigen::Matrix3d, kBoneCount> world;
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    const Bone& bone = skeleton.bone(b);
    const Eigen::Matrix3d& parent = bone.parent < 0 ? body : world[static_cast<std::size_t>(bone.parent)];
    const Eigen::Matrix3d rest = parent * toMatrix(bone.rest_rotation);
    world[b] = rest;
    if (bone.joint < 0) continue;
    const auto j = static_cast<std::size_t>(bone.joint);
    if (!target[j]) continue;
    const Eigen::Vector3d yxz = decomposeYxzNear(rest.transpose() * *target[j], yxzOf(near, j));
    for (std::size_t d = 0; d < kDofsPerJoint; ++d) angles[j * kDofsPerJoint + d] = yxz[static_cast<int>(d)];
    world[b] = rest * Eigen::AngleAxisd(yxz[0], Eigen::Vector3d::UnitY()) *
               Eigen::AngleAxisd(yxz[1], Eigen::Vector3d::UnitX()) *
               Eigen::AngleAxisd(yxz[2], Eigen::Vector3d::UnitZ());
  }
  return angles;
}

Eigen::Matrix3d chainRotation(const std::vector<CoordinateRotation>& chain, const std::vector<int>& columns,
                              const std::vector<double>& row, double angle_unit) {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  for (std::size_t i = 0; i < chain.size(); ++i) {
    rotation = rotation * Eigen::AngleAxisd(row[static_cast<std::size_t>(columns[i])] * angle_unit, chain[i].axis);
  }
  return rotation;
}

// A capture's floor that rises or sinks along the record (a tilted calibration, CMU 02_01: the
// left foot lands 3 cm higher a cycle later) cannot be followed by a periodic motion: its feet
// would float above the ground in one cycle and sink into it in the next. The floor is where a
// foot rests: the lower foot's lowest point while it hardly moves up or down (under 5 cm/s),
// fitted by a line in time; the root and the reference feet are levelled by it. A level record
// gives a flat line whatever part of a cycle it covers (the resting foot's height is the floor's).
void levelFloor(SampledMotion& motion) {
  constexpr double kRestingSpeed = 0.05;  // m/s
  const std::size_t frames = motion.times.size();
  std::vector<std::pair<double, double>> resting;  // time, floor height
  for (std::size_t f = 1; f + 1 < frames; ++f) {
    const auto& feet = motion.reference_lowest_foot;
    const std::size_t lower = feet[f][0] <= feet[f][1] ? 0 : 1;
    const double speed = (feet[f + 1][lower] - feet[f - 1][lower]) / (motion.times[f + 1] - motion.times[f - 1]);
    if (std::abs(speed) < kRestingSpeed) resting.emplace_back(motion.times[f], feet[f][lower]);
  }
  motion.floor_rise_per_second = 0.0;
  if (resting.size() < 10 || resting.back().first - resting.front().first < 0.5) return;
  double mean_t = 0.0;
  double mean_floor = 0.0;
  for (const auto& [t, floor] : resting) {
    mean_t += t / static_cast<double>(resting.size());
    mean_floor += floor / static_cast<double>(resting.size());
  }
  double covariance = 0.0;
  double variance = 0.0;
  for (const auto& [t, floor] : resting) {
    covariance += (t - mean_t) * (floor - mean_floor);
    variance += (t - mean_t) * (t - mean_t);
  }
  motion.floor_rise_per_second = covariance / variance;
  for (std::size_t f = 0; f < frames; ++f) {
    const double rise = motion.floor_rise_per_second * (motion.times[f] - mean_t);
    motion.root[f].translation.z() -= rise;
    for (double& lowest : motion.reference_lowest_foot[f]) lowest -= rise;
  }
}

// With a fitted body (its unit and proportions found here), the root and the reference in metres
// of the capture: our joints (FK with the fitted shape on the retargeted angles) and the
// capture's, both relative to the source root, differ by a constant offset of our root in the
// pelvis frame; it is the mean of their differences, turned into the body frame, over every
// driven joint and frame (least squares). The fitted body holds the carried joints where the
// capture holds them (carried_joints.h).
void placeFittedBody(const BvhClip& clip, const std::vector<BvhPose>& poses, const BvhJointMap& map,
                     const Skeleton& skeleton, const Eigen::Matrix3d& to_ours, std::size_t root,
                     const std::array<std::size_t, kJointCount>& source_joint, const std::string& units,
                     SampledMotion& motion) {
  motion.units = units.empty() ? detectBvhUnits(clip, motion.source) : unitsByName(units);
  motion.proportions = fitBodyProportions(clip, map, skeleton, motion.units.metres_per_unit, motion.source);
  motion.body_fitted = true;
  const double metres = motion.units.metres_per_unit;
  holdCarriedJoints(skeleton, metres, motion.held_joints, motion.source, motion.proportions.shape);
  const ForwardKinematics kinematics(skeleton, motion.proportions.shape);
  const std::size_t frames = clip.frames.size();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::size_t count = 0;
  SkeletonPose ours;
  for (std::size_t f = 0; f < frames; ++f) {
    RigidTransform body;
    body.rotation = motion.root[f].rotation;
    kinematics.compute(body, motion.angles[f], ours);
    const Eigen::Matrix3d to_body = toMatrix(body.rotation).transpose();
    for (std::size_t j = 0; j < kJointCount; ++j) {
      if (!motion.driven[j]) continue;
      const Eigen::Vector3d source =
          metres * (to_ours * (poses[f].position[source_joint[j]] - poses[f].position[root]));
      sum += to_body * (source - ours.bone_in_world[static_cast<std::size_t>(skeleton.joint(j).bone)].translation);
      ++count;
    }
  }
  motion.root_offset = count > 0 ? Eigen::Vector3d(sum / static_cast<double>(count)) : Eigen::Vector3d::Zero();
  motion.root_scale = metres;
  motion.reference_scale = metres;
  // The lowest point of each foot: the mapped ankle's subtree, joints and end sites.
  std::array<std::vector<std::size_t>, 2> feet;
  for (std::size_t side = 0; side < 2; ++side) {
    const std::string& ankle = map.joints[side == 0 ? kLeftAnkle : kRightAnkle];
    if (!ankle.empty()) feet[side] = bvhSubtree(clip, static_cast<std::size_t>(clip.findJoint(ankle)));
  }
  motion.reference_lowest_foot.assign(frames, {0.0, 0.0});
  for (std::size_t f = 0; f < frames; ++f) {
    const Eigen::Vector3d offset = toMatrix(motion.root[f].rotation) * motion.root_offset;
    motion.root[f].translation = metres * (to_ours * poses[f].position[root]) + offset;
    for (std::size_t j = 0; j < kJointCount; ++j) {
      if (!motion.driven[j]) continue;
      motion.reference_joint_positions[f][j] =
          metres * (to_ours * (poses[f].position[source_joint[j]] - poses[f].position[root])) - offset;
    }
    for (std::size_t side = 0; side < 2; ++side) {
      double lowest = std::numeric_limits<double>::infinity();
      for (const std::size_t j : feet[side]) {
        lowest = std::min(lowest, metres * (to_ours * poses[f].position[j]).z());
        for (const Eigen::Vector3d& end : clip.joints[j].end_sites) {
          lowest = std::min(lowest, metres * (to_ours * (poses[f].position[j] + poses[f].rotation[j] * end)).z());
        }
      }
      motion.reference_lowest_foot[f][side] = feet[side].empty() ? 0.0 : lowest;
    }
  }
  if (!feet[0].empty() && !feet[1].empty()) levelFloor(motion);
}

// From the lowest to the highest joint or end site of the source's rest pose, along our up.
double restHeight(const BvhClip& clip, const BvhPose& rest, const Eigen::Matrix3d& to_ours, std::size_t root) {
  double low = 0.0;
  double high = 0.0;
  for (std::size_t j = 0; j < clip.joints.size(); ++j) {
    const double height = (to_ours * (rest.position[j] - rest.position[root])).z();
    low = std::min(low, height);
    high = std::max(high, height);
    for (const Eigen::Vector3d& end : clip.joints[j].end_sites) {
      const double end_height = (to_ours * (rest.position[j] + end - rest.position[root])).z();
      low = std::min(low, end_height);
      high = std::max(high, end_height);
    }
  }
  return high - low;
}

}  // namespace

Eigen::Matrix3d bvhToOurAxes(const BvhClip& clip, const BvhPose& rest, const BvhJointMap& map,
                             const std::string& source_name) {
  // BVH is Y-up; left comes from the hips of the rest pose, forward = left x up.
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  if (map.joints[kLeftHip].empty() || map.joints[kRightHip].empty()) {
    throw JointMapError(source_name + ": the joint map must name both hips (they give the body's left-right axis)");
  }
  const auto position = [&](int joint) -> const Eigen::Vector3d& {
    return rest.position[static_cast<std::size_t>(clip.findJoint(map.joints[static_cast<std::size_t>(joint)]))];
  };
  Eigen::Vector3d left = position(kLeftHip) - position(kRightHip);
  left -= left.dot(up) * up;
  if (left.norm() < 1e-9) {
    throw MotionError(source_name + ": the rest pose puts both hips at the same place: no left-right direction");
  }
  left.normalize();
  Eigen::Matrix3d to_ours;  // rows: forward, left, up in source coordinates
  to_ours.row(0) = left.cross(up);
  to_ours.row(1) = left;
  to_ours.row(2) = up;
  return to_ours;
}

// Where the middle angle nears +-90 degrees the outer two share one axis. Their split is then
// ill-conditioned: reading them off entries that carry cos(middle) costs eps / cos(middle) in the
// rebuilt rotation, while putting everything into the first angle costs ~cos(middle). Switching
// where the two meet, cos(middle) ~ sqrt(eps), bounds the rebuild error by ~3e-8 everywhere (the
// former test 1 - |sin| < 1e-12 switched at cos ~ 1.4e-6 and lost up to ~3e-6). The middle angle
// comes from atan2 with cos(middle) = |column or row|: asin near +-1 loses half the digits.
constexpr double kGimbalCosine = 1e-8;

Eigen::Vector3d decomposeYxz(const Eigen::Matrix3d& r) {
  // R = Ry(a) Rx(b) Rz(c): third column (sa cb, -sb, ca cb), second row (cb sc, cb cc, -sb).
  const double cos_x = std::hypot(r(0, 2), r(2, 2));
  const double x = std::atan2(-r(1, 2), cos_x);
  if (cos_x < kGimbalCosine) {
    // Gimbal lock: only y - z (at +90 degrees) or y + z (at -90) is defined; put it all into y.
    return {std::atan2(-r(2, 0), r(0, 0)), x, 0.0};
  }
  return {std::atan2(r(0, 2), r(2, 2)), x, std::atan2(r(1, 0), r(1, 1))};
}

namespace {

double nearestTurn(double angle, double reference) { return reference + std::remainder(angle - reference, 2.0 * M_PI); }

Eigen::Vector3d nearestTurns(const Eigen::Vector3d& angles, const Eigen::Vector3d& reference) {
  return {nearestTurn(angles[0], reference[0]), nearestTurn(angles[1], reference[1]),
          nearestTurn(angles[2], reference[2])};
}

}  // namespace

Eigen::Vector3d decomposeYxzNear(const Eigen::Matrix3d& r, const Eigen::Vector3d& near) {
  const Eigen::Vector3d principal = decomposeYxz(r);
  const double x = principal[1];
  if (std::hypot(r(0, 2), r(2, 2)) < kGimbalCosine) {
    // decomposeYxz put all of y - z (x = +90) or y + z (x = -90) into y: z keeps near's.
    const double z = near[2];
    return nearestTurns({x > 0.0 ? principal[0] + z : principal[0] - z, x, z}, near);
  }
  const Eigen::Vector3d first = nearestTurns(principal, near);
  const Eigen::Vector3d second = nearestTurns({principal[0] + M_PI, M_PI - x, principal[2] + M_PI}, near);
  return (first - near).squaredNorm() <= (second - near).squaredNorm() ? first : second;
}

Eigen::Vector3d decomposeRollPitchYaw(const Eigen::Matrix3d& r) {
  // R = Rz(yaw) Ry(pitch) Rx(roll): third row (-sp, cp sr, cp cr), first column (cy cp, sy cp, -sp).
  const double cos_pitch = std::hypot(r(2, 1), r(2, 2));
  const double pitch = std::atan2(-r(2, 0), cos_pitch);
  if (cos_pitch < kGimbalCosine) return {0.0, pitch, std::atan2(-r(0, 1), r(1, 1))};
  return {std::atan2(r(2, 1), r(2, 2)), pitch, std::atan2(r(1, 0), r(0, 0))};
}

double skeletonStature(const Skeleton& skeleton) {
  const RestPose rest = ourRestPose(skeleton);
  double low = 0.0;
  double high = 0.0;
  for (std::size_t b = 0; b < kBoneCount; ++b) {
    const Eigen::Vector3d end = rest.position[b] + rest.rotation[b].col(2) * skeleton.bone(b).length;
    low = std::min({low, rest.position[b].z(), end.z()});
    high = std::max({high, rest.position[b].z(), end.z()});
  }
  return high - low;
}

namespace {

// Our left leg's length (hip to knee to ankle) over the source's, at rest.
double legScale(const BvhClip& clip, const BvhPose& source_rest, const BvhJointMap& map, const Skeleton& skeleton,
                const RestPose& our_rest, const std::string& source_name) {
  const auto source = [&](int joint) {
    return source_rest.position[static_cast<std::size_t>(clip.findJoint(map.joints[static_cast<std::size_t>(joint)]))];
  };
  const auto ours = [&](int joint) {
    return our_rest.position[static_cast<std::size_t>(skeleton.joint(static_cast<std::size_t>(joint)).bone)];
  };
  double source_leg = 0.0;
  if (!map.joints[kLeftKnee].empty() && !map.joints[kLeftAnkle].empty()) {
    source_leg = (source(kLeftKnee) - source(kLeftHip)).norm() + (source(kLeftAnkle) - source(kLeftKnee)).norm();
  }
  if (!(source_leg > 1e-9)) throw MotionError(source_name + ": the source's left leg has no length at rest");
  return ((ours(kLeftKnee) - ours(kLeftHip)).norm() + (ours(kLeftAnkle) - ours(kLeftKnee)).norm()) / source_leg;
}

}  // namespace

SampledMotion retargetBvh(const BvhClip& file_clip, const BvhJointMap& map, const Skeleton& skeleton,
                          const std::string& source_name, const RetargetOptions& options) {
  const StandingRest standing = standingRest(file_clip, map, source_name);
  const BvhClip& clip = standing.clip;
  checkBvhJointMap(map, clip, source_name);
  const BvhPose source_rest = bvhRestPose(clip);
  const RestPose our_rest = ourRestPose(skeleton);
  const auto sourceIndex = [&](const std::string& name) { return static_cast<std::size_t>(clip.findJoint(name)); };
  const std::size_t root = sourceIndex(map.root);

  const Eigen::Matrix3d to_ours = bvhToOurAxes(clip, source_rest, map, source_name);
  const OurFoot our_foot(options.body ? FootSoles(skeleton, BodyShape(), *options.body)
                                      : FootSoles(skeleton, BodyShape()));

  // Constant per-bone offset: our rest frame turned so that its bone axis lies along the source's
  // rest segment. World target of bone b = to_ours * G_source * to_ours^T * offset_b.
  std::array<Eigen::Matrix3d, kJointCount> rest_offset;
  std::array<std::size_t, kJointCount> source_joint{};
  std::array<std::optional<ToeTip>, kJointCount> toe_tip;  // a foot's farthest point, which its bone points at
  std::array<CarriedJoints, kJointCount> carried;
  SampledMotion motion;
  motion.source = source_name;
  motion.rest_frame = standing.rest_frame;
  motion.body = options.body;
  for (std::size_t j = 0; j < kJointCount; ++j) {
    motion.driven[j] = !map.joints[j].empty();
    if (!motion.driven[j]) continue;
    source_joint[j] = sourceIndex(map.joints[j]);
    const auto s = static_cast<int>(source_joint[j]);
    const int distal = kDistalJoint[j];
    // A foot points at its farthest point (the toe tip), which its length reaches (body_proportions.h):
    // in a flat stance the sole's line, where the first descendant (the ball) tilts it into the ground.
    const bool foot = j == static_cast<std::size_t>(kLeftAnkle) || j == static_cast<std::size_t>(kRightAnkle);
    const bool own_tip = foot && (distal < 0 || map.joints[static_cast<std::size_t>(distal)].empty());
    Eigen::Vector3d to_tip = Eigen::Vector3d::Zero();
    if (own_tip) {
      const BvhPoint tip = bvhFarthestPointBelow(clip, source_rest, source_joint[j]);
      to_tip = bvhPointPosition(clip, source_rest, tip) - source_rest.position[source_joint[j]];
      const Eigen::Vector3d tip_in_ours = to_ours * to_tip;
      toe_tip[j] = ToeTip{tip, to_tip.norm(), 0.0, 0.0};
      toe_tip[j]->flat_height = tipHeight(clip, source_rest, *toe_tip[j], source_joint[j], to_ours);
      // At rest our sole lies flat under the capture's foot: the tip's heading, level.
      const Eigen::Vector3d level(tip_in_ours.x(), tip_in_ours.y(), 0.0);
      if (level.norm() > 1e-9) to_tip = to_ours.transpose() * level.normalized() * to_tip.norm();
    }
    Eigen::Vector3d direction = distal >= 0 && !map.joints[static_cast<std::size_t>(distal)].empty()
                                    ? source_rest.position[sourceIndex(map.joints[static_cast<std::size_t>(distal)])] -
                                          source_rest.position[source_joint[j]]
                                : own_tip ? to_tip
                                          : firstDistinctDescendant(clip, source_rest, s);
    if (direction.norm() < 1e-9) direction = firstDistinctDescendant(clip, source_rest, s);
    carried[j] = carriedJoints(clip, source_rest, map, skeleton, j, source_joint[j], to_ours);
    const std::size_t bone = static_cast<std::size_t>(skeleton.joint(j).bone);
    Eigen::Matrix3d offset = our_rest.rotation[bone];
    if (direction.norm() > 1e-9) {
      const Eigen::Quaterniond swing =
          Eigen::Quaterniond::FromTwoVectors(our_rest.rotation[bone].col(2), to_ours * direction);
      offset = toMatrix(swing) * offset;
    }
    rest_offset[j] = offset;
  }

  // Root translation: scaled by leg length so that the feet reach the floor and strides do not
  // slide; shifted so that our hip joints sit at the scaled height of the source's.
  const std::size_t source_hip = sourceIndex(map.joints[kLeftHip]);
  motion.root_scale = legScale(clip, source_rest, map, skeleton, our_rest, source_name);
  const double source_hip_drop = -(to_ours * (source_rest.position[source_hip] - source_rest.position[root])).z();
  const double our_hip_drop = -our_rest.position[static_cast<std::size_t>(skeleton.joint(kLeftHip).bone)].z();
  const double height_shift = our_hip_drop - motion.root_scale * source_hip_drop;

  // The stature needs the top of the head; a source without one (an OpenSim gait model: legs and
  // pelvis) is scaled by its legs, as the root is.
  motion.reference_scale = map.joints[kHead].empty()
                               ? motion.root_scale
                               : skeletonStature(skeleton) / restHeight(clip, source_rest, to_ours, root);

  const std::size_t frames = clip.frames.size();
  std::vector<BvhPose> poses(frames);
  for (std::size_t f = 0; f < frames; ++f) poses[f] = bvhForwardKinematics(clip, f);
  holdPostures(poses, source_joint, to_ours, rest_offset, carried, motion.held_joints);
  const auto footOf = [&](const BvhPose& pose, std::size_t j) {
    return aimedFoot(to_ours * pose.rotation[source_joint[j]] * to_ours.transpose() * rest_offset[j],
                     footAim(clip, pose, *toe_tip[j], source_joint[j], to_ours, our_foot, motion.root_scale),
                     toe_tip[j]->flat_roll);
  };
  for (std::size_t j = 0; j < kJointCount; ++j) {
    if (!toe_tip[j]) continue;
    toe_tip[j]->flat_height = flatHeight(clip, poses, *toe_tip[j], source_joint[j], to_ours);
    toe_tip[j]->flat_roll = flatRoll(poses, source_joint[j], to_ours, [&](const BvhPose& p) { return footOf(p, j); });
  }
  motion.times.resize(frames);
  motion.angles.resize(frames);
  motion.root.resize(frames);
  motion.reference_joint_positions.resize(frames);
  std::array<Eigen::Matrix3d, kJointCount> target;
  std::array<const Eigen::Matrix3d*, kJointCount> target_pointer{};
  std::vector<Eigen::Vector3d> carried_now;
  for (std::size_t f = 0; f < frames; ++f) {
    const BvhPose& pose = poses[f];
    motion.times[f] = static_cast<double>(f) * clip.frame_time;
    const Eigen::Matrix3d body = to_ours * pose.rotation[root] * to_ours.transpose();
    for (std::size_t j = 0; j < kJointCount; ++j) {
      target_pointer[j] = nullptr;
      if (!motion.driven[j]) continue;
      target[j] = to_ours * pose.rotation[source_joint[j]] * to_ours.transpose() * rest_offset[j];
      if (toe_tip[j]) target[j] = footOf(pose, j);
      if (!toe_tip[j] && !carried[j].source.empty())
        target[j] = carriedRotation(carried[j], pose, source_joint[j], to_ours, carried_now) * rest_offset[j];
      target_pointer[j] = &target[j];
      motion.reference_joint_positions[f][j] =
          motion.reference_scale * (to_ours * (pose.position[source_joint[j]] - pose.position[root]));
    }
    motion.angles[f] = solveJointAngles(skeleton, body, target_pointer, f > 0 ? motion.angles[f - 1] : JointAngles{});
    Eigen::Vector3d position = motion.root_scale * (to_ours * pose.position[root]);
    position.z() += height_shift;
    motion.root[f].translation = position;
    motion.root[f].rotation = Eigen::Quaterniond(body).normalized();
  }
  if (options.fit_body) placeFittedBody(clip, poses, map, skeleton, to_ours, root, source_joint, options.units, motion);
  return motion;
}

SampledMotion retargetCoordinates(const OpenSimTable& table, const CoordinateJointMap& map, const Skeleton& skeleton,
                                  const std::string& source_name) {
  checkCoordinateJointMap(map, table, source_name);
  const RestPose our_rest = ourRestPose(skeleton);
  // OpenSim axes (X forward, Y up, Z right) -> ours (x forward, y left, z up).
  Eigen::Matrix3d to_ours;
  to_ours << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  const double angle_unit = table.in_degrees ? kDegree : 1.0;
  const auto columnsOf = [&](const std::vector<CoordinateRotation>& chain) {
    std::vector<int> columns;
    for (const CoordinateRotation& r : chain) columns.push_back(table.findColumn(r.column));
    return columns;
  };
  const std::vector<int> root_columns = columnsOf(map.root_rotation);
  std::array<std::vector<int>, kJointCount> joint_columns;
  SampledMotion motion;
  motion.source = source_name;
  for (std::size_t j = 0; j < kJointCount; ++j) {
    joint_columns[j] = columnsOf(map.joints[j]);
    motion.driven[j] = !map.joints[j].empty();
  }
  std::array<int, 3> translation_columns{};
  for (std::size_t k = 0; k < 3; ++k) {
    translation_columns[k] = map.root_translation[k].empty() ? -1 : table.findColumn(map.root_translation[k]);
  }

  const std::size_t frames = table.rows.size();
  motion.times.resize(frames);
  motion.angles.resize(frames);
  motion.root.resize(frames);
  for (std::size_t f = 0; f < frames; ++f) {
    const std::vector<double>& row = table.rows[f];
    motion.times[f] = table.times[f] - table.times[0];
    for (std::size_t j = 0; j < kJointCount; ++j) {
      if (!motion.driven[j]) continue;
      // A joint rotation between segments that are parallel at rest, in our body axes, turned
      // into our bone's frame: R_joint = R0^T D R0 (R0: our bone's rest orientation).
      const Eigen::Matrix3d relative =
          to_ours * chainRotation(map.joints[j], joint_columns[j], row, angle_unit) * to_ours.transpose();
      const Eigen::Matrix3d& rest = our_rest.rotation[static_cast<std::size_t>(skeleton.joint(j).bone)];
      const Eigen::Vector3d before = f > 0 ? yxzOf(motion.angles[f - 1], j) : Eigen::Vector3d::Zero();
      const Eigen::Vector3d yxz = decomposeYxzNear(rest.transpose() * relative * rest, before);
      for (std::size_t d = 0; d < kDofsPerJoint; ++d)
        motion.angles[f][j * kDofsPerJoint + d] = yxz[static_cast<int>(d)];
    }
    const Eigen::Matrix3d body =
        to_ours * chainRotation(map.root_rotation, root_columns, row, angle_unit) * to_ours.transpose();
    Eigen::Vector3d translation = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < 3; ++k) {
      if (translation_columns[k] >= 0)
        translation[static_cast<int>(k)] = row[static_cast<std::size_t>(translation_columns[k])];
    }
    motion.root[f].translation = to_ours * translation;
    motion.root[f].rotation = Eigen::Quaterniond(body).normalized();
  }
  return motion;
}

}  // namespace dressed_human
