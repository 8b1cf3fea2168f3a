#pragma once
// Retargeting motion capture onto our skeleton: per frame, the 48 joint angles (y, x, z chain
// order of every joint) and the root pose that make our bones take the orientations of the
// corresponding source segments.
//
// Rotations are composed, never copied as Euler numbers: a BVH joint's channels are multiplied in
// the file's rotation order and accumulated down the source tree into world orientations; the
// source axes are changed to ours (BVH Y-up -> our Z-up, facing from the rest pose); a constant
// per-bone offset absorbs the difference of rest poses (a T-pose arm vs our hanging arm: the
// smallest rotation taking our bone's rest direction onto the source's rest direction); then the
// local rotation relative to our parent bone is split into our R_rest * Ry * Rx * Rz.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/foot_sole.h"
#include "dressed_human/core/motion/body_proportions.h"
#include "dressed_human/core/motion/bvh_file.h"
#include "dressed_human/core/motion/capture_units.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/motion/mocap_joint_map.h"
#include "dressed_human/core/motion/opensim_motion_file.h"
#include "dressed_human/core/skeleton/skeleton.h"

namespace dressed_human {

using JointPositions = std::array<Eigen::Vector3d, kJointCount>;

struct SampledMotion {
  std::string source;
  std::vector<double> times;               // seconds from the first frame, uniform steps
  std::vector<JointAngles> angles;         // radians in (-pi, pi]: unwrapping is the fitter's job
  std::vector<RigidTransform> root;        // our body frame in the capture's world, our axes (z up), metres
  std::array<bool, kJointCount> driven{};  // false: the source does not move this joint (held at rest)
  // The source skeleton's own forward kinematics, for the accuracy metric: the proximal joint of
  // every driven bone, our axes, relative to our root. Without a fitted body: relative to the
  // source root, scaled to our stature (our legs without a mapped head); with one: metres, relative to where our root
  // is placed in the capture's world. Empty when the source has no skeleton (joint coordinates).
  std::vector<JointPositions> reference_joint_positions;
  // With a fitted body: the lowest point of each foot of the capture (the mapped ankle's subtree,
  // joints and end sites; left, right), height in the capture's world, metres, levelled as the root.
  std::vector<std::array<double, 2>> reference_lowest_foot;
  // With a fitted body: how fast the capture's floor (the resting lower foot's lowest point, a line
  // fitted in time) rises, m/s; the root and the reference feet are levelled by it.
  double floor_rise_per_second = 0.0;
  double root_scale = 1.0;  // metres per source unit for the root translation (leg length ratio)
  double reference_scale =
      1.0;  // metres per source unit for the reference positions (stature ratio; leg ratio without a head)
  // The captured person's proportions (body_proportions.h): set when RetargetOptions::fit_body;
  // otherwise our default body (identity shape).
  bool body_fitted = false;
  BodyProportions proportions;
  CaptureUnits units;  // of the source, when body_fitted
  // Our root's place relative to the source root, in our body frame (metres): the offset that puts
  // our joints nearest the capture's over the whole record (least squares), when body_fitted.
  Eigen::Vector3d root_offset = Eigen::Vector3d::Zero();
  // Each joint that a segment of ours carries through joints we lack (our chest: the neck and
  // shoulders; carried_joints.h): where the capture holds it over the record, in the carrying
  // segment's frame, from its joint, source units; a fitted body's offsets put it there. Empty for
  // other joints.
  std::array<std::optional<Eigen::Vector3d>, kJointCount> held_joints;

  // The drawn body the feet were aimed for (RetargetOptions::body); null: the URDF's feet.
  std::shared_ptr<const BodyDescription> body;
  // Our soles as the feet were aimed for, with the person's proportions.
  FootSoles soles(const Skeleton& skeleton) const {
    return body ? FootSoles(skeleton, proportions.shape, *body) : FootSoles(skeleton, proportions.shape);
  }

  // The source frame taken as its rest pose where the file's zero pose does not stand
  // (bvh_standing_rest.h); -1: the file's own.
  int rest_frame = -1;

  double frameTime() const { return times.size() > 1 ? times[1] - times[0] : 0.0; }
};

// R = Ry(y) Rx(x) Rz(z) -> (y, x, z), each in (-pi, pi], x in [-pi/2, pi/2]. At gimbal lock
// (cos x < 1e-8) z = 0 and y takes y - z (x = +90 degrees) or y + z (x = -90); the angles rebuild
// R to ~3e-8 everywhere, but y and z jump where a motion passes through x = +-90 degrees.
Eigen::Vector3d decomposeYxz(const Eigen::Matrix3d& rotation);
// The same rotation's angles on the branch nearest `near` (a joint's angles a frame before, or
// its rest pose): of (y, x, z) and (y + pi, pi - x, z + pi), each shifted by whole turns to lie
// nearest, the one nearest `near`; at gimbal lock z stays at near's and y takes the rest. A
// joint moving through x = +-90 degrees keeps continuous angles, which decomposeYxz's principal
// branch breaks by half a turn in y and z (and a smooth Fourier series then cuts the corner).
Eigen::Vector3d decomposeYxzNear(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& near);
// R = Rz(yaw) Ry(pitch) Rx(roll) -> (roll, pitch, yaw); at pitch +-90 degrees roll = 0.
Eigen::Vector3d decomposeRollPitchYaw(const Eigen::Matrix3d& rotation);

// Source axes to ours (x forward, y left, z up) for a Y-up BVH: left from the rest pose's hips.
// Throws JointMapError if the map lacks a hip, MotionError if the hips coincide.
Eigen::Matrix3d bvhToOurAxes(const BvhClip& clip, const BvhPose& rest, const BvhJointMap& map,
                             const std::string& source_name);

// The standing height of our skeleton at rest (lowest to highest bone end), metres.
double skeletonStature(const Skeleton& skeleton);

struct RetargetOptions {
  // Fit the person's proportions (fitBodyProportions) and retarget onto our skeleton with them:
  // the root moves in metres of the capture, the reference is the capture's own FK in metres.
  bool fit_body = false;
  std::string units;  // the capture's length unit (unitsByName); "": detected from the rest stature
  // Our drawn body: its feet (FootSoles) stand flat where the capture's do. Null: the URDF's foot
  // cylinders.
  std::shared_ptr<const BodyDescription> body;
};

// Throws JointMapError for a map that does not fit the clip and MotionError for a rest pose that
// gives no left-right direction, and with fit_body for a rest pose whose unit or proportions
// cannot be read.
SampledMotion retargetBvh(const BvhClip& clip, const BvhJointMap& map, const Skeleton& skeleton,
                          const std::string& source_name, const RetargetOptions& options = RetargetOptions());
SampledMotion retargetCoordinates(const OpenSimTable& table, const CoordinateJointMap& map, const Skeleton& skeleton,
                                  const std::string& source_name);

}  // namespace dressed_human
