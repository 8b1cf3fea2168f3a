#pragma once
// Two-bone leg inverse kinematics on a Fourier pose: moves a foot by a small world shift, keeping
// its orientation, by bending the knee (law of cosines) and swinging the thigh about the hip; the
// ankle takes back the foot's orientation. Used to hold the second foot in double support where
// it touched down (PlantedFeet moves the body with the first), and to turn a leg at the hip so
// that a foot on the ground keeps its direction while the body turns.

#include <array>

#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace dressed_human {

class LegIk {
 public:
  explicit LegIk(const ForwardKinematics& kinematics);  // keeps a reference

  // Moves foot `side` (0 left, 1 right) of `pose` by `shift` (world) and updates `angles` and
  // `pose` to match. A target out of the leg's reach is approached as far as the knee allows.
  void shiftFoot(std::size_t side, const Eigen::Vector3d& shift, JointAngles& angles, SkeletonPose& pose) const;
  // Turns leg `side` of `pose` rigidly by `angle` (rad, counter-clockwise seen from its hip) about
  // the line from the hip to `pivot` (a point of its foot, world): the hip and the pivot stay where
  // they are, and the foot turns about the pivot. Updates `angles` and `pose`.
  void turnLeg(std::size_t side, double angle, const Eigen::Vector3d& pivot, JointAngles& angles,
               SkeletonPose& pose) const;

 private:
  // The joint angles (y, x, z) that give `bone` the world rotation `wanted` in `pose`.
  void setJointRotation(std::size_t bone, const Eigen::Quaterniond& wanted, JointAngles& angles,
                        const SkeletonPose& pose) const;

  const ForwardKinematics& kinematics_;
  std::array<std::array<std::size_t, 3>, 2> bones_{};  // thigh, shank, foot per side
};

}  // namespace dressed_human
