#include "dressed_human/core/locomotion/speed_gait.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "dressed_human/core/locomotion/planted_feet.h"
#include "dressed_human/core/locomotion/symmetric_walk.h"

namespace dressed_human {
namespace {

constexpr double kGravity = 9.81;      // m/s^2
constexpr int kSamplesPerCycle = 100;  // when measuring strides and heel strikes
constexpr int kStridesPerKnot = 4;     // strides measured per interval between knots
constexpr std::array<const char*, 2> kSides = {"l_", "r_"};
constexpr std::size_t kPelvisPitch = 1;  // Motion::root.rotation: roll, pitch, yaw
constexpr std::array<const char*, 3> kSagittalJoints = {"hip", "knee", "ankle"};
const std::array<const char*, 6> kLegJoints = {"l_hip", "l_knee", "l_ankle", "r_hip", "r_knee", "r_ankle"};

Eigen::Quaterniond rollPitchYaw(double roll, double pitch, double yaw) {
  return Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX());
}

}  // namespace

Motion walkInCycles(const Motion& walk) {
  Motion m = walk;
  for (std::size_t i = 0; i < Motion::kSeriesCount; ++i) {
    const FourierSeries& s = walk.series(i);
    if (std::abs(s.period - walk.period) > 1e-9 * walk.period) {
      throw LocomotionError("motion '" + walk.name + "': series " + walk.seriesName(i) + " has period " +
                            std::to_string(s.period) + " s, not the motion's " + std::to_string(walk.period) +
                            " s; a walk's series share one cycle");
    }
  }
  for (FourierSeries& s : m.dofs) s = inCycles(s);
  for (FourierSeries& s : m.root.rotation) s = inCycles(s);
  for (FourierSeries& s : m.root.translation) s = FourierSeries{};
  m.root.forward_speed = 0.0;
  m.period = 1.0;
  return m;
}

SpeedGait::SpeedGait(const Motion& walk, const NormativeGait& normative, const Skeleton& skeleton,
                     const BodyShape& shape, FootSoles soles)
    : kinematics_(std::make_shared<const ForwardKinematics>(skeleton, shape)), soles_(std::move(soles)) {
  walk.validate();
  if (normative.classes.empty()) throw LocomotionError("the gait table has no speed classes");
  walk_speed_ = walk.root.forward_speed;
  if (!(walk_speed_ > 0.1)) {
    throw LocomotionError("motion '" + walk.name + "' moves forward at " + std::to_string(walk_speed_) +
                          " m/s: a walk (root.forward_speed > 0.1 m/s) is needed to walk routes");
  }
  const Motion cycles = symmetricWalk(walkInCycles(walk), skeleton);
  for (std::size_t i = 0; i < kDofCount; ++i) standing_[i] = 0.5 * cycles.dofs[i].a0;
  standing_pelvis_ = rollPitchYaw(0.5 * cycles.root.rotation[0].a0, 0.5 * cycles.root.rotation[1].a0, 0.0);
  measureLeg(skeleton);

  // Our heel strike: where the left foot takes the body over from the right (PlantedFeet).
  MotionEvaluator own(cycles);
  PlantedFeet feet(soles_);
  SkeletonPose pose;
  left_heel_strike_ = -1.0;
  for (int i = 0; i <= 2 * kSamplesPerCycle && left_heel_strike_ < 0.0; ++i) {
    const double phase = static_cast<double>(i) / kSamplesPerCycle;
    const bool was_right = !feet.isLeft(feet.carryingPoint());
    own.evaluate(phase, scratch_, scratch_root_);
    kinematics_->compute({Eigen::Vector3d::Zero(), scratch_root_.rotation}, scratch_, pose);
    feet.place(pose, 0.0);
    if (i > 0 && was_right && feet.isLeft(feet.carryingPoint())) left_heel_strike_ = std::fmod(phase, 1.0);
  }
  if (left_heel_strike_ < 0.0)
    throw LocomotionError("motion '" + walk.name + "' never sets the left foot down after the right");

  const double root_gl = std::sqrt(kGravity * leg_length_);
  for (const NormativeGaitClass& c : normative.classes) {
    gaits_.emplace_back(gaitAt(cycles, normative, c.speed));
    Knot knot{};
    knot.speed = c.speed * root_gl;
    knot.normative_stride = c.stride * leg_length_;
    knot.normative_cadence = c.cadence * std::sqrt(kGravity / leg_length_);
    knot.normative_stride_sd = c.stride_sd * leg_length_;
    knot.normative_cadence_sd = c.cadence_sd * std::sqrt(kGravity / leg_length_);
    knots_.push_back(knot);
  }
  // Strides measured on a grid finer than the knots: a mixed gait's stride is not the mix of theirs.
  for (std::size_t k = 0; k < knots_.size(); ++k) {
    for (int sub = 0; sub < (k + 1 < knots_.size() ? kStridesPerKnot : 1); ++sub) {
      const double v = k + 1 < knots_.size()
                           ? knots_[k].speed + (knots_[k + 1].speed - knots_[k].speed) * sub / kStridesPerKnot
                           : knots_[k].speed;
      const double stride = measuredStride(v);
      if (!(stride > 0.05)) {
        throw LocomotionError("motion '" + walk.name + "' at " + std::to_string(v) + " m/s makes strides of " +
                              std::to_string(stride) + " m with its feet planted: not a walk forward");
      }
      strides_.emplace_back(v, stride);
      if (sub == 0) {
        knots_[k].stride = stride;
        knots_[k].cycle_rate = v / stride;
      }
    }
  }
}

// Leg length, the DOFs of the sagittal curves and their signs, and a standing pose with the
// legs straight and the soles flat.
void SpeedGait::measureLeg(const Skeleton& skeleton) {
  for (const char* joint : kLegJoints) {
    const int j = skeleton.findJoint(joint);
    for (std::size_t d = 0; d < kDofsPerJoint; ++d) standing_[static_cast<std::size_t>(j) * kDofsPerJoint + d] = 0.0;
  }
  PlantedFeet feet(soles_);
  SkeletonPose pose;
  const auto at = [&](const JointAngles& angles) -> const SkeletonPose& {
    kinematics_->compute(RigidTransform(), angles, pose);
    return pose;
  };
  const auto bonePosition = [&](const SkeletonPose& p, const std::string& bone) {
    return p.bone_in_world[static_cast<std::size_t>(skeleton.findBone(bone))].translation;
  };
  for (std::size_t side = 0; side < 2; ++side) {
    const std::string s = kSides[side];
    const std::size_t heel = feet.soles().heel(side), toe = feet.soles().ball(side);
    for (std::size_t c = 0; c < 3; ++c) {
      sagittal_dof_[side][c] = static_cast<std::size_t>(skeleton.findJoint(s + kSagittalJoints[c])) * kDofsPerJoint;
    }
    // Level the sole: the ankle angle at which heel and toe are equally high (bisection).
    const std::size_t ankle = sagittal_dof_[side][2];
    double low = -0.8, high = 0.8;
    const auto tilt = [&](double angle) {
      JointAngles a = standing_;
      a[ankle] = angle;
      const SkeletonPose& p = at(a);
      return feet.solePoint(p, toe).z() - feet.solePoint(p, heel).z();
    };
    const bool rising = tilt(high) > tilt(low);
    for (int i = 0; i < 60; ++i) ((tilt(0.5 * (low + high)) > 0.0) == rising ? high : low) = 0.5 * (low + high);
    standing_[ankle] = 0.5 * (low + high);
    // Signs: hip flexion brings the knee forward (+x), knee flexion the ankle back, dorsiflexion the toe up.
    const std::array<Eigen::Vector3d, 3> base = {bonePosition(at(standing_), s + "knee"),
                                                 bonePosition(pose, s + "ankle"), feet.solePoint(pose, toe)};
    for (std::size_t c = 0; c < 3; ++c) {
      JointAngles a = standing_;
      a[sagittal_dof_[side][c]] += 0.1;
      const SkeletonPose& p = at(a);
      const double moved = c == 0   ? bonePosition(p, s + "knee").x() - base[0].x()
                           : c == 1 ? base[1].x() - bonePosition(p, s + "ankle").x()
                                    : feet.solePoint(p, toe).z() - base[2].z();
      if (std::abs(moved) < 1e-4)
        throw LocomotionError("joint " + s + kSagittalJoints[c] + " y does not move its limb forward or back");
      sagittal_sign_[side][c] = moved > 0.0 ? 1.0 : -1.0;
    }
  }
  // Anterior tilt brings the chest forward.
  const double chest = bonePosition(at(standing_), "torso").x();
  kinematics_->compute({Eigen::Vector3d::Zero(), rollPitchYaw(0.0, 0.1, 0.0)}, standing_, pose);
  const double tilted = bonePosition(pose, "torso").x() - chest;
  if (std::abs(tilted) < 1e-4) throw LocomotionError("the root's pitch does not move the torso forward or back");
  tilt_sign_ = tilted > 0.0 ? 1.0 : -1.0;
  const SkeletonPose& p = at(standing_);
  double sole = 0.0;
  for (std::size_t k = 0; k < feet.soles().pointCount(); ++k) sole = std::min(sole, feet.solePoint(p, k).z());
  leg_length_ = bonePosition(p, "l_hip").z() - sole;
  if (!(leg_length_ > 0.3)) throw LocomotionError("the skeleton's legs are " + std::to_string(leg_length_) + " m long");
}

// The walk changed as the normative curves change from the walk's own speed to `dimensionless_speed`.
Motion SpeedGait::gaitAt(const Motion& walk_in_cycles, const NormativeGait& normative,
                         double dimensionless_speed) const {
  Motion m = walk_in_cycles;
  const double own = walk_speed_ / std::sqrt(kGravity * leg_length_);
  for (std::size_t side = 0; side < 2; ++side) {
    // The normative curves start at this side's heel strike; the right's is half a cycle later.
    const double strike = 2.0 * M_PI * (left_heel_strike_ + 0.5 * static_cast<double>(side));
    for (std::size_t c = 0; c < 3; ++c) {
      FourierSeries change = sumOf(normative.curveAt(kSagittalCurves[c], dimensionless_speed),
                                   normative.curveAt(kSagittalCurves[c], own), -1.0);
      change.phase = -strike;
      FourierSeries& dof = m.dofs[sagittal_dof_[side][c]];
      dof = sumOf(dof, inCycles(change), sagittal_sign_[side][c]);
    }
  }
  // The pelvis tilts twice a cycle, the same at either heel strike: the left side's curve.
  FourierSeries tilt =
      sumOf(normative.curveAt(kPelvisTiltCurve, dimensionless_speed), normative.curveAt(kPelvisTiltCurve, own), -1.0);
  tilt.phase = -2.0 * M_PI * left_heel_strike_;
  m.root.rotation[kPelvisPitch] = sumOf(m.root.rotation[kPelvisPitch], inCycles(tilt), tilt_sign_);
  return m;
}

double SpeedGait::measuredStride(double speed) {
  PlantedFeet feet(soles_);
  SkeletonPose pose;
  JointAngles angles{};
  Eigen::Quaterniond pelvis;
  double start = 0.0;
  for (int i = 0; i <= 2 * kSamplesPerCycle; ++i) {
    evaluate(static_cast<double>(i) / kSamplesPerCycle, speed, 1.0, angles, pelvis);
    kinematics_->compute({Eigen::Vector3d::Zero(), pelvis}, angles, pose);
    const double x = feet.place(pose, 0.0).x();
    if (i == kSamplesPerCycle) start = x;
    if (i == 2 * kSamplesPerCycle) return x - start;
  }
  return 0.0;
}

double SpeedGait::cycleRate(double speed) const {
  const double v = std::clamp(speed, slowestSpeed(), fastestSpeed());
  std::size_t k = 1;
  while (k + 1 < strides_.size() && strides_[k].first < v) ++k;
  if (strides_.size() == 1) return v / strides_[0].second;
  const double t = (v - strides_[k - 1].first) / (strides_[k].first - strides_[k - 1].first);
  return v / ((1.0 - t) * strides_[k - 1].second + t * strides_[k].second);
}

void SpeedGait::evaluate(double phase, double speed, double walking, JointAngles& angles, Eigen::Quaterniond& pelvis) {
  const double v = std::clamp(speed, slowestSpeed(), fastestSpeed());
  std::size_t k = 1;
  while (k + 1 < knots_.size() && knots_[k].speed < v) ++k;
  const std::size_t before = knots_.size() == 1 ? 0 : k - 1, after = knots_.size() == 1 ? 0 : k;
  const double t = before == after ? 0.0 : (v - knots_[before].speed) / (knots_[after].speed - knots_[before].speed);
  gaits_[before].evaluate(phase, angles, scratch_root_);
  const Eigen::Quaterniond first = scratch_root_.rotation;
  gaits_[after].evaluate(phase, scratch_, scratch_root_);
  const double w = std::clamp(walking, 0.0, 1.0);
  for (std::size_t i = 0; i < kDofCount; ++i) {
    const double walked = (1.0 - t) * angles[i] + t * scratch_[i];
    angles[i] = standing_[i] + w * (walked - standing_[i]);
  }
  pelvis = standing_pelvis_.slerp(w, first.slerp(t, scratch_root_.rotation));
}

}  // namespace dressed_human
