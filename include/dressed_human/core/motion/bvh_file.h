#pragma once
// BVH motion capture files (Biovision hierarchy): the joint tree with offsets and channels, and the
// frames. Any channel order and any rotation order per joint; the root usually has 6 channels.
// Angles in a BVH are degrees; a joint's rotation is the product of its rotation channels in the
// order they are listed (e.g. "Zrotation Yrotation Xrotation" gives Rz * Ry * Rx).

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace dressed_human {

struct BvhError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class BvhChannel : int { kXposition, kYposition, kZposition, kXrotation, kYrotation, kZrotation };

struct BvhJoint {
  std::string name;
  int parent = -1;                                   // joint index; -1 for the root
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // from the parent joint, in the parent's frame
  std::vector<BvhChannel> channels;
  std::size_t first_channel = 0;  // column of its first channel in a frame
  std::vector<int> children;
  // "End Site" offsets below this joint (the distal end of a leaf segment), in this joint's frame.
  std::vector<Eigen::Vector3d> end_sites;
};

struct BvhClip {
  std::vector<BvhJoint> joints;  // parents before children; joints[0] is the root
  std::size_t channel_count = 0;
  double frame_time = 0.0;                  // seconds
  std::vector<std::vector<double>> frames;  // frames[f][channel], as written (degrees, units)

  int findJoint(const std::string& name) const;  // -1 when absent
  // Local rotation of a joint in frame f: its rotation channels composed in file order.
  Eigen::Matrix3d localRotation(std::size_t frame, std::size_t joint) const;
  // Local translation: the offset, replaced per axis by position channels when present.
  Eigen::Vector3d localTranslation(std::size_t frame, std::size_t joint) const;
};

// Global (world) rotation and position of every joint in one frame, in the file's coordinates.
struct BvhPose {
  std::vector<Eigen::Matrix3d> rotation;
  std::vector<Eigen::Vector3d> position;
};
BvhPose bvhForwardKinematics(const BvhClip& clip, std::size_t frame);
// The same with every channel zero but the root at the origin: the rest (bind) pose.
BvhPose bvhRestPose(const BvhClip& clip);
// `joint` and every joint below it.
std::vector<std::size_t> bvhSubtree(const BvhClip& clip, std::size_t joint);
// A joint, or one of its end sites.
struct BvhPoint {
  std::size_t joint = 0;
  int end_site = -1;  // -1: the joint itself
};
Eigen::Vector3d bvhPointPosition(const BvhClip& clip, const BvhPose& pose, const BvhPoint& point);
// The joint or end site of `joint`'s subtree farthest from it in `pose` (`joint` itself for a lone
// joint without end sites): where a segment that ends in markers ends (a foot's toe tip).
BvhPoint bvhFarthestPointBelow(const BvhClip& clip, const BvhPose& pose, std::size_t joint);
// From `joint` to that point.
Eigen::Vector3d bvhFarthestBelow(const BvhClip& clip, const BvhPose& pose, std::size_t joint);

// Throws BvhError "source:line: what" for any malformed input: unknown keywords, bad or missing
// numbers, non-finite values, a frame count that does not match, unbalanced braces, ...
BvhClip parseBvh(const std::string& text, const std::string& source_name);
BvhClip loadBvhFile(const std::string& path);

}  // namespace dressed_human
