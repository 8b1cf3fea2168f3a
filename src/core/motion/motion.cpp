#include "dressed_human/core/motion/motion.h"

#include <cmath>
#include <sstream>
#include <string>

namespace dressed_human {
namespace {

double phaseAngle(const FourierSeries& s, double time) { return 2.0 * M_PI * time / s.period + s.phase; }

}  // namespace

double FourierSeries::valueBySummation(double time) const {
  const double t = phaseAngle(*this, time);
  double value = 0.5 * a0;
  for (std::size_t n = 1; n <= order(); ++n) {
    value += a[n - 1] * std::cos(static_cast<double>(n) * t) + b[n - 1] * std::sin(static_cast<double>(n) * t);
  }
  return value;
}

double FourierSeries::derivativeBySummation(double time) const {
  const double t = phaseAngle(*this, time);
  double value = 0.0;
  for (std::size_t n = 1; n <= order(); ++n) {
    const double k = static_cast<double>(n);
    value += k * (-a[n - 1] * std::sin(k * t) + b[n - 1] * std::cos(k * t));
  }
  return value * (2.0 * M_PI) / period;
}

const std::array<const char*, kJointCount>& humanJointNames() {
  static const std::array<const char*, kJointCount> names = {
      "waist",   "torso",   "neck",  "head",   "l_shoulder", "l_elbow", "l_wrist", "r_shoulder",
      "r_elbow", "r_wrist", "l_hip", "l_knee", "l_ankle",    "r_hip",   "r_knee",  "r_ankle"};
  return names;
}

const FourierSeries& Motion::series(std::size_t index) const {
  if (index < kDofCount) return dofs[index];
  if (index < kDofCount + 3) return root.translation[index - kDofCount];
  return root.rotation.at(index - kDofCount - 3);
}

std::string Motion::seriesName(std::size_t index) const {
  if (index < kDofCount) {
    return std::string(humanJointNames()[index / kDofsPerJoint]) + "." + kDofNames[index % kDofsPerJoint];
  }
  if (index < kDofCount + 3) return std::string("root.translation.") + kRootTranslationNames[index - kDofCount];
  return std::string("root.rotation.") + kRootRotationNames.at(index - kDofCount - 3);
}

namespace {

std::string formatted(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

void requireWithin(double value, double low, double high, const std::string& what, const std::string& unit) {
  if (!(value >= low && value <= high)) {
    throw MotionError(what + " " + formatted(value) + unit + " is outside [" + formatted(low) + ", " + formatted(high) +
                      "]" + unit);
  }
}

// The largest |value| the series can take (Eq. 1 with a0 / 2).
double amplitudeBound(const FourierSeries& s) {
  double bound = 0.5 * std::abs(s.a0);
  for (std::size_t k = 0; k < s.a.size(); ++k) bound += std::hypot(s.a[k], s.b[k]);
  return bound;
}

}  // namespace

void Motion::validate() const {
  if (!std::isfinite(period)) throw MotionError("motion period must be a finite number, got " + formatted(period));
  requireWithin(period, MotionLimits::kMinPeriod, MotionLimits::kMaxPeriod, "motion period", " s");
  if (!std::isfinite(root.forward_speed)) throw MotionError("root.forward_speed must be finite");
  requireWithin(root.forward_speed, -MotionLimits::kMaxForwardSpeed, MotionLimits::kMaxForwardSpeed,
                "root.forward_speed", " m/s");
  for (std::size_t i = 0; i < kSeriesCount; ++i) {
    const FourierSeries& s = series(i);
    const std::string name = seriesName(i);
    if (!std::isfinite(s.period))
      throw MotionError(name + ": period must be a finite number, got " + formatted(s.period));
    requireWithin(s.period, MotionLimits::kMinPeriod, MotionLimits::kMaxPeriod, name + ": period", " s");
    if (!std::isfinite(s.phase)) throw MotionError(name + ": phase must be finite");
    requireWithin(s.phase, -MotionLimits::kMaxPhase, MotionLimits::kMaxPhase, name + ": phase", " rad");
    if (s.a.size() != s.b.size()) {
      throw MotionError(name + ": " + std::to_string(s.a.size()) + " cosine coefficients but " +
                        std::to_string(s.b.size()) + " sine coefficients; both lists must have the order m");
    }
    if (s.order() > MotionLimits::kMaxOrder) {
      throw MotionError(name + ": order " + std::to_string(s.order()) + " is above " +
                        std::to_string(MotionLimits::kMaxOrder) +
                        " (more harmonics than a gait capture holds; fit_motion picks orders up to 12)");
    }
    bool finite = std::isfinite(s.a0);
    for (double c : s.a) finite = finite && std::isfinite(c);
    for (double c : s.b) finite = finite && std::isfinite(c);
    if (!finite) throw MotionError(name + ": coefficients must be finite numbers");
    const bool translation = i >= kDofCount && i < kDofCount + 3;
    requireWithin(amplitudeBound(s), 0.0, translation ? MotionLimits::kMaxTranslation : MotionLimits::kMaxAngle,
                  name + ": amplitude 0.5 |a0| + sum |(a_k, b_k)| =", translation ? " m" : " rad");
  }
}

}  // namespace dressed_human
