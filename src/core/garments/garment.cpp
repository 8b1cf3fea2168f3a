#include "dressed_human/core/garments/garment.h"

#include "dressed_human/core/garments/skirt_length_map.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>

namespace dressed_human {
namespace {

// Off-curve point I (I % 3 != 0) of a Bezier circle of `columns` arcs starting at angle
// `start`: unit-circle coordinates (cos-like, sin-like). The on-curve points (I % 3 == 0) are
// the midpoints of their two neighbours: the circle obeys the midpoint rule by construction.
Eigen::Vector2d circlePoint(int columns, double start, int index) {
  const double arc = 2.0 * M_PI / columns;
  const double k = 4.0 / 3.0 * std::tan(arc / 4.0);
  const int column = index / 3;
  const bool first = index % 3 == 1;
  const double angle = start + arc * (first ? column : column + 1);
  const Eigen::Vector2d e(std::cos(angle), std::sin(angle));
  const Eigen::Vector2d t(-std::sin(angle), std::cos(angle));
  return first ? Eigen::Vector2d(e + k * t) : Eigen::Vector2d(e - k * t);
}

Eigen::Vector3d mirrored(const Eigen::Vector3d& p) { return Eigen::Vector3d(p.x(), -p.y(), p.z()); }

std::string mirrorName(const std::string& name) { return "r_" + name.substr(2); }
bool isLeft(const std::string& name) { return name.rfind("l_", 0) == 0; }

// A ring lattice: (3 * columns) points around, J rows; idx[J][I].
struct Lattice {
  int columns = 4;
  int patch_rows = 1;
  int tube_row = -1;  // patch rows >= this are two tubes of columns/2 patches (pants)
  std::vector<std::vector<std::int64_t>> idx;
  int around() const { return 3 * columns; }
  int lastRow() const { return 3 * patch_rows; }
  bool tubeRow(int j) const { return tube_row >= 0 && j > 3 * tube_row; }
  std::pair<int, int> uNeighbours(int i, int j) const {
    const int n = around();
    if (tubeRow(j)) {
      const int half = n / 2;
      const int base = (i / half) * half;
      return {base + (i - base + half - 1) % half, base + (i - base + 1) % half};
    }
    return {(i + n - 1) % n, (i + 1) % n};
  }
  // Lattice column of patch column pc, control column c (0..3).
  int column(int patch_row, int pc, int c) const {
    const int n = around();
    if (tube_row >= 0 && patch_row >= tube_row) {
      const int half = n / 2;
      const int base = ((3 * pc) / half) * half;
      return base + (3 * pc + c - base) % half;
    }
    return (3 * pc + c) % n;
  }
};

class Builder {
 public:
  Builder(const GarmentDescription& d, const Skeleton& skeleton, const BodyShape& shape, GarmentControlNet& net)
      : d_(d), skeleton_(skeleton), shape_(shape), net_(net) {
    ForwardKinematics fk(skeleton, shape);
    JointAngles zero{};
    zero.fill(0.0);
    fk.compute(RigidTransform(), zero, rest_);
  }

  int boneOf(const std::string& frame) const {
    if (frame == "body") return kRootFrame;
    const int b = skeleton_.findBone(frame);
    if (b < 0) throw GarmentError(d_.name + ": unknown frame '" + frame + "'");
    return b;
  }

  Eigen::Vector3d scaled(int bone, const Eigen::Vector3d& p) const {
    return bone == kRootFrame ? p : Eigen::Vector3d(p.cwiseProduct(shape_.scale[static_cast<std::size_t>(bone)]));
  }

  // Body front and left in a bone frame at rest, made perpendicular to the bone's z axis.
  void axes(int bone, Eigen::Vector3d& front, Eigen::Vector3d& left) const {
    const Eigen::Matrix3d r = bone == kRootFrame
                                  ? Eigen::Matrix3d::Identity()
                                  : rest_.bone_in_world[static_cast<std::size_t>(bone)].rotation.toRotationMatrix();
    front = r.transpose() * Eigen::Vector3d::UnitX();
    left = r.transpose() * Eigen::Vector3d::UnitY();
    front.z() = 0.0;
    front.normalize();
    left -= left.dot(Eigen::Vector3d::UnitZ()) * Eigen::Vector3d::UnitZ() + left.dot(front) * front;
    left.normalize();
  }

  // Unscaled local point of ring `r` at lattice index i of a ring of `columns` arcs from `start`.
  Eigen::Vector3d ringLocal(const GarmentRing& r, int columns, double start, int i, bool ease = true) const {
    Eigen::Vector3d front, left;
    axes(boneOf(r.frame), front, left);
    const Eigen::Vector2d c = circlePoint(columns, start, i);
    const double e = ease ? d_.ease : 0.0;
    return r.centre + (r.radius.x() + e) * c.x() * front + (r.radius.y() + e) * c.y() * left;
  }

  // Shape point of ring r at index i; left bones: the right half is the mirror (index n - i).
  ShapeAttachment ringPoint(const GarmentRing& r, int columns, double start, int i, bool right_half) const {
    ShapeAttachment a;
    const int n = 3 * columns;
    if (isLeft(r.frame) && right_half) {
      a.bone = boneOf(mirrorName(r.frame));
      a.local = scaled(a.bone, mirrored(ringLocal(r, columns, start, (n - i) % n)));
    } else {
      a.bone = boneOf(r.frame);
      a.local = scaled(a.bone, ringLocal(r, columns, start, i));
    }
    return a;
  }

  // Eq. 8' point of the legs rings at normalized length c.
  ShapeAttachment legPoint(int columns, double start, int i, bool right_half, double c) const {
    const GarmentLegs& legs = d_.legs;
    const int n = 3 * columns;
    const int k = right_half ? (n - i) % n : i;
    const std::string upper_name = right_half ? mirrorName(legs.knee.frame) : legs.knee.frame;
    const std::string lower_name = right_half ? mirrorName(legs.long_hem.frame) : legs.long_hem.frame;
    const int upper = boneOf(upper_name);
    const int lower = boneOf(lower_name);
    auto side = [&](const Eigen::Vector3d& p) { return right_half ? mirrored(p) : p; };
    const Eigen::Vector3d p0 = scaled(upper, side(ringLocal(legs.top, columns, start, k)));
    const Eigen::Vector3d pi = scaled(upper, side(ringLocal(legs.knee, columns, start, k)));
    const Eigen::Vector3d qj = scaled(lower, side(ringLocal(legs.long_hem, columns, start, k)));
    // P^j = Q^j - M_rest^-1 P^i: from the knee-length hem to the long hem, in frame j.
    const RigidTransform& m = rest_.bone_in_parent[static_cast<std::size_t>(lower)];
    const Eigen::Vector3d pj = qj - m.rotation.conjugate() * (pi - m.translation);
    const SkirtLengthWeights w = skirtLengthWeights(c, boneLength(upper), boneLength(lower));
    if (d_.type == GarmentType::kPants && w.aj > 0.0) {
      // A trouser leg below the knee rides the shank alone (garment.h): the knee ring carried
      // into the shank's rest frame, blended toward the long hem by A_j.
      ShapeAttachment a;
      a.bone = lower;
      a.local = (1.0 - w.aj) * (m.rotation.conjugate() * (pi - m.translation)) + w.aj * qj;
      return a;
    }
    ShapeAttachment a;
    a.bone = upper;
    a.local = w.a0 * p0 + w.ai * pi;
    a.lower_bone = lower;
    a.lower_vector = pj;
    a.lower_weight = w.aj;
    return a;
  }

  double boneLength(int bone) const {
    return skeleton_.bone(static_cast<std::size_t>(bone)).length * shape_.scale[static_cast<std::size_t>(bone)].z();
  }

  // Creates the lattice points: shape points from `shape(i, j)`, then midpoints. `override_point`
  // may claim a lattice position first (returns >= 0).
  void fill(Lattice& lat, const std::string& piece, const std::function<ShapeAttachment(int, int)>& shape,
            const std::function<std::int64_t(int, int)>& override_point) {
    const int n = lat.around();
    const int rows = lat.lastRow() + 1;
    lat.idx.assign(static_cast<std::size_t>(rows), std::vector<std::int64_t>(static_cast<std::size_t>(n), -1));
    auto rim = [&](int j) { return j % 3 == 0 && j > 0 && j < lat.lastRow(); };
    for (int j = 0; j < rows; ++j) {
      for (int i = 0; i < n; ++i) {
        const std::int64_t o = override_point(i, j);
        if (o >= 0) lat.idx[j][i] = o;
      }
    }
    for (int j = 0; j < rows; ++j) {
      for (int i = 0; i < n; ++i) {
        if (lat.idx[j][i] >= 0 || i % 3 == 0 || rim(j)) continue;
        lat.idx[j][i] = net_.addShape(shape(i, j), piece);
      }
    }
    // Boundary midpoints: across the boundary lines between columns, then between rows.
    for (int j = 0; j < rows; ++j) {
      for (int i = 0; i < n; ++i) {
        if (lat.idx[j][i] >= 0) continue;
        if (i % 3 == 0 && !rim(j)) {
          const auto [a, b] = lat.uNeighbours(i, j);
          lat.idx[j][i] = net_.addMidpoint(ControlPointKind::kBoundaryMidpoint, at(lat, a, j), at(lat, b, j), piece);
        } else if (i % 3 != 0 && rim(j)) {
          lat.idx[j][i] =
              net_.addMidpoint(ControlPointKind::kBoundaryMidpoint, at(lat, i, j - 1), at(lat, i, j + 1), piece);
        }
      }
    }
    for (int j = 0; j < rows; ++j) {
      for (int i = 0; i < n; ++i) {
        if (lat.idx[j][i] >= 0) continue;
        const auto [a, b] = lat.uNeighbours(i, j);
        lat.idx[j][i] = net_.addMidpoint(ControlPointKind::kCornerMidpoint, at(lat, a, j), at(lat, b, j), piece);
      }
    }
  }

  static std::uint32_t at(const Lattice& lat, int i, int j) {
    const std::int64_t v = lat.idx[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)];
    if (v < 0) throw std::logic_error("garment lattice: a midpoint source is missing");
    return static_cast<std::uint32_t>(v);
  }

  void patches(const Lattice& lat, const std::function<std::string(int, int)>& piece) {
    for (int pr = 0; pr < lat.patch_rows; ++pr) {
      for (int pc = 0; pc < lat.columns; ++pc) {
        GarmentControlNet::PatchIndices p{};
        for (int a = 0; a < 4; ++a) {    // u: down the garment
          for (int b = 0; b < 4; ++b) {  // v: around, counter-clockwise from above
            p[BezierPatch::index(a, b)] = at(lat, lat.column(pr, pc, b), 3 * pr + a);
          }
        }
        net_.addPatch(p, piece(pr, pc));
      }
    }
  }

  void sleeves() {
    if (d_.sleeve.empty()) return;
    for (int side = 0; side < 2; ++side) {
      const std::string piece = side == 0 ? "l_sleeve" : "r_sleeve";
      Lattice lat;
      lat.columns = 2;
      lat.patch_rows = 1;
      fill(
          lat, piece,
          [&](int i, int j) { return ringPoint(d_.sleeve[static_cast<std::size_t>(j)], 2, -M_PI / 2, i, side == 1); },
          [](int, int) { return std::int64_t{-1}; });
      patches(lat, [&](int, int) { return piece; });
    }
  }

  double length_ = 0.0;
  double knee_ = 0.0;
  std::int64_t crotch_ = -1;

  using LatticePoints = std::vector<std::pair<std::pair<int, int>, std::uint32_t>>;  // (i, j) of the net, point

  // Pants: the crotch C (lattice (0, 3) = (n/2, 3), where the hips' front and back centre lines
  // end and both tubes' inseams start) and its twist ring: the eight control points diagonal
  // to C, one per patch: tangent projections of shape points on the crotch ellipse (garment.h).
  LatticePoints crotchPoints(int n) {
    LatticePoints crotch_points;
    const int bone = boneOf(d_.crotch_frame);
    ShapeAttachment a;
    a.bone = bone;
    a.local = scaled(bone, d_.crotch);
    const std::uint32_t c = net_.addShape(a, "crotch");
    crotch_ = c;
    crotch_points.push_back({{0, 3}, c});
    crotch_points.push_back({{n / 2, 3}, c});
    const int half = n / 2;
    // Lattice position of each patch's twist point at C, by the angle of its sector around C
    // (x front, y left): hips front-left, left leg front, left leg back, hips back-left, ...
    const std::pair<int, int> twist[8] = {{1, 2},        {1, 4},        {half - 1, 4}, {half - 1, 2},
                                          {half + 1, 2}, {half + 1, 4}, {n - 1, 4},    {n - 1, 2}};
    for (int k = 0; k < 8; ++k) {
      const double angle = M_PI / 8.0 + k * M_PI / 4.0;
      const bool leg_sector = twist[k].second > 3;
      const Eigen::Vector2d& radius = leg_sector ? d_.crotch_leg_radius : d_.crotch_radius;
      // Source: on the crotch ellipse, fixed in the crotch frame. (Riding the thighs instead
      // follows the legs better, but hip rotation then swaps the sources' order around C in
      // some walk poses, and the 8 sectors no longer go once around it: a fold.)
      ShapeAttachment t;
      t.bone = bone;
      t.local =
          a.local + scaled(bone, Eigen::Vector3d(radius.x() * std::cos(angle), radius.y() * std::sin(angle), 0.0));
      const std::uint32_t source = net_.addShape(t, "crotch");
      crotch_points.push_back({twist[k], net_.addTangentProjection(source, c, bone, "crotch")});
    }
    return crotch_points;
  }

  void build() {
    const GarmentType type = d_.type;
    Lattice lat;
    lat.columns = 4;
    std::vector<int> explicit_rows;  // lattice row of rows[k]
    std::vector<int> leg_rows;       // lattice rows of the leg's inner control rows, then the hem
    switch (type) {
      case GarmentType::kJacket:
        lat.patch_rows = 2;
        explicit_rows = {0, 1, 2, 4, 5, 6};
        break;
      case GarmentType::kSkirt:
        lat.patch_rows = 2;
        explicit_rows = {0, 1, 2};
        leg_rows = {4, 5, 6};
        break;
      // Two patch rows per trouser leg: one cubic from crotch to ankle cannot bend with the knee.
      case GarmentType::kPants:
        lat.patch_rows = 3;
        explicit_rows = {0, 1, 2};
        leg_rows = {4, 5, 7, 8, 9};
        break;
      case GarmentType::kOnePiece:
        lat.patch_rows = 4;
        explicit_rows = {0, 1, 2, 4, 5, 7, 8};
        leg_rows = {10, 11, 12};
        break;
    }
    if (d_.rows.size() != explicit_rows.size()) {
      throw GarmentError(d_.name + ": a " + garmentTypeName(type) + " needs " + std::to_string(explicit_rows.size()) +
                         " shape rows, got " + std::to_string(d_.rows.size()));
    }
    std::vector<double> fractions = d_.legs.row_fractions;
    if (!leg_rows.empty()) {
      const std::size_t inner = leg_rows.size() - 1;
      if (fractions.empty()) {
        for (std::size_t k = 1; k <= inner; ++k)
          fractions.push_back(static_cast<double>(k) / static_cast<double>(inner + 1));
      }
      if (fractions.size() != inner) {
        throw GarmentError(d_.name + ": a " + garmentTypeName(type) + " needs " + std::to_string(inner) +
                           " leg row fractions, got " + std::to_string(fractions.size()));
      }
      for (std::size_t k = 0; k < inner; ++k) {
        if (!(fractions[k] > (k == 0 ? 0.0 : fractions[k - 1]) && fractions[k] < 1.0)) {
          throw GarmentError(d_.name + ": leg row fractions must increase strictly within (0, 1)");
        }
      }
      fractions.push_back(1.0);
      const int upper = boneOf(d_.legs.knee.frame);
      const int lower = boneOf(d_.legs.long_hem.frame);
      knee_ = kneeLength(boneLength(upper), boneLength(lower));
      length_ = d_.legs.at_knee ? knee_ : d_.legs.length;
      // A trouser leg of length 0 is a curve (every leg row on the crotch ring): no tangent
      // plane to tessellate. The shortest leg is a micrometre; a skirt at 0 stays a surface.
      if (type == GarmentType::kPants) length_ = std::max(length_, Garment::kShortestPantsLeg);
    }
    const bool pants = type == GarmentType::kPants;
    if (pants) lat.tube_row = 1;
    const int n = lat.around();

    const LatticePoints crotch_points = pants ? crotchPoints(n) : LatticePoints{};
    auto override_point = [&](int i, int j) -> std::int64_t {
      for (const auto& [at_ij, point] : crotch_points) {
        if (at_ij == std::make_pair(i, j)) return point;
      }
      return -1;
    };
    const std::string upper_piece = type == GarmentType::kJacket     ? "torso"
                                    : type == GarmentType::kOnePiece ? "bodice"
                                                                     : "hips";
    auto shape = [&](int i, int j) -> ShapeAttachment {
      const bool right = i > n / 2;
      for (std::size_t k = 0; k < explicit_rows.size(); ++k) {
        if (explicit_rows[k] == j) return ringPoint(d_.rows[k], 4, 0.0, i, right);
      }
      std::size_t r = 0;
      while (r + 1 < leg_rows.size() && leg_rows[r] != j) ++r;
      const double c = length_ * fractions[r];
      if (pants) {
        const int half = n / 2;
        const bool right_leg = i >= half;
        return legPoint(2, -M_PI / 2, right_leg ? i - half : i, right_leg, c);
      }
      return legPoint(4, 0.0, i, right, c);
    };
    fill(lat, upper_piece, shape, override_point);
    patches(lat, [&](int pr, int pc) -> std::string {
      if (pants && pr >= 1) return pc < 2 ? "l_leg" : "r_leg";
      if (type == GarmentType::kSkirt || type == GarmentType::kPants) return pr == 0 ? "hips" : "skirt";
      if (type == GarmentType::kOnePiece && pr >= 2) return "skirt";
      return upper_piece;
    });
    sleeves();
    net_.finish();
  }

 private:
  const GarmentDescription& d_;
  const Skeleton& skeleton_;
  const BodyShape& shape_;
  GarmentControlNet& net_;
  SkeletonPose rest_;
};

}  // namespace

Garment::Garment(const GarmentDescription& description, const Skeleton& skeleton, const BodyShape& shape)
    : description_(description) {
  if (description_.type == GarmentType::kJacket && description_.sleeve.size() != 4) {
    throw GarmentError(description_.name + ": a jacket needs 4 sleeve rows, got " +
                       std::to_string(description_.sleeve.size()));
  }
  if (!description_.sleeve.empty() && description_.sleeve.size() != 4) {
    throw GarmentError(description_.name + ": a sleeve needs 4 rows, got " +
                       std::to_string(description_.sleeve.size()));
  }
  Builder builder(description_, skeleton, shape, net_);
  try {
    builder.build();
  } catch (const std::invalid_argument& error) {
    throw GarmentError(description_.name + ": " + error.what());
  }
  knee_length_ = builder.knee_;
  length_ = builder.length_;
  crotch_ = builder.crotch_;
  SkeletonPose rest;
  ForwardKinematics fk(skeleton, shape);
  JointAngles zero{};
  zero.fill(0.0);
  fk.compute(RigidTransform(), zero, rest);
  net_.pose(rest);
}

}  // namespace dressed_human
