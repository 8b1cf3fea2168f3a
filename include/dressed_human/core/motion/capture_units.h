#pragma once
// The length unit of a motion capture. BVH files carry no unit: CMU's conversions are in ASF
// units (1/0.45 inch), others in centimetres, metres or inches. The unit is taken from the rest
// pose's stature (the one that makes it a human height), or named by the user.

#include <string>

#include "dressed_human/core/motion/bvh_file.h"

namespace dressed_human {

struct CaptureUnits {
  double metres_per_unit = 1.0;
  std::string name;    // "m", "cm", "mm", "in", "cmu" or the number given
  std::string reason;  // how it was chosen, for the user: "given", or the stature it implies
};

// The names unitsByName() knows, for messages: "m, cm, mm, in, cmu (ASF units: 1/0.45 in)".
std::string knownUnitNames();
// "m", "cm", "mm", "in", "cmu", or a positive number of metres per unit. Throws MotionError
// naming the accepted forms.
CaptureUnits unitsByName(const std::string& name);

// The BVH rest pose's stature (lowest to highest joint or end site along Y, the BVH up axis) in
// file units.
double bvhRestStature(const BvhClip& clip);
// The known unit that puts the rest stature in [1.0, 2.3] m, nearest 1.7 m. Throws MotionError
// for a rest pose with no height (all offsets zero) or a stature that is no human height in any
// known unit, saying what it found and that --units names the unit.
CaptureUnits detectBvhUnits(const BvhClip& clip, const std::string& source_name);

}  // namespace dressed_human
