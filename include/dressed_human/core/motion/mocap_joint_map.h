#pragma once
// Which part of a motion capture drives each of our 16 joints.
//
// Two kinds of source:
//  - a skeleton with joint rotations (BVH): each of our joints takes the orientation of one source
//    joint (the one at the proximal end of the same anatomical segment);
//  - joint coordinates (OpenSim .mot): each of our joints is a chain of single-axis rotations
//    read from columns, about axes of the OpenSim segment frame (X forward, Y up, Z right).
// Built-in maps: CMU BVH names (Hips, LeftUpLeg, ...), ASF-style names (root, lfemur, ...), the
// HumanIK / Mixamo, Unity humanoid / Bandai and Unreal rigs (names with alternatives, letter case
// and a "mixamorig:"-style namespace aside), OpenSim
// models turned into BVH clips (opensim_capture.h: body names pelvis, femur_l, ...; with or
// without arms) and the OpenSim gait models' coordinates (gait2354/gait2392 coordinate names, for
// a motion without its model). Other sources: a YAML map file.
//
// YAML layout (see data/motion/README.md for full examples):
//   kind: bvh                 # the source joint for every one of our 16 joints (~: held at rest)
//   root: Hips
//   joints: {waist: Spine, torso: Spine1, ..., r_ankle: RightFoot}
// or
//   kind: coordinates         # OpenSim axes: X forward, Y up, Z right
//   root: {translation: [pelvis_tx, pelvis_ty, pelvis_tz],
//          rotation: [[pelvis_tilt, 0, 0, 1], [pelvis_list, 1, 0, 0], [pelvis_rotation, 0, 1, 0]]}
//   joints: {l_hip: [[hip_flexion_l, 0, 0, 1], ...], ...}   # each joint listed; [] = held at rest

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dressed_human/core/motion/bvh_file.h"
#include "dressed_human/core/motion/opensim_motion_file.h"
#include "dressed_human/core/skeleton/skeleton.h"

namespace dressed_human {

// Our joints by index (humanJointNames() order), for the code that reads segments by place.
namespace human_joint {
constexpr int kWaist = 0;
constexpr int kTorso = 1;
constexpr int kNeck = 2;
constexpr int kHead = 3;
constexpr int kLeftShoulder = 4;
constexpr int kRightShoulder = 7;
constexpr int kLeftHip = 10;
constexpr int kLeftKnee = 11;
constexpr int kLeftAnkle = 12;
constexpr int kRightHip = 13;
constexpr int kRightAnkle = 15;
// For each joint, the joint at the distal end of its bone (-1: the bone ends free): the source
// joints mapped to both ends give the source segment's rest direction and length.
constexpr std::array<int, kJointCount> kDistalJoint = {1, 2, 3, -1, 5, 6, -1, 8, 9, -1, 11, 12, -1, 14, 15, -1};
}  // namespace human_joint

struct JointMapError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct BvhJointMap {
  std::string name;                             // "CMU BVH", "ASF", or the YAML file
  std::string root;                             // source joint of our body frame (pelvis)
  std::array<std::string, kJointCount> joints;  // in humanJointNames() order; "" = held at rest
};

struct CoordinateRotation {
  std::string column;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit, in the source segment frame
};

struct CoordinateJointMap {
  std::string name;
  std::array<std::string, 3> root_translation;                      // columns along source X, Y, Z; "" = absent (0)
  std::vector<CoordinateRotation> root_rotation;                    // applied in list order (body-fixed)
  std::array<std::vector<CoordinateRotation>, kJointCount> joints;  // empty = held at rest
};

const std::vector<BvhJointMap>& builtinBvhJointMaps();
const CoordinateJointMap& builtinOpenSimGaitMap();

// The built-in map that names the most joints of the clip. Throws JointMapError listing the
// joints the best map needs but the clip does not have.
BvhJointMap chooseBvhJointMap(const BvhClip& clip, const std::string& source_name);
// Throws JointMapError naming every joint of the map missing in the clip.
void checkBvhJointNames(const BvhJointMap& map, const BvhClip& clip, const std::string& source_name);
// The same, and that the map's pelvis is the clip's root (standingRest lifts it there).
void checkBvhJointMap(const BvhJointMap& map, const BvhClip& clip, const std::string& source_name);
// Throws JointMapError naming every column of the map missing in the table.
void checkCoordinateJointMap(const CoordinateJointMap& map, const OpenSimTable& table, const std::string& source_name);

// A YAML map file of either kind; `kind` tells which one was read ("bvh" or "coordinates").
struct JointMapFile {
  std::string kind;
  BvhJointMap bvh;
  CoordinateJointMap coordinates;
};
JointMapFile loadJointMapFile(const std::string& path);
JointMapFile parseJointMapYaml(const std::string& yaml_text, const std::string& source_name);

}  // namespace dressed_human
