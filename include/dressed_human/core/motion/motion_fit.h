#pragma once
// A sampled (retargeted) capture -> our Motion: period, whole-cycle window, root frame of the walk,
// unwrapped channels, one least-squares Fourier fit per series with its own order.
//
// The walk's frame: x along the average horizontal velocity of the root over the window (from a
// fit of linear term + Fourier series to each horizontal coordinate), z up, origin on that line at
// time 0. The root's forward progression is forward_speed * t plus a periodic sway series; lateral
// and vertical position and roll, pitch, yaw (R = Rz Ry Rx) relative to that frame are periodic.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "dressed_human/core/motion/gait_period.h"
#include "dressed_human/core/motion/mocap_retarget.h"
#include "dressed_human/core/motion/motion.h"

namespace dressed_human {

struct MotionFitOptions {
  double period = 0.0;              // seconds; 0: estimate from the data
  double tolerance_degrees = 0.5;   // RMS residual an angle series must reach
  double tolerance_metres = 0.002;  // the same for root translation series
  std::size_t max_order = 8;        // cap on m
  std::size_t fixed_order = 0;      // > 0: every series gets exactly this m (no tolerance search)
  // Frames dropped at the start. -1: automatic, i.e. the leading frames that jump to the rest of
  // the record by more than 15 degrees and 10x the median frame-to-frame step (CMU BVH
  // conversions start with a bind-pose frame).
  int skip_frames = -1;
  PeriodOptions period_options;
  std::string name = "fitted_motion";
};

struct SeriesFitReport {
  std::size_t order = 0;
  double rms_residual = 0.0;  // radians for angles, metres for translations
  bool is_angle = true;
  bool driven = true;  // false: held at rest by the source (constant 0)
  bool reached_tolerance = true;
};

struct MotionFit {
  Motion motion;
  std::array<SeriesFitReport, Motion::kSeriesCount> reports;
  std::size_t skipped_frames = 0;  // at the start of the record; times count from the next
  bool period_estimated = false;
  PeriodEstimate period_estimate;  // filled when estimated
  std::size_t cycles = 0;
  std::size_t frames_used = 0;                                  // the window: frames 0 .. frames_used-1, whole cycles
  std::size_t max_order_allowed = 0;                            // the cap after the sampling limit (samples per cycle)
  Eigen::Matrix3d walk_rotation = Eigen::Matrix3d::Identity();  // walk frame in the capture world
  Eigen::Vector3d walk_origin = Eigen::Vector3d::Zero();
  // The fitted data over the window, in Motion::series order: unwrapped angles (radians) and
  // root translation in the walk frame (x with the forward progression: it is fitted with the
  // linear term).
  std::vector<double> times;
  std::array<std::vector<double>, Motion::kSeriesCount> samples;
};

// Throws MotionError: non-finite samples, non-uniform frame times when the period is estimated,
// no clear period, fewer frames than one cycle or than 8 per cycle, a fixed order above the
// sampling limit.
MotionFit fitMotion(const SampledMotion& sampled, const MotionFitOptions& options);

// The automatic choice of MotionFitOptions::skip_frames.
std::size_t countLeadingOutlierFrames(const SampledMotion& sampled);

// The same samples, period, window and walk frame as `fit`, every driven series refitted with
// exactly `order` harmonics: for order sweeps.
MotionFit refitWithOrder(const MotionFit& fit, std::size_t order);

}  // namespace dressed_human
