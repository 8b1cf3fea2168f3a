#pragma once
// Periodic motion of the skeleton: one truncated Fourier series per DOF (SPEC Eq. 1) and the
// root's motion (forward progression plus periodic pelvis translation and rotation).

#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dressed_human/core/skeleton/skeleton.h"

namespace dressed_human {

struct MotionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Eq. 1: theta(t) = a0/2 + sum_{n=1..m} (a_n cos nt + b_n sin nt), with the phase
// t = 2*pi*time/period + phase (radians). `a` and `b` hold a_1..a_m and b_1..b_m.
struct FourierSeries {
  double a0 = 0.0;
  std::vector<double> a;
  std::vector<double> b;
  double period = 1.0;  // seconds
  double phase = 0.0;   // radians

  std::size_t order() const { return a.size(); }
  // Term-by-term summation with one cos/sin per harmonic: the reference the fast path is tested
  // against, and a readable statement of Eq. 1.
  double valueBySummation(double time) const;
  double derivativeBySummation(double time) const;  // d theta / d time
};

// Root (the "body" frame) in the frame where the motion starts:
// position = (forward_speed * time + x(t), y(t), z(t)); rotation = Rz(yaw) Ry(pitch) Rx(roll).
struct RootMotion {
  double forward_speed = 0.0;                // m/s along the start frame's x
  std::array<FourierSeries, 3> translation;  // x, y, z  (z includes the pelvis height)
  std::array<FourierSeries, 3> rotation;     // roll, pitch, yaw
};
constexpr std::array<const char*, 3> kRootTranslationNames = {"x", "y", "z"};
constexpr std::array<const char*, 3> kRootRotationNames = {"roll", "pitch", "yaw"};

// Physical ranges of a motion: the gait cycles, angles, speeds and sizes a person has, and the
// orders a sampled capture supports. Beyond them a number is an error in the file, not a motion
// (a period of 1e-300 s is a frequency of 1e300 Hz; a forward speed of 1e300 m/s puts the human
// 3e300 m away after a second).
struct MotionLimits {
  static constexpr double kMinPeriod = 0.1;         // s
  static constexpr double kMaxPeriod = 60.0;        // s
  static constexpr double kMaxForwardSpeed = 12.5;  // m/s, the fastest human sprint
  // Largest |value| a series can reach, 0.5 |a0| + sum_k |(a_k, b_k)|: an angle (joints, root
  // rotation) within a full turn either way, a root translation within 10 m.
  static constexpr double kMaxAngle = 6.283185307179586;  // rad
  static constexpr double kMaxTranslation = 10.0;         // m
  static constexpr double kMaxPhase = 1000.0;             // rad; sin() keeps ~1e-13 there
  // A capture at 120 Hz over a ~1.1 s gait cycle holds 66 harmonics (Nyquist); fits use <= 12.
  static constexpr std::size_t kMaxOrder = 64;
};

struct Motion {
  std::string name;
  double period = 1.0;                        // the cycle, seconds: loops and start phase refer to it
  std::array<FourierSeries, kDofCount> dofs;  // index joint * 3 + dof, joints in skeleton order
  RootMotion root;
  // The captured person's proportions (a fitted motion, body_proportions.h); absent: the motion
  // fits any body. The node requires robot_description to carry them (urdf_body_shape.h).
  std::optional<BodyShape> body_shape;

  // Throws MotionError naming the first series with a non-finite number, different counts of
  // cosine and sine coefficients, or a value outside MotionLimits (the value and the range).
  void validate() const;
  // Every series, DOFs first then root translation x,y,z and rotation roll,pitch,yaw, with a name
  // such as "l_knee.y" or "root.translation.z": for messages and tools.
  std::string seriesName(std::size_t index) const;
  const FourierSeries& series(std::size_t index) const;
  static constexpr std::size_t kSeriesCount = kDofCount + 6;
};

// The 16 joint names, in skeleton order ("waist", ..., "r_ankle").
const std::array<const char*, kJointCount>& humanJointNames();

}  // namespace dressed_human
