#pragma once
// Normative joint curves at several walking speeds (config/gait/speed_gaits.yaml, written by
// scripts/gait_speed_table.py from Schwartz et al. 2008): per speed class its dimensionless
// speed, cadence and stride (Hof 1996: v / sqrt(g L), steps/s * sqrt(L / g), stride / L) and
// Fourier series of the sagittal hip, knee and ankle angles and the pelvis's tilt over one cycle
// from heel strike.

#include <array>
#include <map>
#include <string>
#include <vector>

#include "dressed_human/core/locomotion/route.h"
#include "dressed_human/core/motion/motion.h"

namespace dressed_human {

// The curves the speed-dependent gait uses, Plug-in-Gait signs (+ flexion, + dorsiflexion).
constexpr std::array<const char*, 3> kSagittalCurves = {"hip_flexion", "knee_flexion", "ankle_dorsiflexion"};
// The pelvis's tilt (+ anterior) against the walking direction: the hip angles are measured from
// the pelvis, so without its change the thighs lean as the slower gait's do.
constexpr const char* kPelvisTiltCurve = "pelvis_tilt";

struct NormativeGaitClass {
  std::string name;
  double speed = 0.0;    // dimensionless
  double cadence = 0.0;  // dimensionless, steps (not strides)
  double stride = 0.0;   // dimensionless, two steps
  // Standard deviations between the class's subjects (0: the table does not say).
  double cadence_sd = 0.0;
  double stride_sd = 0.0;
  // kSagittalCurves and kPelvisTiltCurve: radians; period 1 (one cycle), phase 0 at this side's
  // heel strike.
  std::map<std::string, FourierSeries> curves;
};

struct NormativeGait {
  std::vector<NormativeGaitClass> classes;  // by increasing speed

  // A curve at dimensionless `speed`, linear in the coefficients between the two classes around
  // it, the end class beyond them.
  FourierSeries curveAt(const std::string& curve, double speed) const;
};

// Throws LocomotionError "source:line:col: key: message" for a malformed table: no classes,
// speeds not increasing, a missing curve, a non-finite or out-of-range number.
NormativeGait parseNormativeGaitYaml(const std::string& yaml_text, const std::string& source_name);
NormativeGait loadNormativeGaitFile(const std::string& path);

// The same function of time in cycles: period 1, phase 0 (coefficients rotated by the series'
// phase). Time in cycles is time / period.
FourierSeries inCycles(const FourierSeries& series);
// a + weight b, term by term (both in cycles).
FourierSeries sumOf(const FourierSeries& a, const FourierSeries& b, double weight = 1.0);
// (1 - t) a + t b (both in cycles).
FourierSeries mixOf(const FourierSeries& a, const FourierSeries& b, double t);

}  // namespace dressed_human
