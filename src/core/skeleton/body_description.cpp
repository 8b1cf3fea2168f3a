#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/io/text_file.h"

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <utility>

#include "dressed_human/core/io/yaml_reader.h"
#include "dressed_human/core/skeleton/body_shape_yaml.h"

namespace dressed_human {
namespace {

// A joined child's joint must lie on the parent's z axis to this tolerance (metres).
constexpr double kAxisTolerance = 1e-6;
// Section heights and cap lengths along a bone, metres: no bone of a person is longer.
constexpr double kMaxLength = 1.0;

using BodyYamlReader = YamlReader<BodyDescriptionError>;

std::string format(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

const std::vector<std::pair<std::string, std::vector<std::string>>>& bodyShapeGroups() {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> groups = {
      {"all", {"waist",   "torso",      "neck",       "head",    "l_clavicle", "l_shoulder", "l_elbow",
               "l_wrist", "r_clavicle", "r_shoulder", "r_elbow", "r_wrist",    "l_pelvis",   "l_hip",
               "l_knee",  "l_ankle",    "r_pelvis",   "r_hip",   "r_knee",     "r_ankle"}},
      {"trunk", {"waist", "torso"}},
      {"head_neck", {"neck", "head"}},
      {"arms", {"l_clavicle", "l_shoulder", "l_elbow", "l_wrist", "r_clavicle", "r_shoulder", "r_elbow", "r_wrist"}},
      {"l_arm", {"l_clavicle", "l_shoulder", "l_elbow", "l_wrist"}},
      {"r_arm", {"r_clavicle", "r_shoulder", "r_elbow", "r_wrist"}},
      {"legs", {"l_pelvis", "l_hip", "l_knee", "l_ankle", "r_pelvis", "r_hip", "r_knee", "r_ankle"}},
      {"l_leg", {"l_pelvis", "l_hip", "l_knee", "l_ankle"}},
      {"r_leg", {"r_pelvis", "r_hip", "r_knee", "r_ankle"}},
  };
  return groups;
}

namespace {

// What is known of the segments read so far, for the checks that look across segments.
struct SegmentsRead {
  std::map<std::string, std::size_t> segment_of_bone;
  std::vector<YAML::Node> nodes;
  std::vector<int> joined_child;  // per segment, the segment continuing it; -1: none
};

// One entry of `segments`: its bone, joined flag, caps and sections, checked on their own.
SkinSegmentSpec readSegment(const BodyYamlReader& reader, const YAML::Node& node, std::size_t index,
                            const Skeleton& skeleton, const SegmentsRead& read) {
  std::string key = "segments[" + std::to_string(index) + "]";
  reader.requireMap(node, key);
  reader.rejectUnknownKeys(node, key, {"bone", "joined", "proximal_cap", "distal_cap", "sections"});
  const YAML::Node bone_node = reader.require(node, "bone", key);
  if (!bone_node.IsScalar()) reader.fail(bone_node, key + ".bone", "expected a bone name");
  SkinSegmentSpec spec;
  spec.bone = bone_node.Scalar();
  key = "segments." + spec.bone;
  if (spec.bone != "body") {
    spec.bone_index = skeleton.findBone(spec.bone);
    if (spec.bone_index < 0)
      reader.fail(bone_node, key, "no bone of that name in the skeleton (or \"body\" for the root frame)");
  }
  if (read.segment_of_bone.count(spec.bone)) reader.fail(bone_node, key, "a second segment for the same bone");
  if (node["joined"]) spec.joined_to_parent = reader.boolean(node["joined"], key + ".joined");
  if (node["proximal_cap"]) spec.proximal_cap = reader.number(node["proximal_cap"], key + ".proximal_cap");
  if (node["distal_cap"]) spec.distal_cap = reader.number(node["distal_cap"], key + ".distal_cap");
  for (const char* cap : {"proximal_cap", "distal_cap"}) {
    if (node[cap] && reader.number(node[cap], key + "." + cap) > kMaxLength) {
      reader.numberWithin(node[cap], key + "." + cap, 0.0, kMaxLength, " m");
    }
  }
  for (const char* cap : {"proximal_cap", "distal_cap"}) {
    if (node[cap] && reader.number(node[cap], key + "." + cap) < 0.0) {
      reader.fail(node[cap], key + "." + cap, "must be >= 0 metres");
    }
  }

  const YAML::Node sections = reader.require(node, "sections", key);
  if (!sections.IsSequence() || sections.size() == 0) {
    reader.fail(sections, key + ".sections",
                "expected a list of [z, radius_x, radius_y], got " + BodyYamlReader::describe(sections));
  }
  for (std::size_t k = 0; k < sections.size(); ++k) {
    const std::string section_key = key + ".sections[" + std::to_string(k) + "]";
    const std::vector<double> v = reader.numbers(sections[k], section_key, 3, "[z, radius_x, radius_y] in metres");
    if (!(v[1] > 0.0) || !(v[2] > 0.0)) reader.fail(sections[k], section_key, "radii must be > 0");
    if (v[1] > 1.0 || v[2] > 1.0) reader.fail(sections[k], section_key, "radii above 1 m: metres expected");
    reader.numberWithin(sections[k][0], section_key + "[0]", -kMaxLength, kMaxLength, " m (z along the bone)");
    if (k > 0 && !(v[0] > spec.sections.back().z)) {
      reader.fail(
          sections[k], section_key,
          "z " + format(v[0]) + " must be greater than the previous section's " + format(spec.sections.back().z));
    }
    spec.sections.push_back(SkinSection{v[0], v[1], v[2]});
  }
  return spec;
}

// A joined segment continues its parent's surface: the parent comes first, has no other
// continuation, ends below the joint, and the joint is on its axis.
void checkJoin(const BodyYamlReader& reader, const YAML::Node& node, const SkinSegmentSpec& spec,
               const Skeleton& skeleton, const BodyDescription& body, SegmentsRead& read) {
  const std::string key = "segments." + spec.bone;
  const YAML::Node sections = node["sections"];
  if (spec.bone_index < 0) reader.fail(node["joined"], key + ".joined", "the root segment has no parent to join");
  const Bone& bone = skeleton.bone(static_cast<std::size_t>(spec.bone_index));
  const std::string parent_name =
      bone.parent < 0 ? std::string("body") : skeleton.bone(static_cast<std::size_t>(bone.parent)).name;
  const auto parent = read.segment_of_bone.find(parent_name);
  if (parent == read.segment_of_bone.end()) {
    reader.fail(node["joined"], key + ".joined",
                "the parent segment '" + parent_name + "' must come earlier in the list");
  }
  if (read.joined_child[parent->second] >= 0) {
    reader.fail(node["joined"], key + ".joined",
                "segment '" + parent_name + "' already continues into '" +
                    body.segments[static_cast<std::size_t>(read.joined_child[parent->second])].bone + "'");
  }
  if (node["proximal_cap"] && spec.proximal_cap != 0.0) {
    reader.fail(node["proximal_cap"], key + ".proximal_cap", "a joined segment has no proximal cap");
  }
  if (spec.sections.front().z != 0.0) {
    reader.fail(sections[0], key + ".sections[0]", "a joined segment starts with its joint ring: z must be 0");
  }
  const Eigen::Vector3d& joint = bone.rest_translation;
  if (std::abs(joint.x()) > kAxisTolerance || std::abs(joint.y()) > kAxisTolerance) {
    reader.fail(node["joined"], key + ".joined",
                "the joint is off the parent's z axis; only a bone continuing its parent can join");
  }
  const SkinSegmentSpec& parent_spec = body.segments[parent->second];
  if (!(joint.z() > parent_spec.sections.back().z)) {
    reader.fail(read.nodes[parent->second]["sections"], "segments." + parent_name + ".sections",
                "the last section (z = " + format(parent_spec.sections.back().z) +
                    ") must lie below the joint of the joined child '" + spec.bone + "' (z = " + format(joint.z()) +
                    ")");
  }
  read.joined_child[parent->second] = static_cast<int>(body.segments.size());
}

// Every segment's far end is either continued by a joined child or closed by a cap.
void checkSegmentEnds(const BodyYamlReader& reader, const BodyDescription& body, const SegmentsRead& read) {
  for (std::size_t s = 0; s < body.segments.size(); ++s) {
    const SkinSegmentSpec& spec = body.segments[s];
    const YAML::Node& node = read.nodes[s];
    const std::string key = "segments." + spec.bone;
    if (read.joined_child[s] >= 0) {
      if (node["distal_cap"] && spec.distal_cap != 0.0) {
        reader.fail(node["distal_cap"], key + ".distal_cap",
                    "segment '" + body.segments[static_cast<std::size_t>(read.joined_child[s])].bone +
                        "' continues this one: no distal cap");
      }
    } else {
      if (!(spec.distal_cap > 0.0))
        reader.fail(node, key + ".distal_cap", "open distal end: give distal_cap > 0 or join a child segment");
      if (spec.sections.size() < 2)
        reader.fail(node["sections"], key + ".sections", "needs at least 2 sections (one stack)");
    }
  }
}

}  // namespace

BodyDescription parseBodyDescriptionYaml(const std::string& yaml_text, const Skeleton& skeleton,
                                         const std::string& source_name) {
  const BodyYamlReader reader(source_name);
  const YAML::Node document = reader.load(yaml_text, "the body description");
  reader.rejectUnknownKeys(document, "", {"name", "segments", "shape"});

  BodyDescription body;
  if (document["name"]) {
    body.name = reader.text(document["name"], "name");
  }
  const YAML::Node shape = document["shape"];
  if (shape && !shape.IsNull()) readBodyShapeYaml(reader, shape, "shape", body.shape);

  const YAML::Node segments = reader.require(document, "segments", "");
  if (!segments.IsSequence() || segments.size() == 0) {
    reader.fail(segments, "segments",
                "expected a non-empty list of segments, got " + BodyYamlReader::describe(segments));
  }
  SegmentsRead read;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const YAML::Node node = segments[s];
    const SkinSegmentSpec spec = readSegment(reader, node, s, skeleton, read);
    if (spec.joined_to_parent) {
      checkJoin(reader, node, spec, skeleton, body, read);
    } else if (!(spec.proximal_cap > 0.0)) {
      reader.fail(node, "segments." + spec.bone + ".proximal_cap",
                  "open proximal end: give proximal_cap > 0 or join the parent");
    }
    read.segment_of_bone[spec.bone] = body.segments.size();
    read.nodes.push_back(node);
    read.joined_child.push_back(-1);
    body.segments.push_back(spec);
  }
  checkSegmentEnds(reader, body, read);
  return body;
}

BodyDescription loadBodyDescriptionFile(const std::string& path, const Skeleton& skeleton) {
  return parseBodyDescriptionYaml(readWholeFileOrThrow<BodyDescriptionError>(path, "the body description"), skeleton,
                                  path);
}

}  // namespace dressed_human
