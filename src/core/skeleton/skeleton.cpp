#include "dressed_human/core/skeleton/skeleton.h"
#include "dressed_human/core/skeleton/urdf_body_shape.h"
#include "dressed_human/core/io/text_file.h"

#include <algorithm>
#include <cctype>
#include <set>

#include <urdf_model/model.h>
#include <urdf_parser/urdf_parser.h>

namespace dressed_human {
namespace {

struct LayoutParent {
  const char* bone;
  const char* parent;
};

// Parent of every bone in the human layout; "body" is the root frame (pelvis centre).
constexpr std::array<LayoutParent, kBoneCount> kLayoutParents = {{
    {"waist", "body"},       {"torso", "waist"},           {"neck", "torso"},         {"head", "neck"},
    {"l_clavicle", "torso"}, {"l_shoulder", "l_clavicle"}, {"l_elbow", "l_shoulder"}, {"l_wrist", "l_elbow"},
    {"r_clavicle", "torso"}, {"r_shoulder", "r_clavicle"}, {"r_elbow", "r_shoulder"}, {"r_wrist", "r_elbow"},
    {"l_pelvis", "body"},    {"l_hip", "l_pelvis"},        {"l_knee", "l_hip"},       {"l_ankle", "l_knee"},
    {"r_pelvis", "body"},    {"r_hip", "r_pelvis"},        {"r_knee", "r_hip"},       {"r_ankle", "r_knee"},
}};

constexpr double kAxisTolerance = 1e-9;

Eigen::Vector3d toEigen(const urdf::Vector3& v) { return {v.x, v.y, v.z}; }

Eigen::Quaterniond toEigen(const urdf::Rotation& r) { return Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized(); }

bool isIdentity(const urdf::Pose& pose) {
  return toEigen(pose.position).norm() < kAxisTolerance &&
         toEigen(pose.rotation).angularDistance(Eigen::Quaterniond::Identity()) < kAxisTolerance;
}

bool isRotational(const urdf::Joint& joint) {
  return joint.type == urdf::Joint::REVOLUTE || joint.type == urdf::Joint::CONTINUOUS;
}

std::string describeSuffix(const std::string& suffix) {
  return suffix.empty() ? std::string("no suffix") : "suffix '" + suffix + "'";
}

// Walks from a bone link up through its three revolute joints (rz, rx, ry) and checks the
// REP-155-style chain: axes z, x, y from the bone upwards, identity origins on all but the
// first, bare intermediate links. Returns the link above the chain.
urdf::LinkConstSharedPtr readArticulatedChain(const urdf::ModelInterface& model, const urdf::Link& bone_link,
                                              ArticulatedJoint& joint, Bone& bone) {
  const std::array<Eigen::Vector3d, kDofsPerJoint> axes = {Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX(),
                                                           Eigen::Vector3d::UnitZ()};
  const urdf::Link* link = &bone_link;
  for (int dof = static_cast<int>(kDofsPerJoint) - 1; dof >= 0; --dof) {
    const urdf::JointSharedPtr& urdf_joint = link->parent_joint;
    if (!urdf_joint || !isRotational(*urdf_joint)) {
      throw SkeletonError("URDF link '" + link->name + "' must hang from a revolute joint (DOF '" + kDofNames[dof] +
                          "' of joint '" + bone.name + "'), found " +
                          (urdf_joint ? "joint '" + urdf_joint->name + "' of another type" : "none"));
    }
    if ((toEigen(urdf_joint->axis) - axes[dof]).norm() > kAxisTolerance) {
      throw SkeletonError("URDF joint '" + urdf_joint->name + "' must turn about the " + kDofNames[dof] +
                          " axis (DOF " + std::to_string(dof) + " of '" + bone.name + "' in chain order y, x, z)");
    }
    joint.urdf_joints[dof] = urdf_joint->name;
    if (dof > 0 && !isIdentity(urdf_joint->parent_to_joint_origin_transform)) {
      throw SkeletonError("URDF joint '" + urdf_joint->name +
                          "' must have an identity origin: only the first joint of a 3-DOF chain is offset");
    }
    const urdf::LinkConstSharedPtr parent = model.getLink(urdf_joint->parent_link_name);
    if (!parent) throw SkeletonError("URDF joint '" + urdf_joint->name + "' has no parent link");
    if (dof > 0) {
      if (parent->child_joints.size() != 1 || !parent->visual_array.empty()) {
        throw SkeletonError("URDF link '" + parent->name + "' between the DOFs of '" + bone.name +
                            "' must be a bare link with exactly one child joint");
      }
      joint.intermediate_links[dof - 1] = parent->name;
    } else {
      bone.rest_translation = toEigen(urdf_joint->parent_to_joint_origin_transform.position);
      bone.rest_rotation = toEigen(urdf_joint->parent_to_joint_origin_transform.rotation);
      return parent;
    }
    link = parent.get();
  }
  return nullptr;  // unreachable: the loop returns at dof 0
}

bool validSuffix(const std::string& suffix) {
  return suffix.empty() || (suffix[0] == '_' && isHumanId(suffix.substr(1)));
}

void readBoneCylinder(const urdf::Link& link, Bone& bone) {
  for (const urdf::VisualSharedPtr& visual : link.visual_array) {
    if (!visual || !visual->geometry || visual->geometry->type != urdf::Geometry::CYLINDER) continue;
    const auto& cylinder = static_cast<const urdf::Cylinder&>(*visual->geometry);
    const urdf::Pose& origin = visual->origin;
    if (toEigen(origin.rotation).angularDistance(Eigen::Quaterniond::Identity()) > kAxisTolerance ||
        std::abs(origin.position.x) > kAxisTolerance || std::abs(origin.position.y) > kAxisTolerance) {
      throw SkeletonError("URDF link '" + link.name + "': its cylinder visual must lie on the bone's z axis");
    }
    bone.length = origin.position.z + cylinder.length / 2.0;
    bone.radius = cylinder.radius;
    if (!(bone.length > 0.0) || !(bone.radius > 0.0)) {
      throw SkeletonError("URDF link '" + link.name + "': its cylinder visual gives a bone length " +
                          std::to_string(bone.length) + " m and radius " + std::to_string(bone.radius) +
                          " m; both must be positive");
    }
    return;
  }
  throw SkeletonError("URDF link '" + link.name +
                      "' has no cylinder visual: the cylinder on the bone's z axis defines the bone length");
}

}  // namespace

const std::array<BoneLayoutEntry, kBoneCount>& humanBoneLayout() {
  static const std::array<BoneLayoutEntry, kBoneCount> layout = {{
      {"waist", "lower spine (abdomen)", true},
      {"torso", "upper spine (chest)", true},
      {"neck", "neck", true},
      {"head", "head", true},
      {"l_clavicle", "left clavicle", false},
      {"l_shoulder", "left upper arm", true},
      {"l_elbow", "left forearm", true},
      {"l_wrist", "left hand", true},
      {"r_clavicle", "right clavicle", false},
      {"r_shoulder", "right upper arm", true},
      {"r_elbow", "right forearm", true},
      {"r_wrist", "right hand", true},
      {"l_pelvis", "left hip bone", false},
      {"l_hip", "left thigh", true},
      {"l_knee", "left shank", true},
      {"l_ankle", "left foot", true},
      {"r_pelvis", "right hip bone", false},
      {"r_hip", "right thigh", true},
      {"r_knee", "right shank", true},
      {"r_ankle", "right foot", true},
  }};
  return layout;
}

Skeleton Skeleton::fromUrdfFile(const std::string& path) {
  const std::string text = readWholeFileOrThrow<SkeletonError>(path, "the URDF file");
  try {
    return fromUrdf(text);
  } catch (const SkeletonError& error) {
    throw SkeletonError(path + ": " + error.what());
  }
}

Skeleton Skeleton::fromUrdf(const std::string& urdf_xml) {
  if (urdf_xml.find_first_not_of(" \t\r\n") == std::string::npos) {
    throw SkeletonError("the URDF text is empty");
  }
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf_xml);
  if (!model) throw SkeletonError("the URDF text could not be parsed (urdfdom rejected it; see its message above)");
  const urdf::LinkConstSharedPtr root = model->getRoot();
  if (!root || root->name.rfind("body", 0) != 0) {
    throw SkeletonError("the URDF root link must be 'body' or 'body_<id>', found '" + (root ? root->name : "") + "'");
  }

  Skeleton skeleton;
  skeleton.suffix_ = root->name.substr(4);
  const std::string& suffix = skeleton.suffix_;
  if (!validSuffix(suffix)) {
    throw SkeletonError("the URDF root link '" + root->name +
                        "' must be 'body' or 'body_<id>' with an alphanumeric id");
  }

  const auto& layout = humanBoneLayout();
  for (std::size_t index = 0; index < kBoneCount; ++index) {
    Bone bone;
    bone.name = layout[index].name;
    bone.anatomical = layout[index].anatomical;
    const std::string link_name = bone.name + suffix;
    const urdf::LinkConstSharedPtr link = model->getLink(link_name);
    if (!link) {
      throw SkeletonError("the URDF has no link '" + link_name + "' (the " + bone.anatomical + ", with " +
                          describeSuffix(suffix) + " taken from the root link)");
    }
    readBoneCylinder(*link, bone);

    urdf::LinkConstSharedPtr parent_link;
    if (layout[index].articulated) {
      ArticulatedJoint joint;
      joint.name = bone.name;
      joint.bone = static_cast<int>(index);
      parent_link = readArticulatedChain(*model, *link, joint, bone);
      bone.joint = static_cast<int>(skeleton.joints_.size());
      skeleton.joints_.push_back(joint);
    } else {
      const urdf::JointSharedPtr& fixed = link->parent_joint;
      if (!fixed || fixed->type != urdf::Joint::FIXED) {
        throw SkeletonError("URDF link '" + link_name + "' (the " + bone.anatomical + ") must hang from a fixed joint");
      }
      bone.rest_translation = toEigen(fixed->parent_to_joint_origin_transform.position);
      bone.rest_rotation = toEigen(fixed->parent_to_joint_origin_transform.rotation);
      parent_link = model->getLink(fixed->parent_link_name);
    }

    const std::string expected_parent = std::string(kLayoutParents[index].parent) + suffix;
    if (!parent_link || parent_link->name != expected_parent) {
      throw SkeletonError("URDF link '" + link_name + "' (the " + bone.anatomical + ") must be attached to '" +
                          expected_parent + "', found '" + (parent_link ? parent_link->name : "") + "'");
    }
    bone.parent = skeleton.findBone(kLayoutParents[index].parent);
    skeleton.bones_.push_back(bone);
  }
  // A generated URDF carries its shape in the numbers: the skeleton is the unshaped one.
  skeleton.body_shape_ = urdfBodyShape(urdf_xml);
  for (Bone& bone : skeleton.bones_) {
    const Eigen::Vector3d& own = skeleton.body_shape_.scale[static_cast<std::size_t>(&bone - skeleton.bones_.data())];
    bone.rest_translation -= skeleton.body_shape_.offset[static_cast<std::size_t>(&bone - skeleton.bones_.data())];
    if (bone.parent >= 0) {
      bone.rest_translation =
          bone.rest_translation.cwiseQuotient(skeleton.body_shape_.scale[static_cast<std::size_t>(bone.parent)]);
    }
    bone.length /= own.z();
    bone.radius /= 0.5 * (own.x() + own.y());
  }
  return skeleton;
}

Skeleton Skeleton::withSuffix(const std::string& suffix) const {
  if (!validSuffix(suffix)) {
    throw SkeletonError("the frame suffix '" + suffix + "' must be empty or '_<id>' with an alphanumeric id");
  }
  Skeleton renamed = *this;
  const auto rename = [&](std::string& name) { name = name.substr(0, name.size() - suffix_.size()) + suffix; };
  for (ArticulatedJoint& joint : renamed.joints_) {
    for (std::string& name : joint.urdf_joints) rename(name);
    for (std::string& name : joint.intermediate_links) rename(name);
  }
  renamed.suffix_ = suffix;
  return renamed;
}

Skeleton Skeleton::withBodyShape(const BodyShape& shape) const {
  Skeleton shaped = *this;
  shaped.body_shape_ = shape;
  return shaped;
}

bool isHumanId(const std::string& id) {
  return !id.empty() && std::all_of(id.begin(), id.end(), [](unsigned char c) { return std::isalnum(c) != 0; });
}

std::vector<std::string> humanSuffixesAmong(const std::vector<std::string>& frames) {
  const std::set<std::string> known(frames.begin(), frames.end());
  const std::string first_bone = humanBoneLayout()[0].name;
  std::vector<std::string> suffixes;
  for (const std::string& frame : known) {
    if (frame.rfind("body", 0) != 0) continue;
    const std::string suffix = frame.substr(4);
    if (validSuffix(suffix) && known.count(first_bone + suffix) != 0) suffixes.push_back(suffix);
  }
  return suffixes;  // sorted: the set is
}

int Skeleton::findBone(const std::string& name) const {
  for (std::size_t i = 0; i < bones_.size(); ++i) {
    if (bones_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int Skeleton::findJoint(const std::string& name) const {
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    if (joints_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace dressed_human
