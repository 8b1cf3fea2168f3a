#pragma once
// A walk whose stride, cadence and joint curves follow the walking speed. The fitted walk (a
// Motion), its two sides made one (symmetricWalk), is the gait at its own speed; at another speed
// its sagittal hip, knee and ankle curves and its pelvis's tilt change as the normative curves
// change between the two speeds (Schwartz et al. 2008, scaled by leg length, Hof 1996),
// phase-aligned at heel strike. Gaits are built at the normative classes' speeds and mixed
// linearly in between (linear in the Fourier coefficients, as Unuma et al. 1995 mix styles, so
// mixing the evaluated angles is the same). The cycle rate at each speed is the speed over the
// stride the legs actually make with planted feet, so that travel comes from the feet and matches
// the commanded speed.

#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "dressed_human/core/locomotion/normative_gait.h"
#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/skeleton/foot_sole.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"

namespace dressed_human {

// `walk` with every series in cycles (period 1), the root's travel taken out (the feet decide
// it). Throws LocomotionError for a series whose period is not the motion's.
Motion walkInCycles(const Motion& walk);

class SpeedGait {
 public:
  // Throws LocomotionError when `walk` is not a walk (no forward speed, series of another period).
  // `soles`: where the feet meet the ground (the drawn foot's, FootSoles), planted by the walker too.
  SpeedGait(const Motion& walk, const NormativeGait& normative, const Skeleton& skeleton, const BodyShape& shape,
            FootSoles soles);

  // The pose at cycle `phase` (cycles; the walk's own time / period) walking at `speed` m/s
  // (clamped to the knots' range), mixed with standing by `walking` in [0, 1].
  // Allocation-free; not thread-safe.
  void evaluate(double phase, double speed, double walking, JointAngles& angles, Eigen::Quaterniond& pelvis);

  struct Knot {
    double speed;                 // m/s
    double stride;                // m per cycle with planted feet (PlantedFeet), measured
    double cycle_rate;            // cycles per second: speed / stride
    double normative_stride;      // m, the class's dimensionless stride times the leg length
    double normative_cadence;     // steps per second
    double normative_stride_sd;   // m, between the class's subjects (0: the table does not say)
    double normative_cadence_sd;  // steps per second
  };
  const std::vector<Knot>& knots() const { return knots_; }
  // Gait cycles per second at `speed` (>= the slowest knot: the legs' range shrinks below it).
  double cycleRate(double speed) const;
  double slowestSpeed() const { return knots_.front().speed; }
  double fastestSpeed() const { return knots_.back().speed; }
  double legLength() const { return leg_length_; }             // hip joint to the ground, standing
  double walkSpeed() const { return walk_speed_; }             // the fitted walk's own
  double leftHeelStrike() const { return left_heel_strike_; }  // cycles
  const JointAngles& standing() const { return standing_; }
  const FootSoles& soles() const { return soles_; }

 private:
  void measureLeg(const Skeleton& skeleton);
  Motion gaitAt(const Motion& walk_in_cycles, const NormativeGait& normative, double dimensionless_speed) const;
  double measuredStride(double speed);  // m per cycle, planted feet

  std::shared_ptr<const ForwardKinematics> kinematics_;  // shared by copies
  FootSoles soles_;
  std::vector<MotionEvaluator> gaits_;  // one per knot
  std::vector<Knot> knots_;
  std::vector<std::pair<double, double>> strides_;  // (speed, measured stride), finer than the knots
  // Per side (left, right) the angle index of each kSagittalCurves DOF and the sign that turns
  // the normative (Plug-in-Gait) angle into ours, found by moving the joint.
  std::array<std::array<std::size_t, 3>, 2> sagittal_dof_{};
  std::array<std::array<double, 3>, 2> sagittal_sign_{};
  double tilt_sign_ = 1.0;  // turns the normative (anterior +) pelvis tilt into our root's pitch
  JointAngles standing_{};
  Eigen::Quaterniond standing_pelvis_ = Eigen::Quaterniond::Identity();
  double leg_length_ = 0.0;
  double walk_speed_ = 0.0;
  double left_heel_strike_ = 0.0;
  JointAngles scratch_{};
  RigidTransform scratch_root_;
};

}  // namespace dressed_human
