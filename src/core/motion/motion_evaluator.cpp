#include "dressed_human/core/motion/motion_evaluator.h"

#include <cmath>

namespace dressed_human {

MotionEvaluator::MotionEvaluator(const Motion& motion) : motion_(motion) {
  motion_.validate();
  for (std::size_t i = 0; i < Motion::kSeriesCount; ++i) {
    const FourierSeries& s = motion_.series(i);
    std::size_t clock = 0;
    while (clock < clocks_.size() && !(clocks_[clock].period == s.period && clocks_[clock].phase == s.phase)) ++clock;
    if (clock == clocks_.size()) clocks_.push_back({s.period, s.phase, 0, 0});
    clocks_[clock].order = std::max(clocks_[clock].order, s.order());
    series_.push_back({clock, s.order(), a_.size(), 0.5 * s.a0});
    a_.insert(a_.end(), s.a.begin(), s.a.end());
    b_.insert(b_.end(), s.b.begin(), s.b.end());
  }
  std::size_t table_size = 0;
  for (Clock& clock : clocks_) {
    clock.table = table_size;
    table_size += clock.order;
  }
  cos_.assign(table_size, 0.0);
  sin_.assign(table_size, 0.0);
  values_.assign(Motion::kSeriesCount, 0.0);
  derivatives_.assign(Motion::kSeriesCount, 0.0);
}

void MotionEvaluator::evaluate(double time, JointAngles& angles, RigidTransform& root, JointAngles* velocities) {
  for (const Clock& clock : clocks_) {
    if (clock.order == 0) continue;
    // Reduce to one cycle first (fmod is exact) so that long runs keep full precision in the phase.
    double cycle_time = std::fmod(time, clock.period);
    if (cycle_time < 0.0) cycle_time += clock.period;
    const double t = 2.0 * M_PI * cycle_time / clock.period + clock.phase;
    double s1 = 0.0;
    double c1 = 0.0;
    ::sincos(t, &s1, &c1);
    double* cn = &cos_[clock.table];
    double* sn = &sin_[clock.table];
    cn[0] = c1;
    sn[0] = s1;
    for (std::size_t n = 1; n < clock.order; ++n) {
      cn[n] = cn[n - 1] * c1 - sn[n - 1] * s1;
      sn[n] = sn[n - 1] * c1 + cn[n - 1] * s1;
    }
  }
  const bool want_derivatives = velocities != nullptr;
  for (std::size_t i = 0; i < series_.size(); ++i) {
    const Series& s = series_[i];
    const Clock& clock = clocks_[s.clock];
    const double* a = &a_[s.coefficients];
    const double* b = &b_[s.coefficients];
    const double* cn = cos_.data() + clock.table;
    const double* sn = sin_.data() + clock.table;
    double value = s.half_a0;
    for (std::size_t n = 0; n < s.order; ++n) value += a[n] * cn[n] + b[n] * sn[n];
    values_[i] = value;
    if (want_derivatives) {
      double derivative = 0.0;
      for (std::size_t n = 0; n < s.order; ++n) {
        derivative += static_cast<double>(n + 1) * (b[n] * cn[n] - a[n] * sn[n]);
      }
      derivatives_[i] = derivative * (2.0 * M_PI) / clock.period;
    }
  }
  for (std::size_t i = 0; i < kDofCount; ++i) angles[i] = values_[i];
  if (want_derivatives) {
    for (std::size_t i = 0; i < kDofCount; ++i) (*velocities)[i] = derivatives_[i];
  }
  const double* translation = &values_[kDofCount];
  const double* rotation = &values_[kDofCount + 3];
  root.translation = {motion_.root.forward_speed * time + translation[0], translation[1], translation[2]};
  root.rotation = Eigen::AngleAxisd(rotation[2], Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(rotation[1], Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(rotation[0], Eigen::Vector3d::UnitX());
}

}  // namespace dressed_human
