// Signed clearance of a point over the skin, from the body description's cross-sections (the
// data the skin patches are built from): per skin segment, the elliptic section at the point's
// height in the bone frame (linear between sections; a joined child's joint ring closes the
// parent's profile; caps as half-ellipsoids), posed by the bone frames. Positive outside.
// It is the skin's rest cross-section model, not the tessellated Bezier surface: near joints
// the real skin's joint ring bisects the bend, which this model does not reproduce.
#pragma once

#include "dressed_human/core/body_description.h"
#include "dressed_human/core/forward_kinematics.h"
#include "dressed_human/core/skeleton.h"

#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

namespace dressed_human {

class SkinClearance {
 public:
  SkinClearance(const Skeleton& skeleton, const BodyDescription& body, const BodyShape& shape);

  std::size_t segmentCount() const { return segments_.size(); }
  const std::string& segmentName(std::size_t s) const { return segments_.at(s).name; }
  int segmentBone(std::size_t s) const { return segments_.at(s).bone; }
  // Segment indices whose bone name is in `names` ("body" for the pelvis segment).
  std::vector<std::size_t> segmentsNamed(const std::vector<std::string>& names) const;

  // Clearance of world point p over segment s in `pose`: distance from the section ellipse
  // (measured radially from the bone axis), +infinity beyond the segment's ends and caps.
  double clearance(const SkeletonPose& pose, std::size_t s, const Eigen::Vector3d& p) const;
  // Minimum over the given segments (all when empty).
  double clearance(const SkeletonPose& pose, const Eigen::Vector3d& p, const std::vector<std::size_t>& segments = {}) const;

  // The sections of segment s (z, radius_x, radius_y; Eq. 5 applied), caps as heights.
  struct Profile {
    std::string name;
    int bone = -1;
    std::vector<Eigen::Vector3d> sections;
    double proximal_cap = 0.0;
    double distal_cap = 0.0;
  };
  const Profile& profile(std::size_t s) const { return segments_.at(s); }

 private:
  std::vector<Profile> segments_;
};

}  // namespace dressed_human
