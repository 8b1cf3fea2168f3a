// What a designer writes for one garment (SPEC §3): shape rows per bone, ease, colour, skirt
// length. Read from YAML by garment_file.h; built into patches by garment.h.
#pragma once

#include <Eigen/Core>

#include <stdexcept>
#include <string>
#include <vector>

namespace dressed_human {

struct GarmentError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class GarmentType { kJacket, kSkirt, kPants, kOnePiece };
const char* garmentTypeName(GarmentType type);

// One row of shape points: an ellipse around `centre` in bone frame `frame` (a bone name or
// "body"), semi-axes radius.x toward the body's front and radius.y toward its left (the rest
// pose's directions, projected across the bone), before ease. The row's shape points are the
// off-curve points of the Bezier circle of 4 (trunk, skirt) or 2 (sleeve, trouser leg) arcs.
// A frame "l_..." is a left bone: the row's left half rides on it and the right half on the
// mirrored "r_..." bone (centre and points mirrored y -> -y in the bone frame).
struct GarmentRing {
  std::string frame;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector2d radius = Eigen::Vector2d::Zero();
};

// The part below the hips, across thigh (frame i) and shank (frame j): Eq. 8' rings.
struct GarmentLegs {
  double length = 0.5;   // normalized c in [0, 1]; knee length c_k = d_i / (d_i + d_j)
  bool at_knee = false;  // `length: knee`: c = c_k of the shaped body (overrides `length`)
  // The inner control rows between the hips and the hem sit at these fractions of c, strictly
  // increasing in (0, 1): legRowFractionCount(type) of them (skirt, one_piece: 2, one patch
  // row; pants: 4, two patch rows per leg whose shared ring is the midpoint of rows 2 and 3).
  // Empty: evenly spaced.
  std::vector<double> row_fractions;
  GarmentRing top;       // P^0 ring (thigh frame): the hem of a zero-length skirt
  GarmentRing knee;      // P^i ring (thigh frame): the knee-length hem
  GarmentRing long_hem;  // Q^j ring (shank frame, at rest): the full-length hem
};

struct GarmentDescription {
  std::string name;
  GarmentType type = GarmentType::kSkirt;
  Eigen::Vector3d colour = Eigen::Vector3d(0.6, 0.6, 0.6);  // RGB in [0, 1]
  double ease = 0.0;                                        // metres added to every ring's radii (clearance over skin)
  std::vector<GarmentRing> rows;                            // explicit shape rows, top to bottom (count per type below)
  std::vector<GarmentRing> sleeve;                          // left sleeve rows, shoulder to cuff (4, or none)
  GarmentLegs legs;                                         // skirt, pants, one_piece
  std::string crotch_frame = "body";                        // pants
  Eigen::Vector3d crotch = Eigen::Vector3d(0, 0, -0.12);    // pants: where the legs part
  // pants: semi-axes (toward the front, toward the left) of the crotch's twist ring: the eight
  // shape points around the crotch, in the crotch frame's xy plane (its tangent plane; garment.h).
  // crotch_radius places the 4 twist points of the hips patches, crotch_leg_radius those of the
  // 4 leg patches (their sector angles are 22.5 + 45 k degrees either way).
  Eigen::Vector2d crotch_radius = Eigen::Vector2d(0.17, 0.01);
  Eigen::Vector2d crotch_leg_radius = Eigen::Vector2d(0.17, 0.01);
};

// Shape rows each type needs in `rows` (jacket 6, skirt 3, pants 3, one_piece 7).
std::size_t garmentRowCount(GarmentType type);
// Inner leg control rows (legs.row_fractions) per type: skirt, one_piece 2; pants 4; jacket 0.
std::size_t legRowFractionCount(GarmentType type);

}  // namespace dressed_human
