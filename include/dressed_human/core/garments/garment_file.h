// Garment files (YAML, config/garments/*.yaml). Layout:
//
//   name: skirt
//   type: skirt                 # jacket | skirt | pants | one_piece
//   colour: [0.7, 0.2, 0.3]     # RGB in [0, 1]
//   ease: 0.015                 # metres added to every ring's radii, >= 0
//   rows:                       # shape rows top to bottom: jacket 6, skirt/pants 3, one_piece 7
//     - {frame: waist, centre: [0.0, 0.0, 0.10], radius: [0.12, 0.16]}
//   sleeve:                     # jacket (required) / one_piece (optional): 4 left-arm rows
//     - {frame: l_shoulder, centre: [0.0, 0.0, 0.0], radius: [0.06, 0.06]}
//   legs:                       # skirt, pants, one_piece
//     length: 0.5               # c in [0, 1]; or "knee" for c_k
//     rows: [0.333, 0.667]      # optional: the inner control rows at these fractions of c;
//                               # pants: 4 (thigh row 2, shank row 2; garment.h)
//     top:  {frame: l_hip,  centre: [...], radius: [...]}   # P^0 ring
//     knee: {frame: l_hip,  centre: [...], radius: [...]}   # P^i ring
//     long: {frame: l_knee, centre: [...], radius: [...]}   # Q^j ring; frame: child of knee's
//   crotch: {frame: body, point: [0.0, 0.0, -0.12],       # pants only (garment.h: the crotch)
//            radius: [0.17, 0.01],                        # optional: twist ring of the hips patches
//            leg_radius: [0.17, 0.01]}                    # optional: of the leg patches (default: radius)
//
// Every error names the file, line and column, and the key path, e.g.
//   skirt.yaml:7:34: rows[2].radius[1]: must be > 0, got -0.1
#pragma once

#include "dressed_human/core/garments/garment_description.h"
#include "dressed_human/core/skeleton/skeleton.h"

#include <string>

namespace dressed_human {

GarmentDescription loadGarmentFile(const std::string& path, const Skeleton& skeleton);
GarmentDescription parseGarmentYaml(const std::string& yaml_text, const Skeleton& skeleton,
                                    const std::string& source_name = "<garment yaml>");

}  // namespace dressed_human
