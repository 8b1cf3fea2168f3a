#pragma once
// How far the Fourier-driven skeleton strays from the capture, in centimetres of joint position:
// the error users see, where degrees are abstract.
//
// Positions are taken relative to the root (pelvis) position, in the walk frame, frame by frame
// over the fit window; the root's own translation error is reported separately. For each driven
// joint, the position of our bone's proximal joint is compared with
//  - the capture skeleton's own forward kinematics scaled to our stature ("against the capture":
//    includes the difference of bone proportions between the two skeletons; with a fitted body,
//    our skeleton has the capture's proportions and the capture is in its own metres), and
//  - our skeleton driven by the unsmoothed retargeted angles ("against the samples": the error
//    that the truncated series alone adds).

#include "dressed_human/core/motion/mocap_retarget.h"
#include "dressed_human/core/motion/motion.h"
#include "dressed_human/core/motion/motion_fit.h"
#include "dressed_human/core/skeleton/skeleton.h"

namespace dressed_human {

struct PositionError {
  double mean_cm = 0.0;  // over joints and frames
  double rms_cm = 0.0;
  double max_cm = 0.0;
  std::size_t samples = 0;
  // Where max_cm was: the frame of the fitted window (fit.times' index) and our joint (-1: none).
  std::size_t worst_frame = 0;
  int worst_joint = -1;
};

struct FitAccuracy {
  PositionError against_capture;                                 // empty (samples = 0) without a capture skeleton
  std::array<PositionError, kJointCount> joint_against_capture;  // the same per joint
  // Our skeleton on the unsmoothed retargeted angles vs the capture: the floor that the two
  // skeletons' different bone proportions set, whatever the order.
  PositionError unsmoothed_against_capture;
  PositionError against_samples;
  // The capture against itself: each joint against the mean of its cycles at the same phase
  // (periodicCycleVariation). No periodic motion, of any order, follows a capture closer than
  // that on average; empty with one cycle or without a capture skeleton.
  PositionError capture_cycle_variation;
  PositionError root_translation;  // fitted root vs sampled root, walk frame
  // With a fitted body (SampledMotion::body_fitted): how far our lowest sole point (FootSoles)
  // strays from one floor while the capture stands (its lowest foot point within kStanceBand of its
  // lowest in the window), both feet: its height above the capture's lowest point less the median
  // of that height (the capture's lowest point is a joint or a marker, above its own sole).
  PositionError stance_foot_height;
  static constexpr double kStanceBand = 0.02;  // m
  double mean_rms_degrees = 0.0;               // over driven angle series
  double max_rms_degrees = 0.0;
};

// Each joint position against the mean of its positions at the same phase in every cycle of the
// window: `positions[f][j]` at `times[f]` (increasing, from 0), cycles of `period` seconds
// (`cycles` >= 2; times at or beyond cycles * period are not used), linear between frames. The
// cycle-to-cycle variation of a capture, which a periodic fit cannot follow. Joints with
// `used[j]` false are left out.
PositionError periodicCycleVariation(const std::vector<double>& times, const std::vector<JointPositions>& positions,
                                     double period, std::size_t cycles, const std::array<bool, kJointCount>& used);

// `motion` is evaluated at the window's times (it may be a refit of `fit` with another order).
FitAccuracy measureFitAccuracy(const Skeleton& skeleton, const SampledMotion& sampled, const MotionFit& fit,
                               const Motion& motion);

}  // namespace dressed_human
