#pragma once
// Motion files (YAML). Layout:
//
//   name: walk                      # optional
//   period: 1.1                     # seconds per cycle, > 0
//   joints:                         # all 16 joints, each with its three DOFs y, x, z (radians)
//     l_knee:
//       y: {a0: 0.6, a: [0.3, 0.05], b: [0.1, 0.0]}   # Eq. 1; a and b both of length m (may be 0)
//       x: {a0: 0.0}                                  # m = 0: a constant a0/2
//       z: {a0: 0.0, period: 2.2, phase: 0.5}         # optional own period (s) and phase (rad)
//   root:
//     forward_speed: 1.2            # m/s
//     translation: {x: {...}, y: {...}, z: {...}}     # metres, Eq. 1 series each
//     rotation: {roll: {...}, pitch: {...}, yaw: {...}}  # radians
//   body_shape:                     # optional: the captured person's proportions (fit_motion)
//     l_hip: [0.93, 0.93, 1.02]       # Eq. 5 [a, b, c] per bone or group, as a body file's shape
//     l_pelvis: [0.93, 0.93, 1.02, 0.035, 0.001, 0.010]  # and the joint's offset (m), if any
//
// A series may also carry `rms_residual` (radians or metres, from a fit): kept, not used.
// Every error names the file, the line and column, and the key path, e.g.
//   walk.yaml:12:7: joints.l_hip.y.a[2]: expected a finite number, got '.nan'

#include <map>
#include <ostream>
#include <string>

#include "dressed_human/core/motion/motion.h"

namespace dressed_human {

Motion loadMotionFile(const std::string& path);
// `source_name` stands for the file name in messages.
Motion parseMotionYaml(const std::string& yaml_text, const std::string& source_name);

// Writes a motion in the layout above; `notes` (series name -> text) become comments after
// each series, e.g. a fit's order and residual; `rms_residuals` (series name -> value) are
// written as each series' rms_residual key.
void writeMotionYaml(const Motion& motion, std::ostream& out, const std::string& header_comment = "",
                     const std::map<std::string, std::string>& notes = {},
                     const std::map<std::string, double>& rms_residuals = {});

}  // namespace dressed_human
