#include "dressed_human/core/locomotion/symmetric_walk.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "dressed_human/core/locomotion/normative_gait.h"
#include "dressed_human/core/locomotion/route.h"

namespace dressed_human {
namespace {

constexpr double kProbeAngle = 0.1;       // rad: how far each DOF is moved to see its mirror
constexpr double kRestTolerance = 0.001;  // m: the skeleton's two sides at rest
constexpr double kMirrorCorrelation = 0.9;

std::string mirrorName(const std::string& name) {
  if (name.rfind("l_", 0) == 0) return "r_" + name.substr(2);
  if (name.rfind("r_", 0) == 0) return "l_" + name.substr(2);
  return name;
}

Eigen::Vector3d reflected(const Eigen::Vector3d& v) { return {v.x(), -v.y(), v.z()}; }

// Points fixed in each bone's frame; a bone's mirror carries them reflected in its own frame
// (y -> -y), the convention of the URDF and of the garments' mirrored bones.
constexpr std::array<std::array<double, 3>, 4> kBonePoints = {
    {{0.0, 0.0, 0.0}, {0.1, 0.0, 0.0}, {0.0, 0.1, 0.0}, {0.0, 0.0, 0.1}}};

class MirrorProbe {
 public:
  explicit MirrorProbe(const Skeleton& skeleton) : kinematics_(skeleton) {
    for (std::size_t b = 0; b < skeleton.bones().size(); ++b) {
      const int m = skeleton.findBone(mirrorName(skeleton.bone(b).name));
      if (m < 0) throw LocomotionError("bone " + skeleton.bone(b).name + " has no mirror image in the skeleton");
      mirror_bone_.push_back(static_cast<std::size_t>(m));
    }
    JointAngles rest{};
    const std::vector<Eigen::Vector3d> at_rest = points(rest, false), mirrored = points(rest, true);
    for (std::size_t i = 0; i < at_rest.size(); ++i) {
      if ((reflected(at_rest[i]) - mirrored[i]).norm() > kRestTolerance) {
        const std::size_t bone = i / kBonePoints.size();
        throw LocomotionError("bone " + skeleton.bone(bone).name + " is not the mirror image of bone " +
                              skeleton.bone(mirror_bone_[bone]).name + " at rest: the skeleton's two sides differ");
      }
    }
    rest_ = at_rest;
  }

  // +1 or -1: how DOF `dof` of joint `joint` maps onto the same DOF of `mirror`.
  double sign(std::size_t joint, std::size_t mirror, std::size_t dof) const {
    JointAngles moved{};
    moved[joint * kDofsPerJoint + dof] = kProbeAngle;
    const std::vector<Eigen::Vector3d> own = points(moved, false);
    moved = JointAngles{};
    moved[mirror * kDofsPerJoint + dof] = kProbeAngle;
    const std::vector<Eigen::Vector3d> partner = points(moved, true);
    double dot = 0.0, own_norm = 0.0, partner_norm = 0.0;
    for (std::size_t i = 0; i < own.size(); ++i) {
      const Eigen::Vector3d a = reflected(own[i] - rest_[i]), b = partner[i] - reflected(rest_[i]);
      dot += a.dot(b);
      own_norm += a.squaredNorm();
      partner_norm += b.squaredNorm();
    }
    const double correlation = dot / std::sqrt(own_norm * partner_norm + 1e-30);
    if (std::abs(correlation) < kMirrorCorrelation) {
      const Skeleton& s = kinematics_.skeleton();
      throw LocomotionError("DOF " + std::string(kDofNames[dof]) + " of joint " + s.joint(joint).name +
                            " has no mirror image in joint " + s.joint(mirror).name + " (correlation " +
                            std::to_string(correlation) + ")");
    }
    return correlation > 0.0 ? 1.0 : -1.0;
  }

 private:
  // Every bone's points; `mirrored`: each slot holds its mirror bone's points, reflected in that
  // bone's frame, so that a symmetric pose gives the reflection of the unmirrored list.
  std::vector<Eigen::Vector3d> points(const JointAngles& angles, bool mirrored) const {
    kinematics_.compute(RigidTransform(), angles, pose_);
    std::vector<Eigen::Vector3d> out;
    for (std::size_t b = 0; b < mirror_bone_.size(); ++b) {
      const RigidTransform& frame = pose_.bone_in_world[mirrored ? mirror_bone_[b] : b];
      for (const std::array<double, 3>& p : kBonePoints) {
        const Eigen::Vector3d local(p[0], mirrored ? -p[1] : p[1], p[2]);
        out.push_back(frame.translation + frame.rotation * local);
      }
    }
    return out;
  }

  ForwardKinematics kinematics_;
  std::vector<std::size_t> mirror_bone_;
  std::vector<Eigen::Vector3d> rest_;
  mutable SkeletonPose pose_;
};

FourierSeries halfACycleLater(const FourierSeries& series) {
  FourierSeries later = series;
  later.phase += M_PI;
  return inCycles(later);
}

// (series + sign * partner half a cycle later) / 2.
FourierSeries mirroredMean(const FourierSeries& series, const FourierSeries& partner, double sign) {
  FourierSeries mean = sumOf(series, halfACycleLater(partner), sign);
  mean.a0 *= 0.5;
  for (double& c : mean.a) c *= 0.5;
  for (double& c : mean.b) c *= 0.5;
  return mean;
}

}  // namespace

Motion symmetricWalk(const Motion& walk_in_cycles, const Skeleton& skeleton) {
  const MirrorProbe probe(skeleton);
  Motion symmetric = walk_in_cycles;
  for (std::size_t j = 0; j < skeleton.joints().size(); ++j) {
    const int mirror = skeleton.findJoint(mirrorName(skeleton.joint(j).name));
    if (mirror < 0) throw LocomotionError("joint " + skeleton.joint(j).name + " has no mirror image in the skeleton");
    const std::size_t m = static_cast<std::size_t>(mirror);
    for (std::size_t d = 0; d < kDofsPerJoint; ++d) {
      symmetric.dofs[j * kDofsPerJoint + d] = mirroredMean(
          walk_in_cycles.dofs[j * kDofsPerJoint + d], walk_in_cycles.dofs[m * kDofsPerJoint + d], probe.sign(j, m, d));
    }
  }
  // Reflected through the sagittal plane, Rz(yaw) Ry(pitch) Rx(roll) keeps its pitch and negates
  // its roll and yaw; the root keeps its x and z and negates its y.
  constexpr std::array<double, 3> kRotationSigns = {-1.0, 1.0, -1.0}, kTranslationSigns = {1.0, -1.0, 1.0};
  for (std::size_t k = 0; k < 3; ++k) {
    symmetric.root.rotation[k] =
        mirroredMean(walk_in_cycles.root.rotation[k], walk_in_cycles.root.rotation[k], kRotationSigns[k]);
    symmetric.root.translation[k] =
        mirroredMean(walk_in_cycles.root.translation[k], walk_in_cycles.root.translation[k], kTranslationSigns[k]);
  }
  return symmetric;
}

}  // namespace dressed_human
