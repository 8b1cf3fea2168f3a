#pragma once
// The human skeleton read from the URDF: 20 bones, 16 articulated 3-DOF joints, the root frame.

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace dressed_human {

constexpr std::size_t kBoneCount = 20;
constexpr std::size_t kJointCount = 16;
constexpr std::size_t kDofsPerJoint = 3;
constexpr std::size_t kDofCount = kJointCount * kDofsPerJoint;

// The DOFs of every articulated joint, in chain order: flexion about the bone frame's y, then
// ab/adduction about x, then twist about the bone (z). Angle index = joint * 3 + dof.
enum class JointAxis : int { kY = 0, kX = 1, kZ = 2 };
constexpr std::array<const char*, kDofsPerJoint> kDofNames = {"y", "x", "z"};
constexpr std::array<const char*, kDofsPerJoint> kUrdfDofSuffixes = {"ry", "rx", "rz"};

// Eq. 5 per bone: P' = [a Px, b Py, c Pz] in the bone frame. c scales the bone's length, a and b
// its thickness. Children attach at the scaled position of their joint in this bone's frame.
// `offset` moves a bone's proximal joint in its parent's frame beyond what the parent's scale
// does (metres, after scaling): the layout of joints that lengths cannot reach, e.g. hip joints in
// front of the lumbar joint (a fitted capture's hip bones and clavicles; zero otherwise).
struct BodyShape {
  std::array<Eigen::Vector3d, kBoneCount> scale;
  std::array<Eigen::Vector3d, kBoneCount> offset;
  BodyShape() {
    scale.fill(Eigen::Vector3d::Ones());
    offset.fill(Eigen::Vector3d::Zero());
  }
  bool isIdentity() const;
  // This shape on top of `base` (a fitted person's, carried by its URDF): scales multiply,
  // joint offsets add.
  BodyShape appliedOn(const BodyShape& base) const;
};
constexpr double kMaxShapeOffset = 0.3;  // m: a joint moved further is no person's

struct SkeletonError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Bone {
  std::string name;        // frame name without suffix, REP-155 style: "l_knee" is the shank
  std::string anatomical;  // "left shank"
  int parent = -1;         // parent bone index; -1: the root frame "body"
  int joint = -1;          // articulated joint moving this bone; -1: fixed to its parent
  // Pose of this bone's frame in its parent's frame with all angles zero. The translation is the
  // proximal joint position, expressed in the parent frame (Eq. 5 scales it by the parent's a,b,c).
  Eigen::Vector3d rest_translation = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rest_rotation = Eigen::Quaterniond::Identity();
  double length = 0.0;  // along +z, from the bone's cylinder visual
  double radius = 0.0;  // of that cylinder: a first guess for the skin
};

struct ArticulatedJoint {
  std::string name;  // = the name of the bone it moves
  int bone = -1;
  std::array<std::string, kDofsPerJoint> urdf_joints;  // e.g. l_knee_ry, l_knee_rx, l_knee_rz (+suffix)
  std::array<std::string, 2> intermediate_links;       // l_knee_ry_link, l_knee_rx_link (+suffix)
};

class Skeleton {
 public:
  // Parses a URDF (the text of robot_description). Link and joint names may carry a common
  // "_<id>" suffix (several humans in one TF tree); it is detected from the root link "body_<id>".
  // A URDF written by shapedUrdf() (urdf_body_shape.h) carries a person's proportions: the bones
  // are read back as the unshaped skeleton and the proportions are bodyShape(), so that
  // ForwardKinematics(skeleton, skeleton.bodyShape()) puts every joint where the URDF does.
  // Throws SkeletonError naming the link or joint that does not fit the human layout.
  static Skeleton fromUrdf(const std::string& urdf_xml);
  static Skeleton fromUrdfFile(const std::string& path);

  const std::vector<Bone>& bones() const { return bones_; }
  const std::vector<ArticulatedJoint>& joints() const { return joints_; }
  const Bone& bone(std::size_t index) const { return bones_.at(index); }
  const ArticulatedJoint& joint(std::size_t index) const { return joints_.at(index); }

  // -1 when absent. Names are the suffix-free ones ("l_knee").
  int findBone(const std::string& name) const;
  int findJoint(const std::string& name) const;

  // The proportions the URDF was generated with; identity for a URDF that records none.
  const BodyShape& bodyShape() const { return body_shape_; }

  const std::string& suffix() const { return suffix_; }  // "" or "_<id>"
  std::string frameName(const std::string& plain) const { return plain + suffix_; }
  std::string rootFrame() const { return frameName("body"); }
  // The same skeleton for another human of one TF tree: every frame and URDF joint name with
  // `suffix` ("" or "_<id>", id alphanumeric) instead of this one's. Throws SkeletonError for
  // any other suffix.
  Skeleton withSuffix(const std::string& suffix) const;
  // The same bones carrying `shape` as the proportions of the person, as if parsed from the URDF
  // shapedUrdf() writes with it (no parse: a crowd display adds humans on rviz's thread).
  Skeleton withBodyShape(const BodyShape& shape) const;

 private:
  std::vector<Bone> bones_;               // parents before children
  std::vector<ArticulatedJoint> joints_;  // in bone order
  std::string suffix_;
  BodyShape body_shape_;
};

// The 20 bone frame names the layout expects, parents before children, and their anatomy.
struct BoneLayoutEntry {
  const char* name;
  const char* anatomical;
  bool articulated;
};
const std::array<BoneLayoutEntry, kBoneCount>& humanBoneLayout();

// The suffixes ("" or "_<id>") of every human among `frames` (e.g. every frame TF knows): a root
// frame "body" or "body_<id>" with the first bone of the same suffix ("waist_<id>") beside it,
// so that another robot's "body_link" is not taken for a human. Sorted, each once.
// A human id: the letters and digits after "body_" in its frames (REP-155 style suffix "_<id>").
bool isHumanId(const std::string& id);

std::vector<std::string> humanSuffixesAmong(const std::vector<std::string>& frames);

}  // namespace dressed_human
