#pragma once
// The Eq. 5 body shape as the project's YAML files write it (a body file's `shape:`, a fitted
// motion's `body_shape:`): bone or group name -> [a, b, c], or [a, b, c, dx, dy, dz] with the
// joint's offset (BodyShape::offset, metres), applied in the order written (later entries
// override), each factor in [kMinShapeScale, kMaxShapeScale], each offset within kMaxShapeOffset.

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "dressed_human/core/io/yaml_reader.h"
#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/body_shape_groups.h"
#include "dressed_human/core/skeleton/skeleton.h"

namespace dressed_human {

template <typename Error>
void readBodyShapeYaml(const YamlReader<Error>& reader, const YAML::Node& node, const std::string& key,
                       BodyShape& shape) {
  reader.requireMap(node, key);
  const auto& layout = humanBoneLayout();
  for (const auto& entry : node) {
    const std::string name = entry.first.Scalar();
    const std::string entry_key = key + "." + name;
    std::vector<std::string> bones;
    for (const auto& group : bodyShapeGroups()) {
      if (group.first == name) bones = group.second;
    }
    if (bones.empty()) {
      bool is_bone = false;
      for (const BoneLayoutEntry& bone : layout) is_bone = is_bone || name == bone.name;
      if (!is_bone) {
        std::string groups;
        for (const auto& group : bodyShapeGroups()) groups += (groups.empty() ? "" : ", ") + group.first;
        reader.fail(entry.first, entry_key, "neither a bone of the skeleton nor a group (" + groups + ")");
      }
      bones.push_back(name);
    }
    const bool with_offset = entry.second.IsSequence() && entry.second.size() == 6;
    const std::vector<double> abc = reader.numbers(entry.second, entry_key, with_offset ? 6 : 3,
                                                   "[a, b, c] (Eq. 5 scale of x, y, z) or [a, b, c, dx, dy, dz]");
    for (std::size_t k = 3; k < abc.size(); ++k) {
      if (!(std::abs(abc[k]) <= kMaxShapeOffset)) {
        std::ostringstream range;
        range << "offset " << abc[k] << " m outside [-" << kMaxShapeOffset << ", " << kMaxShapeOffset << "]";
        reader.fail(entry.second, entry_key, range.str());
      }
    }
    for (std::size_t k = 0; k < 3; ++k) {
      if (!(abc[k] >= kMinShapeScale && abc[k] <= kMaxShapeScale)) {
        std::ostringstream range;
        range << "scale " << abc[k] << " outside [" << kMinShapeScale << ", " << kMaxShapeScale << "]";
        reader.fail(entry.second, entry_key, range.str());
      }
    }
    for (const std::string& bone : bones) {
      for (std::size_t b = 0; b < layout.size(); ++b) {
        if (bone != layout[b].name) continue;
        shape.scale[b] = Eigen::Vector3d(abc[0], abc[1], abc[2]);
        shape.offset[b] = with_offset ? Eigen::Vector3d(abc[3], abc[4], abc[5]) : Eigen::Vector3d::Zero();
      }
    }
  }
}

}  // namespace dressed_human
