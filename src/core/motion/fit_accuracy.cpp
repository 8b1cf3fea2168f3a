#include "dressed_human/core/motion/fit_accuracy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/skeleton/foot_sole.h"

namespace dressed_human {
namespace {

class ErrorAccumulator {
 public:
  void add(const Eigen::Vector3d& a, const Eigen::Vector3d& b, std::size_t frame = 0, int joint = -1) {
    const double cm = 100.0 * (a - b).norm();
    sum_ += cm;
    sum_squares_ += cm * cm;
    if (result_.samples == 0 || cm > result_.max_cm) {
      result_.max_cm = cm;
      result_.worst_frame = frame;
      result_.worst_joint = joint;
    }
    ++result_.samples;
  }
  PositionError result() const {
    PositionError r = result_;
    if (r.samples > 0) {
      r.mean_cm = sum_ / static_cast<double>(r.samples);
      r.rms_cm = std::sqrt(sum_squares_ / static_cast<double>(r.samples));
    }
    return r;
  }

 private:
  PositionError result_;
  double sum_ = 0.0;
  double sum_squares_ = 0.0;
};

Eigen::Quaterniond rotationFromRollPitchYaw(double roll, double pitch, double yaw) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()));
}

// Our lowest sole point (FootSoles: where our foot meets the floor) above the capture's lowest
// foot point, for each foot the capture has in stance in this frame.
void addStanceFeet(const ForwardKinematics& kinematics, const FootSoles& soles, const RigidTransform& root,
                   const JointAngles& angles, const std::array<double, 2>& capture_lowest,
                   const std::array<double, 2>& lowest_in_window, SkeletonPose& pose, std::vector<double>& above) {
  kinematics.compute(root, angles, pose);
  for (std::size_t side = 0; side < 2; ++side) {
    if (capture_lowest[side] > lowest_in_window[side] + FitAccuracy::kStanceBand) continue;
    above.push_back(soles.lowest(pose, side) - capture_lowest[side]);
  }
}

// `positions` at `time` within [0, times.back()], linear between the neighbouring frames.
Eigen::Vector3d positionAt(const std::vector<double>& times, const std::vector<JointPositions>& positions,
                           std::size_t joint, double time) {
  const auto after = std::upper_bound(times.begin(), times.end(), time);
  if (after == times.begin()) return positions.front()[joint];
  if (after == times.end()) return positions.back()[joint];
  const auto next = static_cast<std::size_t>(after - times.begin());
  const double t0 = times[next - 1], t1 = times[next];
  const double w = t1 > t0 ? (time - t0) / (t1 - t0) : 0.0;
  return (1.0 - w) * positions[next - 1][joint] + w * positions[next][joint];
}

// How far our sole strays from one floor while the capture stands: its height above the capture's
// lowest point, less the median of that (the capture's lowest point is a joint or a marker, some
// centimetres above its own sole).
PositionError strayFromTheFloor(std::vector<double> above) {
  ErrorAccumulator stray;
  if (above.empty()) return stray.result();
  std::vector<double> sorted = above;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double floor = sorted[sorted.size() / 2];
  for (const double a : above) stray.add(Eigen::Vector3d(0, 0, a - floor), Eigen::Vector3d::Zero());
  return stray.result();
}

}  // namespace

PositionError periodicCycleVariation(const std::vector<double>& times, const std::vector<JointPositions>& positions,
                                     double period, std::size_t cycles, const std::array<bool, kJointCount>& used) {
  ErrorAccumulator variation;
  if (cycles < 2 || !(period > 0.0) || times.size() != positions.size()) return variation.result();
  const double end = static_cast<double>(cycles) * period;
  for (std::size_t f = 0; f < times.size() && times[f] < end; ++f) {
    const double phase_time = std::fmod(times[f], period);
    for (std::size_t j = 0; j < kJointCount; ++j) {
      if (!used[j]) continue;
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (std::size_t c = 0; c < cycles; ++c) {
        mean += positionAt(times, positions, j, phase_time + static_cast<double>(c) * period);
      }
      variation.add(positions[f][j], mean / static_cast<double>(cycles), f, static_cast<int>(j));
    }
  }
  return variation.result();
}

FitAccuracy measureFitAccuracy(const Skeleton& skeleton, const SampledMotion& sampled, const MotionFit& fit,
                               const Motion& motion) {
  const ForwardKinematics kinematics(skeleton, sampled.proportions.shape);
  const FootSoles soles = sampled.soles(skeleton);
  MotionEvaluator evaluator(motion);
  ErrorAccumulator capture;
  std::array<ErrorAccumulator, kJointCount> joint_capture;
  ErrorAccumulator unsmoothed_capture;
  ErrorAccumulator samples;
  ErrorAccumulator root;
  const std::size_t first = fit.skipped_frames;  // the window starts after the skipped frames
  const bool has_capture = sampled.reference_joint_positions.size() >= first + fit.frames_used;
  std::vector<double> feet;
  const bool has_feet = sampled.body_fitted && sampled.reference_lowest_foot.size() >= first + fit.frames_used;
  std::array<double, 2> lowest_in_window = {std::numeric_limits<double>::infinity(),
                                            std::numeric_limits<double>::infinity()};
  for (std::size_t f = 0; has_feet && f < fit.frames_used; ++f) {
    for (std::size_t side = 0; side < 2; ++side) {
      lowest_in_window[side] = std::min(lowest_in_window[side], sampled.reference_lowest_foot[first + f][side]);
    }
  }
  const Eigen::Matrix3d to_walk = fit.walk_rotation.transpose();
  SkeletonPose fitted_pose;
  SkeletonPose sampled_pose;
  for (std::size_t f = 0; f < fit.frames_used; ++f) {
    const double time = fit.times[f];
    JointAngles fitted_angles{};
    RigidTransform fitted_root;
    evaluator.evaluate(time, fitted_angles, fitted_root);
    const Eigen::Vector3d sampled_root(fit.samples[kDofCount][f], fit.samples[kDofCount + 1][f],
                                       fit.samples[kDofCount + 2][f]);
    root.add(fitted_root.translation, sampled_root);
    if (has_feet)
      addStanceFeet(kinematics, soles, fitted_root, fitted_angles, sampled.reference_lowest_foot[first + f],
                    lowest_in_window, fitted_pose, feet);
    fitted_root.translation.setZero();

    JointAngles sampled_angles{};
    for (std::size_t i = 0; i < kDofCount; ++i) sampled_angles[i] = fit.samples[i][f];
    RigidTransform sampled_root_pose;
    sampled_root_pose.rotation = rotationFromRollPitchYaw(fit.samples[kDofCount + 3][f], fit.samples[kDofCount + 4][f],
                                                          fit.samples[kDofCount + 5][f]);
    kinematics.compute(fitted_root, fitted_angles, fitted_pose);
    kinematics.compute(sampled_root_pose, sampled_angles, sampled_pose);
    for (std::size_t j = 0; j < kJointCount; ++j) {
      if (!sampled.driven[j]) continue;
      const auto bone = static_cast<std::size_t>(skeleton.joint(j).bone);
      const Eigen::Vector3d& ours = fitted_pose.bone_in_world[bone].translation;
      const int joint = static_cast<int>(j);
      samples.add(ours, sampled_pose.bone_in_world[bone].translation, f, joint);
      if (has_capture) {
        const Eigen::Vector3d reference = to_walk * sampled.reference_joint_positions[first + f][j];
        capture.add(ours, reference, f, joint);
        joint_capture[j].add(ours, reference, f, joint);
        unsmoothed_capture.add(sampled_pose.bone_in_world[bone].translation, reference, f, joint);
      }
    }
  }
  FitAccuracy accuracy;
  if (has_capture) {
    std::vector<JointPositions> window(fit.frames_used);
    for (std::size_t f = 0; f < fit.frames_used; ++f) {
      for (std::size_t j = 0; j < kJointCount; ++j)
        window[f][j] = to_walk * sampled.reference_joint_positions[first + f][j];
    }
    accuracy.capture_cycle_variation =
        periodicCycleVariation(fit.times, window, motion.period, fit.cycles, sampled.driven);
  }
  accuracy.against_capture = capture.result();
  for (std::size_t j = 0; j < kJointCount; ++j) accuracy.joint_against_capture[j] = joint_capture[j].result();
  accuracy.unsmoothed_against_capture = unsmoothed_capture.result();
  accuracy.against_samples = samples.result();
  accuracy.root_translation = root.result();
  accuracy.stance_foot_height = strayFromTheFloor(std::move(feet));
  std::size_t driven = 0;
  for (std::size_t i = 0; i < Motion::kSeriesCount; ++i) {
    const SeriesFitReport& report = fit.reports[i];
    if (!report.is_angle || !report.driven) continue;
    // The residual of `motion`, which may differ from the fit's own reports (a refit).
    const FourierSeries& series = motion.series(i);
    double squares = 0.0;
    for (std::size_t f = 0; f < fit.frames_used; ++f) {
      const double residual = series.valueBySummation(fit.times[f]) - fit.samples[i][f];
      squares += residual * residual;
    }
    const double rms_degrees = std::sqrt(squares / static_cast<double>(fit.frames_used)) * 180.0 / M_PI;
    accuracy.mean_rms_degrees += rms_degrees;
    accuracy.max_rms_degrees = std::max(accuracy.max_rms_degrees, rms_degrees);
    ++driven;
  }
  if (driven > 0) accuracy.mean_rms_degrees /= static_cast<double>(driven);
  return accuracy;
}

}  // namespace dressed_human
