#include "dressed_human/core/motion/mocap_joint_map.h"
#include "dressed_human/core/io/text_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "dressed_human/core/motion/motion.h"

namespace dressed_human {
namespace {

// humanJointNames() order: waist torso neck head l_shoulder l_elbow l_wrist r_shoulder r_elbow
// r_wrist l_hip l_knee l_ankle r_hip r_knee r_ankle. Each source joint is the one at the proximal
// end of the same segment (LeftUpLeg rotates the thigh, LeftLeg the shank, ...). The spine by
// place: CMU's LowerBack sits at the pelvis like our waist joint, Spine1 and Neck share the
// base of the neck (the ASF thorax has no length), so our chest spans Spine to Neck1 and our
// head starts at Head; this puts our spine joints within 1 cm of the capture's (Spine, Spine1 for
// waist and torso left them 5 cm off).
BvhJointMap cmuBvhMap() {
  return {"CMU BVH",
          "Hips",
          {"LowerBack", "Spine", "Neck1", "Head", "LeftArm", "LeftForeArm", "LeftHand", "RightArm", "RightForeArm",
           "RightHand", "LeftUpLeg", "LeftLeg", "LeftFoot", "RightUpLeg", "RightLeg", "RightFoot"}};
}

// The Acclaim ASF bone names of the same CMU skeleton (BVH files converted from ASF/AMC).
BvhJointMap asfMap() {
  return {"ASF",
          "root",
          {"lowerback", "upperback", "upperneck", "head", "lhumerus", "lradius", "lwrist", "rhumerus", "rradius",
           "rwrist", "lfemur", "ltibia", "lfoot", "rfemur", "rtibia", "rfoot"}};
}

// Rigs named as animation tools name them, each name with the alternatives its variants use: the
// HumanIK / Mixamo / LAFAN1 convention (Hips, Spine..Spine2, LeftUpLeg; Mixamo's joints carry a
// "mixamorig:" namespace, which resolution strips), Unity's humanoid and the Bandai-Namco capture
// set (UpperLeg_L), and Unreal's mannequin (pelvis, spine_01, thigh_l). The spine by place, as for
// CMU: the waist at the lowest spine joint, the torso mid-back, the neck at its base.
BvhJointMap humanIkMap() {
  return {"HumanIK / Mixamo",
          "Hips",
          {"Spine", "Spine2|Spine1|Chest", "Neck|Neck1", "Head", "LeftArm", "LeftForeArm", "LeftHand", "RightArm",
           "RightForeArm", "RightHand", "LeftUpLeg", "LeftLeg", "LeftFoot", "RightUpLeg", "RightLeg", "RightFoot"}};
}

BvhJointMap unityHumanoidMap() {
  return {"Unity humanoid / Bandai",
          "Hips",
          {"Spine", "Chest|UpperChest", "Neck", "Head", "LeftUpperArm|UpperArm_L", "LeftLowerArm|LowerArm_L",
           "LeftHand|Hand_L", "RightUpperArm|UpperArm_R", "RightLowerArm|LowerArm_R", "RightHand|Hand_R",
           "LeftUpperLeg|UpperLeg_L", "LeftLowerLeg|LowerLeg_L", "LeftFoot|Foot_L", "RightUpperLeg|UpperLeg_R",
           "RightLowerLeg|LowerLeg_R", "RightFoot|Foot_R"}};
}

BvhJointMap unrealMap() {
  return {"Unreal mannequin",
          "pelvis",
          {"spine_01", "spine_03|spine_02", "neck_01", "head", "upperarm_l", "lowerarm_l", "hand_l", "upperarm_r",
           "lowerarm_r", "hand_r", "thigh_l", "calf_l", "foot_l", "thigh_r", "calf_r", "foot_r"}};
}

// OpenSim models as BVH clips (opensim_capture.h): joints named by the body they move. The
// full-body models (Hamner, Rajagopal) add arms to gait2392's legs and back; gait2392's torso
// carries head and arms rigidly, so its neck and arms stay at rest.
BvhJointMap openSimFullBodyMap() {
  return {"OpenSim full body",
          "pelvis",
          {"torso", "", "", "", "humerus_l", "ulna_l", "hand_l", "humerus_r", "ulna_r", "hand_r", "femur_l", "tibia_l",
           "talus_l", "femur_r", "tibia_r", "talus_r"}};
}

BvhJointMap openSimGaitBodyMap() {
  return {
      "OpenSim gait2392 bodies",
      "pelvis",
      {"torso", "", "", "", "", "", "", "", "", "", "femur_l", "tibia_l", "talus_l", "femur_r", "tibia_r", "talus_r"}};
}

CoordinateRotation about(const char* column, double x, double y, double z) {
  return {column, Eigen::Vector3d(x, y, z).normalized()};
}

// OpenSim gait2354/gait2392 (Delp et al. 1990): body-fixed rotation sequences of its CustomJoints,
// axes as in the model file. The left side mirrors ad/abduction and rotation axes.
CoordinateJointMap openSimGaitMap() {
  CoordinateJointMap map;
  map.name = "OpenSim gait2392";
  map.root_translation = {"pelvis_tx", "pelvis_ty", "pelvis_tz"};
  map.root_rotation = {about("pelvis_tilt", 0, 0, 1), about("pelvis_list", 1, 0, 0), about("pelvis_rotation", 0, 1, 0)};
  auto& joints = map.joints;
  joints[0] = {about("lumbar_extension", 0, 0, 1), about("lumbar_bending", 1, 0, 0), about("lumbar_rotation", 0, 1, 0)};
  joints[10] = {about("hip_flexion_l", 0, 0, 1), about("hip_adduction_l", -1, 0, 0), about("hip_rotation_l", 0, -1, 0)};
  joints[11] = {about("knee_angle_l", 0, 0, 1)};
  joints[12] = {about("ankle_angle_l", 0.10501355, 0.17402245, 0.97912632)};
  joints[13] = {about("hip_flexion_r", 0, 0, 1), about("hip_adduction_r", 1, 0, 0), about("hip_rotation_r", 0, 1, 0)};
  joints[14] = {about("knee_angle_r", 0, 0, 1)};
  joints[15] = {about("ankle_angle_r", -0.10501355, -0.17402245, 0.97912632)};
  return map;
}

// A clip joint named `name` (letter case aside), or `name` in the clip's namespace ("mixamorig:").
int findNamed(const BvhClip& clip, const std::string& name) {
  const auto same = [](const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
             return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
  };
  for (std::size_t j = 0; j < clip.joints.size(); ++j) {
    const std::string& joint = clip.joints[j].name;
    const std::size_t colon = joint.rfind(':');
    if (same(joint, name) || (colon != std::string::npos && same(joint.substr(colon + 1), name)))
      return static_cast<int>(j);
  }
  return -1;
}

// The clip's own name for one of `alternatives` ("Spine2|Spine1"), the first found; the
// alternatives themselves when none is.
std::string resolveName(const BvhClip& clip, const std::string& alternatives) {
  if (alternatives.empty() || clip.findJoint(alternatives) >= 0) return alternatives;
  std::size_t start = 0;
  while (start <= alternatives.size()) {
    const std::size_t bar = std::min(alternatives.find('|', start), alternatives.size());
    const int joint = findNamed(clip, alternatives.substr(start, bar - start));
    if (joint >= 0) return clip.joints[static_cast<std::size_t>(joint)].name;
    start = bar + 1;
  }
  return alternatives;
}

BvhJointMap resolveMap(const BvhJointMap& map, const BvhClip& clip) {
  BvhJointMap resolved = map;
  resolved.root = resolveName(clip, map.root);
  for (std::string& joint : resolved.joints) joint = resolveName(clip, joint);
  return resolved;
}

std::vector<std::string> missingJoints(const BvhJointMap& map, const BvhClip& clip) {
  std::vector<std::string> missing;
  if (clip.findJoint(map.root) < 0) missing.push_back(map.root);
  for (const std::string& name : map.joints) {
    if (!name.empty() && clip.findJoint(name) < 0) missing.push_back(name);
  }
  return missing;
}

std::string joinNames(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

const std::vector<BvhJointMap>& builtinBvhJointMaps() {
  static const std::vector<BvhJointMap> maps = {
      cmuBvhMap(), asfMap(), humanIkMap(), unityHumanoidMap(), unrealMap(), openSimFullBodyMap(), openSimGaitBodyMap()};
  return maps;
}

const CoordinateJointMap& builtinOpenSimGaitMap() {
  static const CoordinateJointMap map = openSimGaitMap();
  return map;
}

void checkBvhJointNames(const BvhJointMap& map, const BvhClip& clip, const std::string& source_name) {
  const std::vector<std::string> missing = missingJoints(map, clip);
  if (!missing.empty()) {
    throw JointMapError(source_name + ": the " + map.name + " joint map needs joints this BVH does not have: " +
                        joinNames(missing) + " (give a joint map file with --map for other skeletons)");
  }
}

void checkBvhJointMap(const BvhJointMap& map, const BvhClip& clip, const std::string& source_name) {
  checkBvhJointNames(map, clip, source_name);
  if (clip.joints.empty() || clip.joints[0].name != map.root) {
    throw JointMapError(source_name + ": the " + map.name + " joint map takes the pelvis from '" + map.root +
                        "', which must be the BVH root (the root is '" +
                        (clip.joints.empty() ? std::string() : clip.joints[0].name) + "')");
  }
}

BvhJointMap chooseBvhJointMap(const BvhClip& clip, const std::string& source_name) {
  const BvhJointMap* best = nullptr;
  std::size_t best_missing = 0;
  std::vector<BvhJointMap> resolved;
  for (const BvhJointMap& map : builtinBvhJointMaps()) resolved.push_back(resolveMap(map, clip));
  for (const BvhJointMap& map : resolved) {
    const std::size_t missing = missingJoints(map, clip).size();
    if (!best || missing < best_missing) {
      best = &map;
      best_missing = missing;
    }
  }
  checkBvhJointNames(*best, clip, source_name);  // the pelvis may hang below a still root (bvh_standing_rest.h)
  return *best;
}

void checkCoordinateJointMap(const CoordinateJointMap& map, const OpenSimTable& table, const std::string& source_name) {
  std::vector<std::string> missing;
  for (const CoordinateRotation& r : map.root_rotation) {
    if (table.findColumn(r.column) < 0) missing.push_back(r.column);
  }
  for (const auto& chain : map.joints) {
    for (const CoordinateRotation& r : chain) {
      if (table.findColumn(r.column) < 0) missing.push_back(r.column);
    }
  }
  if (!missing.empty()) {
    throw JointMapError(source_name + ": the " + map.name + " joint map needs coordinates this file does not have: " +
                        joinNames(missing) + " (give a joint map file with --map for other models)");
  }
}

namespace {

[[noreturn]] void failAt(const std::string& source, const YAML::Node& node, const std::string& key,
                         const std::string& message) {
  std::ostringstream text;
  text << source;
  if (node.Mark().line >= 0) text << ':' << node.Mark().line + 1 << ':' << node.Mark().column + 1;
  text << ": " << key << ": " << message;
  throw JointMapError(text.str());
}

std::string scalarOrEmpty(const std::string& source, const YAML::Node& node, const std::string& key) {
  if (node.IsNull()) return "";
  if (!node.IsScalar()) failAt(source, node, key, "expected a joint name or ~");
  return node.Scalar();
}

CoordinateRotation readRotation(const std::string& source, const YAML::Node& node, const std::string& key) {
  if (!node.IsSequence() || node.size() != 4 || !node[0].IsScalar()) {
    failAt(source, node, key, "expected [column, axis_x, axis_y, axis_z]");
  }
  CoordinateRotation rotation;
  rotation.column = node[0].Scalar();
  for (int k = 0; k < 3; ++k) {
    try {
      rotation.axis[k] = node[k + 1].as<double>();
    } catch (const YAML::Exception&) {
      failAt(source, node[k + 1], key, "axis components must be numbers");
    }
  }
  const double norm = rotation.axis.norm();
  if (!std::isfinite(norm) || norm < 1e-9) failAt(source, node, key, "the axis must be finite and non-zero");
  rotation.axis /= norm;
  return rotation;
}

std::vector<CoordinateRotation> readChain(const std::string& source, const YAML::Node& node, const std::string& key) {
  std::vector<CoordinateRotation> chain;
  if (node.IsNull()) return chain;
  if (!node.IsSequence()) failAt(source, node, key, "expected a list of [column, x, y, z] rotations");
  for (std::size_t i = 0; i < node.size(); ++i) {
    chain.push_back(readRotation(source, node[i], key + "[" + std::to_string(i + 1) + "]"));
  }
  return chain;
}

}  // namespace

JointMapFile parseJointMapYaml(const std::string& yaml_text, const std::string& source_name) {
  YAML::Node document;
  try {
    document = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& error) {
    throw JointMapError(source_name + ":" + std::to_string(error.mark.line + 1) + ": not valid YAML: " + error.msg);
  }
  if (!document.IsMap()) throw JointMapError(source_name + ": a joint map must be a YAML mapping");
  JointMapFile file;
  const YAML::Node kind = document["kind"];
  if (!kind || !kind.IsScalar() || (kind.Scalar() != "bvh" && kind.Scalar() != "coordinates")) {
    failAt(source_name, kind ? kind : document, "kind", "must be 'bvh' or 'coordinates'");
  }
  file.kind = kind.Scalar();
  const YAML::Node joints = document["joints"];
  if (!joints || !joints.IsMap()) failAt(source_name, document, "joints", "missing mapping of our 16 joints");
  for (const auto& entry : joints) {
    bool known = false;
    for (const char* name : humanJointNames()) known = known || entry.first.Scalar() == name;
    if (!known) failAt(source_name, entry.first, "joints." + entry.first.Scalar(), "not one of our 16 joints");
  }
  const YAML::Node root = document["root"];
  if (!root) failAt(source_name, document, "root", "missing");
  if (file.kind == "bvh") {
    file.bvh.name = source_name;
    file.bvh.root = scalarOrEmpty(source_name, root, "root");
    if (file.bvh.root.empty()) failAt(source_name, root, "root", "the pelvis must come from a source joint");
  } else {
    file.coordinates.name = source_name;
    if (!root.IsMap()) failAt(source_name, root, "root", "expected {translation: [...], rotation: [...]}");
    if (const YAML::Node translation = root["translation"]) {
      if (!translation.IsSequence() || translation.size() != 3) {
        failAt(source_name, translation, "root.translation", "expected three column names (or ~) for X, Y, Z");
      }
      for (std::size_t k = 0; k < 3; ++k) {
        file.coordinates.root_translation[k] = scalarOrEmpty(source_name, translation[k], "root.translation");
      }
    }
    if (root["rotation"]) file.coordinates.root_rotation = readChain(source_name, root["rotation"], "root.rotation");
  }
  for (std::size_t j = 0; j < kJointCount; ++j) {
    const std::string key = std::string("joints.") + humanJointNames()[j];
    const YAML::Node joint = joints[humanJointNames()[j]];
    if (!joint) failAt(source_name, joints, key, "missing: list every joint (~ holds it at rest)");
    if (file.kind == "bvh") {
      file.bvh.joints[j] = scalarOrEmpty(source_name, joint, key);
    } else {
      file.coordinates.joints[j] = readChain(source_name, joint, key);
    }
  }
  return file;
}

JointMapFile loadJointMapFile(const std::string& path) {
  return parseJointMapYaml(readWholeFileOrThrow<JointMapError>(path, "the joint map file"), path);
}

}  // namespace dressed_human
