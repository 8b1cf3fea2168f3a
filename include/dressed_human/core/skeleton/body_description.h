// The body description: the skin's cross-sections per bone and the Eq. 5 body shape, read from
// YAML (config/bodies/default.yaml is the default adult). See that file for the format.
#pragma once

#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/skeleton/skeleton.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace dressed_human {

struct BodyDescriptionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A cross-section on the skin surface: an ellipse with semi-axes radius_x (along the bone
// frame's x) and radius_y (along y), at height z on the bone (bone frame, metres, at rest).
struct SkinSection {
  double z = 0.0;
  double radius_x = 0.0;
  double radius_y = 0.0;
};

struct SkinSegmentSpec {
  std::string bone;     // a bone name of the skeleton, or "body" (the root frame)
  int bone_index = -1;  // -1 for "body"
  // Joined: this segment's first section (z = 0, at its proximal joint) is also the end of its
  // parent bone's segment, which then has no distal cap. Otherwise the proximal end is closed.
  bool joined_to_parent = false;
  double proximal_cap = 0.0;          // dome height beyond the first section (> 0 unless joined)
  double distal_cap = 0.0;            // dome height beyond the last section (> 0 unless a child joins)
  std::vector<SkinSection> sections;  // >= 2, z strictly increasing
};

struct BodyDescription {
  std::string name;
  std::vector<SkinSegmentSpec> segments;  // parents before children
  BodyShape shape;                        // Eq. 5 (a, b, c) per bone, groups expanded
};

// Parses and validates; errors read "source:line:col: key.path: message". Needs the skeleton to
// check bone names, joint positions (a joined child's joint must lie on its parent's z axis,
// beyond the parent's last section) and that the skin has no open end.
BodyDescription parseBodyDescriptionYaml(const std::string& yaml_text, const Skeleton& skeleton,
                                         const std::string& source_name = "<body yaml>");
BodyDescription loadBodyDescriptionFile(const std::string& path, const Skeleton& skeleton);

// The limb groups accepted under `shape:` besides bone names, and the bones each covers.
const std::vector<std::pair<std::string, std::vector<std::string>>>& bodyShapeGroups();

}  // namespace dressed_human
