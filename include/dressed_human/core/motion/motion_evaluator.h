#pragma once
// Fast evaluation of a Motion at a time: one sincos per distinct (period, phase) clock, the
// harmonics by the angle-addition recurrence, then one dot product per series.

#include <cstddef>
#include <vector>

#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/motion/motion.h"

namespace dressed_human {

class MotionEvaluator {
 public:
  explicit MotionEvaluator(const Motion& motion);  // validates the motion

  // Joint angles, the root pose and (optionally) the angular velocities at `time` seconds.
  // Allocation-free; not thread-safe (it reuses its harmonic tables).
  void evaluate(double time, JointAngles& angles, RigidTransform& root, JointAngles* velocities = nullptr);

  const Motion& motion() const { return motion_; }
  std::size_t clockCount() const { return clocks_.size(); }

 private:
  struct Clock {
    double period;
    double phase;
    std::size_t order;  // highest harmonic any series on this clock needs
    std::size_t table;  // offset of harmonic 1 in cos_/sin_
  };
  struct Series {
    std::size_t clock;
    std::size_t order;
    std::size_t coefficients;  // offset of a_1 in a_ / b_
    double half_a0;
  };

  Motion motion_;
  std::vector<Clock> clocks_;
  std::vector<Series> series_;
  std::vector<double> a_, b_, cos_, sin_;
  std::vector<double> values_, derivatives_;
};

}  // namespace dressed_human
