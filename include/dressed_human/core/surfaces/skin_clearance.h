// Signed clearance of a point over the skin, from the body description's cross-sections (the
// data the skin patches are built from): per skin segment, the elliptic section at the point's
// height in the bone frame (linear between sections; a joined child's joint ring closes the
// parent's profile; caps as half-ellipsoids), posed by the bone frames. Positive outside.
// It is the skin's rest cross-section model, not the tessellated Bezier surface: near joints
// the real skin's joint ring bisects the bend, which this model does not reproduce.
#pragma once

#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/skeleton/skeleton.h"
#include "dressed_human/core/surfaces/skin.h"

#include <Eigen/Core>

#include <array>
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
  double clearance(const SkeletonPose& pose, const Eigen::Vector3d& p,
                   const std::vector<std::size_t>& segments = {}) const;

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

// Signed clearance over the REAL posed skin (skin.h): the Skin's bicubic patches, posed by
// Skin::pose, sampled on a fine uniform grid per patch (default 16 x 16 quads: chord error well
// under 0.1 mm on the default body) and triangulated. The skin is a union of closed parts
// (trunk, limbs, clavicles; skin.h), so the clearance of p is min over parts of p's signed
// distance to that part: the distance to the part's nearest triangle, negative when p is inside
// it (sign of (p - q) . n at the nearest point q, n the outward normal F_u x F_v of its
// triangle; exact for a closed mesh away from ties). Positive outside the whole body.
// Search: per patch an axis-aligned box; parts and patches whose box is farther than the best
// answer so far are skipped (exact, not an approximation).
class SkinSurfaceClearance {
 public:
  SkinSurfaceClearance(const Skeleton& skeleton, const BodyDescription& body, int grid = 16);

  // Poses the skin (ForwardKinematics output with body.shape) and rebuilds the triangles.
  void pose(const SkeletonPose& pose);
  const Skin& skin() const { return skin_; }

  // Signed distance of world point p over the posed skin (metres, positive outside).
  double clearance(const Eigen::Vector3d& p) const;
  // The same with the skin part (Skin::segments()[s].part) that decided it.
  double clearance(const Eigen::Vector3d& p, std::size_t& part) const;
  // Over the given parts only (all when empty): layering, e.g. a sleeve against the arm.
  double clearance(const Eigen::Vector3d& p, const std::vector<std::size_t>& parts, std::size_t& part) const;
  // The parts holding the segments of these bones ("body" for the pelvis segment).
  std::vector<std::size_t> partsOf(const std::vector<std::string>& segment_names) const;

 private:
  struct Triangle {
    Eigen::Vector3d a, b, c, normal;  // normal: unit, outward; zero for a degenerate triangle
  };
  struct PatchBox {
    Eigen::Vector3d lo, hi;
    std::size_t first = 0, count = 0;  // triangles_
  };
  Skin skin_;
  int grid_;
  std::vector<std::vector<std::size_t>> part_patches_;
  std::vector<Triangle> triangles_;
  std::vector<PatchBox> boxes_;
};

}  // namespace dressed_human
