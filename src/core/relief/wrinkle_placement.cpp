#include "dressed_human/core/relief/wrinkle_placement.h"

#include "dressed_human/core/relief/wrinkle_map.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <optional>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace dressed_human {
namespace {

template <typename T>
std::string str(const T& value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// Eigen-decomposition of M = G_rest^-1 G_posed, written out for 2x2 so that M = I gives
// eigenvalues 1 to rounding (the usual tr/2 +- sqrt(tr^2/4 - det) loses half the digits at a
// double eigenvalue: 1e-16 under the root becomes 1e-8).
template <typename Scalar>
struct Stretch2 {
  Scalar lambda_min, lambda_max, m11, m12, m21, m22;
};

template <typename Scalar>
Stretch2<Scalar> stretchEigen(Scalar a, Scalar b, Scalar c, Scalar inverse_det, Scalar e, Scalar f, Scalar g) {
  Stretch2<Scalar> s;
  s.m11 = a * e + b * f;
  s.m12 = a * f + b * g;
  s.m21 = b * e + c * f;
  s.m22 = b * f + c * g;
  const Scalar half_trace = (s.m11 + s.m22) / 2;
  const Scalar half_difference = (s.m11 - s.m22) / 2;
  const Scalar disc = std::sqrt(std::max(Scalar(0), half_difference * half_difference + s.m12 * s.m21));
  s.lambda_max = half_trace + disc;
  // det M / lambda_max: no cancellation when the smaller eigenvalue is small.
  const Scalar det_m = inverse_det * (e * g - f * f);
  s.lambda_min = s.lambda_max > Scalar(0) ? std::max(Scalar(0), det_m / s.lambda_max) : Scalar(0);
  return s;
}

void requireUnit(double value, const char* name) {
  if (!(value >= 0.0 && value <= 1.0)) {
    throw std::invalid_argument(std::string(name) + " must be in [0, 1], got " + str(value));
  }
}

double quantile(std::vector<double> values, double fraction) {
  if (values.empty()) return 1.0;
  const std::size_t k = static_cast<std::size_t>(std::floor(fraction * static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

double curveLength(const BezierPatch& patch, bool along_u, double fixed) {
  constexpr int kSegments = 24;
  double length = 0.0;
  Eigen::Vector3d previous = along_u ? patch.position(0.0, fixed) : patch.position(fixed, 0.0);
  for (int k = 1; k <= kSegments; ++k) {
    const double t = static_cast<double>(k) / kSegments;
    const Eigen::Vector3d point = along_u ? patch.position(t, fixed) : patch.position(fixed, t);
    length += (point - previous).norm();
    previous = point;
  }
  return length;
}

PatternKind firstKind(FoldChain chain) {
  switch (chain) {
    case FoldChain::kI:
      return PatternKind::I;
    case FoldChain::kYY:
      return PatternKind::Y;
    case FoldChain::kX:
      return PatternKind::X;
  }
  throw std::invalid_argument("unknown fold chain " + std::to_string(static_cast<int>(chain)));
}

}  // namespace

void checkWrinklePlacementOptions(const WrinklePlacementOptions& o) {
  if (!(o.alpha_threshold > 0.0 && o.alpha_threshold <= 1.0)) {
    throw std::invalid_argument("WrinklePlacementOptions.alpha_threshold must be in (0, 1], got " +
                                str(o.alpha_threshold));
  }
  if (!(o.region_percentile >= 0.0 && o.region_percentile <= 1.0)) {
    throw std::invalid_argument("WrinklePlacementOptions.region_percentile must be in [0, 1], got " +
                                str(o.region_percentile));
  }
  if (o.samples_per_side < 2) {
    throw std::invalid_argument("WrinklePlacementOptions.samples_per_side must be >= 2, got " +
                                str(o.samples_per_side));
  }
  if (!(o.cell_length > 0.0) || !(o.knee_half_width > 0.0) || !(o.elbow_half_width > 0.0) ||
      !(o.waist_half_width > 0.0) || !(o.span_half_length > 0.0)) {
    throw std::invalid_argument(
        "WrinklePlacementOptions: cell_length, span_half_length and the region half widths must be > 0");
  }
  if (o.cells_around < 2 || o.cells_around % 2 != 0) {
    throw std::invalid_argument(
        "WrinklePlacementOptions.cells_around must be even and >= 2 (a YY chain must close), got " +
        str(o.cells_around));
  }
  if (!(o.reference_alpha > 0.0 && o.reference_alpha < 1.0)) {
    throw std::invalid_argument("WrinklePlacementOptions.reference_alpha must be in (0, 1), got " +
                                str(o.reference_alpha));
  }
  if (!(o.saturation_alpha >= 0.0 && o.saturation_alpha < o.alpha_threshold)) {
    throw std::invalid_argument("WrinklePlacementOptions.saturation_alpha must be in [0, alpha_threshold), got " +
                                str(o.saturation_alpha));
  }
}

PrincipalStretch principalStretch(const Eigen::Vector3d& rest_du, const Eigen::Vector3d& rest_dv,
                                  const Eigen::Vector3d& posed_du, const Eigen::Vector3d& posed_dv) {
  PrincipalStretch result;
  const double er = rest_du.squaredNorm(), fr = rest_du.dot(rest_dv), gr = rest_dv.squaredNorm();
  const double ep = posed_du.squaredNorm(), fp = posed_du.dot(posed_dv), gp = posed_dv.squaredNorm();
  const double det_rest = er * gr - fr * fr;
  const double det_posed = ep * gp - fp * fp;
  if (!(det_rest > kSingularMetric * er * gr) || !(det_posed > kSingularMetric * ep * gp)) {
    result.degenerate = true;
    return result;
  }
  const Stretch2<double> s = stretchEigen(gr / det_rest, -fr / det_rest, er / det_rest, 1.0 / det_rest, ep, fp, gp);
  result.smallest = std::sqrt(s.lambda_min);
  result.largest = std::sqrt(s.lambda_max);
  result.alpha = std::min(1.0, result.smallest);
  // Eigenvector of M for lambda_min from whichever row of (M - lambda I) is better conditioned.
  const Eigen::Vector2d from_first(s.m12, s.lambda_min - s.m11);
  const Eigen::Vector2d from_second(s.lambda_min - s.m22, s.m21);
  Eigen::Vector2d d = from_first.squaredNorm() >= from_second.squaredNorm() ? from_first : from_second;
  if (!(d.squaredNorm() > 1e-24 * (s.m11 * s.m11 + s.m22 * s.m22))) d = Eigen::Vector2d::UnitX();  // isotropic
  const double rest_norm = std::sqrt(er * d.x() * d.x() + 2.0 * fr * d.x() * d.y() + gr * d.y() * d.y());
  result.direction_uv = d / rest_norm;
  result.direction = (posed_du * d.x() + posed_dv * d.y()).normalized();
  return result;
}

PrincipalStretch measureStretch(const std::vector<BezierPatch>& rest, const std::vector<BezierPatch>& posed,
                                const SurfacePoint& at) {
  if (rest.size() != posed.size()) {
    throw std::invalid_argument("measureStretch: rest has " + str(rest.size()) + " patches, posed " +
                                str(posed.size()));
  }
  if (at.patch >= rest.size()) {
    throw std::invalid_argument("measureStretch: patch " + str(at.patch) + " of " + str(rest.size()));
  }
  const PatchDerivatives r = rest[at.patch].derivatives(at.u, at.v);
  const PatchDerivatives p = posed[at.patch].derivatives(at.u, at.v);
  return principalStretch(r.d_du, r.d_dv, p.d_du, p.d_dv);
}

const char* chainText(FoldChain chain) {
  switch (chain) {
    case FoldChain::kI:
      return "I";
    case FoldChain::kYY:
      return "YY";
    case FoldChain::kX:
      return "X";
  }
  throw std::invalid_argument("unknown fold chain " + std::to_string(static_cast<int>(chain)));
}

FoldChain chooseChain(double turn_per_cell, const BucklingCell& cell, const WrinklePlacementOptions& options) {
  const double bend =
      solveBuckling(PatternKind::X, options.reference_alpha, cell, OutOfDomainPolicy::clampToDomainEdge).bend_angle;
  const double turn = std::abs(turn_per_cell);
  const double to_i = turn, to_yy = std::abs(turn - bend / 2.0), to_x = std::abs(turn - bend);
  if (to_i <= to_yy && to_i <= to_x) return FoldChain::kI;
  return to_yy <= to_x ? FoldChain::kYY : FoldChain::kX;
}

WrinkleChoice chooseWrinkles(double alpha, FoldChain chain, const BucklingCell& cell,
                             const WrinklePlacementOptions& options) {
  requireUnit(alpha, "chooseWrinkles: alpha");
  WrinkleChoice choice;
  choice.chain = chain;
  choice.alpha = alpha;
  choice.wrinkled = alpha < options.alpha_threshold;
  choice.alpha_effective = std::min(1.0, alpha / options.alpha_threshold);
  choice.solution = solveBuckling(firstKind(chain), choice.alpha_effective, cell, options.out_of_domain);
  choice.amplitude = choice.solution.h1;
  return choice;
}

namespace {

// Rows of cells of about cell_length along u, cells_around along v, and how far the surface turns
// across one cell (for the pattern rule).
void layoutPatch(const BezierPatch& patch, const WrinklePlacementOptions& options, PatchWrinkleLayout& layout) {
  const double length_u = curveLength(patch, true, 0.5);
  const double length_v = curveLength(patch, false, 0.5);
  layout.rows = std::max(1, static_cast<int>(std::lround(length_u / options.cell_length)));
  layout.cells_around = options.cells_around;
  layout.cell.half_length_y = length_u / layout.rows / 2.0;
  layout.cell.half_width_x = length_v / layout.cells_around / 2.0;
  double turn = 0.0;
  int count = 0;
  for (double u : {0.25, 0.5, 0.75}) {
    for (int k = 0; k < layout.cells_around; ++k) {
      const double dot = patch.normal(u, static_cast<double>(k) / layout.cells_around)
                             .dot(patch.normal(u, static_cast<double>(k + 1) / layout.cells_around));
      turn += std::acos(std::clamp(dot, -1.0, 1.0));
      ++count;
    }
  }
  layout.turn_per_cell = turn / count;
  layout.chain = chooseChain(layout.turn_per_cell, layout.cell, options);
}

// The n x n samples (u, v from 0 to 1) of each patch `wanted` takes.
template <typename Wanted, typename Visit>
void forEachSample(const std::vector<BezierPatch>& patches, int n, const Wanted& wanted, const Visit& visit) {
  for (std::size_t p = 0; p < patches.size(); ++p) {
    if (!wanted(p)) continue;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const SurfacePoint at{static_cast<std::uint32_t>(p), static_cast<double>(i) / (n - 1),
                              static_cast<double>(j) / (n - 1)};
        visit(at, patches[p].sample(at.u, at.v));
      }
    }
  }
}

// A bone of the skeleton at rest (world = body frame at rest: x front, z up).
struct RestBone {
  int index = -1;
  Eigen::Vector3d origin;
  Eigen::Vector3d axis;  // its z axis: along the bone
};

RestBone restBone(const Skeleton& skeleton, const SkeletonPose& rest_pose, const std::string& name) {
  const int b = skeleton.findBone(name);
  if (b < 0) throw std::invalid_argument("WrinklePlacement: the skeleton has no bone '" + name + "'");
  const RigidTransform& frame = rest_pose.bone_in_world[static_cast<std::size_t>(b)];
  return RestBone{b, frame.translation, frame.rotation * Eigen::Vector3d::UnitZ()};
}

// A region across a joint (the header comment's table): the samples of one garment piece within
// half_width of the joint along the upper bone, on the side facing `facing`.
struct JointRegion {
  std::string name;
  std::string piece;
  RestBone upper;  // its axis: the limb's at rest
  RestBone joint;  // its origin: the joint
  Eigen::Vector3d facing;
  double half_width = 0.0;
};

std::vector<JointRegion> jointRegions(const Skeleton& skeleton, const SkeletonPose& rest_pose,
                                      const WrinklePlacementOptions& options) {
  std::vector<JointRegion> regions;
  for (const std::string side : {"l_", "r_"}) {
    const RestBone hip = restBone(skeleton, rest_pose, side + "hip");
    regions.push_back(JointRegion{side + "knee_back", side + "leg", hip, restBone(skeleton, rest_pose, side + "knee"),
                                  -Eigen::Vector3d::UnitX(), options.knee_half_width});
  }
  for (const std::string side : {"l_", "r_"}) {
    const RestBone shoulder = restBone(skeleton, rest_pose, side + "shoulder");
    // The crease of the elbow faces the way the forearm flexes: forward for arms hanging at
    // rest (checked against the flexion in test_wrinkle_placement).
    const Eigen::Vector3d inside =
        (Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitX().dot(shoulder.axis) * shoulder.axis).normalized();
    regions.push_back(JointRegion{side + "elbow_inside", side + "sleeve", shoulder,
                                  restBone(skeleton, rest_pose, side + "elbow"), inside, options.elbow_half_width});
  }
  return regions;
}

// The trunk's pieces: the waist region's, all around.
bool isTrunkPiece(const std::string& piece) {
  return piece != "l_sleeve" && piece != "r_sleeve" && piece != "l_leg" && piece != "r_leg" && piece != "crotch";
}

// The region's samples: those on the patches `wanted` takes that `accept` takes; its main patch
// holds most of them.
template <typename Wanted, typename Accept>
std::optional<CompressionRegion> collectRegion(const std::string& name, const std::vector<BezierPatch>& patches, int n,
                                               const Wanted& wanted, const Accept& accept) {
  CompressionRegion region;
  region.name = name;
  forEachSample(patches, n, wanted, [&](const SurfacePoint& at, const PatchSample& sample) {
    if (accept(at, sample)) region.samples.push_back(at);
  });
  if (region.samples.empty()) return std::nullopt;
  std::vector<int> count(patches.size(), 0);
  for (const SurfacePoint& at : region.samples) ++count[at.patch];
  region.main_patch = static_cast<std::uint32_t>(std::max_element(count.begin(), count.end()) - count.begin());
  return region;
}

// Spans: a sample at h (span_half_length) above the joint paired with the one as far below it
// that lies on the same line along the limb (nearest across the axis), at rest, on the region's
// side of the limb (facing), among the n x n samples of the piece's patches. Longer than the
// region: with r the span's distance behind the joint, the span closes at tan(theta / 2) = h / r
// (alpha_span), so h must be well above r for the measure to keep falling through a walk's knee
// bend.
void addMaterialSpans(const std::vector<BezierPatch>& patches, const GarmentControlNet& net, const JointRegion& joint,
                      const WrinklePlacementOptions& options, CompressionRegion& region) {
  const double h = options.span_half_length;
  const Eigen::Vector3d& axis = joint.upper.axis;
  std::vector<std::pair<SurfacePoint, Eigen::Vector3d>> upper, lower;
  const auto on_piece = [&](std::size_t patch) { return net.patchPiece(patch) == joint.piece; };
  forEachSample(patches, options.samples_per_side, on_piece, [&](const SurfacePoint& at, const PatchSample& sample) {
    if (sample.normal.dot(joint.facing) < 0.5) return;
    const double along = (sample.position - joint.joint.origin).dot(axis);
    if (std::abs(std::abs(along) - h) > 0.2 * h) return;
    (along < 0.0 ? upper : lower).emplace_back(at, sample.position);
  });
  for (const auto& [top, top_position] : upper) {
    double best = std::numeric_limits<double>::infinity();
    const std::pair<SurfacePoint, Eigen::Vector3d>* match = nullptr;
    for (const auto& candidate : lower) {
      const Eigen::Vector3d d = candidate.second - top_position;
      const double across = (d - d.dot(axis) * axis).norm();
      if (across < best) {
        best = across;
        match = &candidate;
      }
    }
    if (match && best < 0.2 * h) {
      region.spans.push_back(MaterialSpan{top, match->first, (match->second - top_position).dot(axis)});
    }
  }
  region.upper_bone = joint.upper.index;
  region.lower_bone = joint.joint.index;
}

}  // namespace

WrinklePlacement::WrinklePlacement(const Garment& garment, const Skeleton& skeleton, const BodyShape& shape,
                                   const WrinklePlacementOptions& options)
    : options_(options) {
  checkWrinklePlacementOptions(options_);
  ForwardKinematics fk(skeleton, shape);
  JointAngles zero{};
  zero.fill(0.0);
  SkeletonPose rest_pose;
  fk.compute(RigidTransform(), zero, rest_pose);
  Garment rest = garment;
  rest.pose(rest_pose);
  rest_patches_ = rest.patches();
  const GarmentControlNet& net = rest.net();

  layouts_.resize(rest_patches_.size());
  for (std::size_t p = 0; p < rest_patches_.size(); ++p) layoutPatch(rest_patches_[p], options_, layouts_[p]);

  const int n = options_.samples_per_side;
  for (const JointRegion& joint : jointRegions(skeleton, rest_pose, options_)) {
    const auto on_piece = [&](std::size_t patch) { return net.patchPiece(patch) == joint.piece; };
    std::optional<CompressionRegion> region =
        collectRegion(joint.name, rest_patches_, n, on_piece, [&](const SurfacePoint&, const PatchSample& sample) {
          return std::abs((sample.position - joint.joint.origin).dot(joint.upper.axis)) <= joint.half_width &&
                 sample.normal.dot(joint.facing) >= 0.5;
        });
    if (!region) continue;
    addMaterialSpans(rest_patches_, net, joint, options_, *region);
    regions_.push_back(std::move(*region));
  }
  const double waist_height = restBone(skeleton, rest_pose, "waist").origin.z();
  const auto on_trunk = [&](std::size_t patch) { return isTrunkPiece(net.patchPiece(patch)); };
  std::optional<CompressionRegion> waist =
      collectRegion("waist", rest_patches_, n, on_trunk, [&](const SurfacePoint&, const PatchSample& sample) {
        return std::abs(sample.position.z() - waist_height) <= options_.waist_half_width;
      });
  if (waist) regions_.push_back(std::move(*waist));
}

const CompressionRegion& WrinklePlacement::region(const std::string& name) const {
  std::string known;
  for (const CompressionRegion& r : regions_) {
    if (r.name == name) return r;
    known += (known.empty() ? "" : ", ") + r.name;
  }
  throw std::invalid_argument("no wrinkle region '" + name + "' on this garment (it has: " + known + ")");
}

PrincipalStretch WrinklePlacement::stretchAt(const std::vector<BezierPatch>& posed, const SurfacePoint& at) const {
  return measureStretch(rest_patches_, posed, at);
}

RegionCompression WrinklePlacement::measureRegion(const std::vector<BezierPatch>& posed, const SkeletonPose& pose,
                                                  const CompressionRegion& region) const {
  if (posed.size() != rest_patches_.size()) {
    throw std::invalid_argument("WrinklePlacement: posed garment has " + str(posed.size()) + " patches, expected " +
                                str(rest_patches_.size()));
  }
  RegionCompression result;
  result.name = region.name;
  std::vector<double> alphas;
  alphas.reserve(region.samples.size());
  for (const SurfacePoint& at : region.samples) {
    const PrincipalStretch s = stretchAt(posed, at);
    alphas.push_back(s.alpha);
    if (s.alpha < result.alpha_minimum) {
      result.alpha_minimum = s.alpha;
      result.most_compressed = at;
      result.direction = s.direction;
    }
  }
  if (region.samples.empty()) return result;
  if (result.alpha_minimum >= 1.0) result.most_compressed = region.samples.front();
  result.alpha_local = quantile(alphas, options_.region_percentile);
  result.alpha = result.alpha_local;
  if (!region.spans.empty() && region.upper_bone >= 0 && region.lower_bone >= 0) {
    const Eigen::Vector3d axis =
        (pose.bone_in_world[static_cast<std::size_t>(region.upper_bone)].rotation * Eigen::Vector3d::UnitZ() +
         pose.bone_in_world[static_cast<std::size_t>(region.lower_bone)].rotation * Eigen::Vector3d::UnitZ())
            .normalized();
    std::vector<double> ratios;
    ratios.reserve(region.spans.size());
    for (const MaterialSpan& span : region.spans) {
      const double length = (posed[span.second.patch].position(span.second.u, span.second.v) -
                             posed[span.first.patch].position(span.first.u, span.first.v))
                                .dot(axis);
      ratios.push_back(std::clamp(length / span.rest_length, 0.0, 1.0));
    }
    result.alpha_span = quantile(ratios, options_.region_percentile);
    result.alpha = result.alpha_span;
  }
  const PatchWrinkleLayout& layout = layouts_[region.main_patch];
  result.wrinkles = chooseWrinkles(result.alpha, layout.chain, layout.cell, options_);
  return result;
}

std::vector<RegionCompression> WrinklePlacement::measureRegions(const std::vector<BezierPatch>& posed,
                                                                const SkeletonPose& pose) const {
  std::vector<RegionCompression> result;
  result.reserve(regions_.size());
  for (const CompressionRegion& region : regions_) result.push_back(measureRegion(posed, pose, region));
  return result;
}

Eigen::Vector2f PoseWrinkleMap::textureCoordinate(std::uint32_t patch, float u, float v) const {
  const float tiles = static_cast<float>(layouts.size());
  return Eigen::Vector2f((static_cast<float>(patch) + u) / tiles, v);
}

PoseWrinkleMap makePoseWrinkleMap(const WrinklePlacement& placement, const std::vector<BezierPatch>& posed,
                                  const SkeletonPose& pose, int tile_pixels) {
  if (tile_pixels < 8)
    throw std::invalid_argument("makePoseWrinkleMap: tile_pixels must be >= 8, got " + str(tile_pixels));
  const std::vector<BezierPatch>& rest = placement.restPatches();
  if (posed.size() != rest.size()) {
    throw std::invalid_argument("makePoseWrinkleMap: posed garment has " + str(posed.size()) + " patches, expected " +
                                str(rest.size()));
  }
  const WrinklePlacementOptions& options = placement.options();
  PoseWrinkleMap result;
  result.tile_pixels = tile_pixels;
  result.layouts = placement.layouts();
  result.atlas = ReliefMap(tile_pixels * static_cast<int>(rest.size()), tile_pixels);
  result.rows.resize(rest.size());
  // Rows holding samples of a knee or elbow region take the region's own measure, as the
  // region's pattern choice does: current versus rest length along the joint's axis, which
  // keeps falling with flexion where the local measure stalls and even recovers (the surface
  // behind a sharply bent joint creases, see RegionCompression::alpha_span). Other rows (the
  // waist, free cloth) take the local measure.
  std::vector<std::vector<std::optional<double>>> span_alpha(rest.size());  // empty: no region's row
  for (std::size_t p = 0; p < rest.size(); ++p) span_alpha[p].resize(static_cast<std::size_t>(result.layouts[p].rows));
  for (const RegionCompression& measured : placement.measureRegions(posed, pose)) {
    const CompressionRegion& region = placement.region(measured.name);
    if (region.spans.empty()) continue;
    for (const SurfacePoint& at : region.samples) {
      const int rows = result.layouts[at.patch].rows;
      const auto row = static_cast<std::size_t>(std::clamp(static_cast<int>(at.u * rows), 0, rows - 1));
      std::optional<double>& alpha = span_alpha[at.patch][row];
      alpha = std::min(alpha.value_or(measured.alpha_span), measured.alpha_span);
    }
  }
  constexpr int kSamplesAround = 9;
  constexpr int kSamplesAlong = 3;  // per row of cells
  for (std::size_t p = 0; p < rest.size(); ++p) {
    const PatchWrinkleLayout& layout = result.layouts[p];
    std::vector<double> row_alpha;
    bool any = false;
    for (int r = 0; r < layout.rows; ++r) {
      std::vector<double> alphas;
      for (int a = 0; a < kSamplesAlong; ++a) {
        const double u = (r + (a + 0.5) / kSamplesAlong) / layout.rows;
        for (int k = 0; k < kSamplesAround; ++k) {
          const double v = static_cast<double>(k) / (kSamplesAround - 1);
          alphas.push_back(measureStretch(rest, posed, SurfacePoint{static_cast<std::uint32_t>(p), u, v}).alpha);
        }
      }
      const std::optional<double>& region_alpha = span_alpha[p][static_cast<std::size_t>(r)];
      const double alpha = region_alpha ? *region_alpha : quantile(alphas, options.region_percentile);
      const WrinkleChoice choice = chooseWrinkles(alpha, layout.chain, layout.cell, options);
      any = any || choice.wrinkled;
      row_alpha.push_back(choice.alpha_effective);
      result.rows[p].push_back(choice);
    }
    if (!any) continue;
    WrinkleMapSpec spec;
    spec.width_pixels = tile_pixels;   // around: v
    spec.height_pixels = tile_pixels;  // rows: u
    spec.cell = layout.cell;
    spec.chain = chainText(layout.chain);
    spec.cells_around = layout.cells_around;
    spec.rows = layout.rows;
    spec.alpha = row_alpha;
    spec.out_of_domain = options.out_of_domain;
    const ReliefMap tile = makeWrinkleMap(spec);
    // Transpose into the atlas: the tile's rows (along u) become the atlas's columns.
    for (int row = 0; row < tile_pixels; ++row) {
      for (int column = 0; column < tile_pixels; ++column) {
        const std::size_t from = tile.index(column, row);
        const std::size_t to = result.atlas.index(static_cast<int>(p) * tile_pixels + row, column);
        result.atlas.heights[to] = tile.heights[from];
        result.atlas.slope_u[to] = tile.slope_v[from];
        result.atlas.slope_v[to] = tile.slope_u[from];
      }
    }
  }
  return result;
}

}  // namespace dressed_human
