// Wrinkle placement (SPEC §4, the part the seed leaves open): where a posed garment is
// compressed, how much, which buckling pattern goes there, and the pose's wrinkle relief.
//
// Compression. The garment's material point is (patch, u, v): the same point in the rest pose
// (the garment posed at the all-zero skeleton pose, as Garment's constructor leaves it) and in
// any other pose. With J = [F_u F_v] (3x2) and G = J^T J the first fundamental form, the map
// rest -> posed stretches a material direction d (in uv) by sqrt(d^T G_posed d / d^T G_rest d);
// its extremes, the principal stretches, are the square roots of the eigenvalues of
// G_rest^-1 G_posed. They do not depend on how the patch is parametrized (a change of (u, v)
// is a congruence of both forms), so they are a property of the cloth, not of the Bezier net.
// alpha = min(1, smallest principal stretch): 1 = not compressed (stretching does not buckle),
// matching buckling_solution.h's convention ("compressed to 2 alpha L_y"). The eigenvector is
// the compression direction: along the bone behind a bent knee or inside a bent elbow, diagonal
// at a twisted waist (a shear's principal axes are at 45 degrees).
//
// From alpha to wrinkles.
//  - Threshold: cloth takes a small shortening in plane (ease, fabric strain) before it buckles.
//    alpha_effective = min(1, alpha / alpha_threshold): no wrinkles above the threshold, and
//    the relief starts from zero there instead of jumping (h1 ~ sqrt(1 - alpha^2) is steep at
//    alpha = 1, a cut-off alone would make the relief pop on as a knee starts to bend).
//    The default, 0.9, is measured (docs/relief/fold_strength_vs_flexion.png): the skinned
//    garment concentrates a bend, so the cloth behind a knee bent only 10 degrees is already at
//    alpha ~0.89 locally; at 0.9 the relaxed elbow of a walk (17-19 degrees) and the waist stay
//    smooth and the folds grow from there (0.98 drew half-strength folds at every slight bend).
//  - Amplitude: the buckling solution's rise h1(alpha_effective) (Eq. 9; Eq. 10 for Y/X with
//    the chosen OutOfDomainPolicy, default clampToDomainEdge), in metres for a cell of
//    physical size (cell_length along the compression, the patch's circumference / cells_around
//    across it).
//  - Pattern (the seed's argument: chains of Y/X cells curl, by 2 atan(w/h2) per split joint,
//    so they fit cylinders; I folds stay flat). Per patch, from rest geometry only, so a pose
//    sequence never switches patterns: the surface turns across the wrinkles (around the limb)
//    by theta = |kappa_around| * 2 L_x per cell. A chain "X" curls by the bend angle B at every
//    joint, "YY" (split joints alternating with flat I-I joints) by B every other joint, "I" not
//    at all; B taken at reference_alpha. The rule picks the chain whose curl per cell, 0, B / 2
//    or B, is nearest theta: I where the cloth is flat at the cell's scale (theta < ~B/4), YY
//    or X on tubes. B grows as the cell narrows (4 atan(h1 / L_x)). With the default cells
//    (about 5 cm along, a quarter patch across) every patch of the jacket and the pants gets
//    YY: the torso turns ~0.35-0.4 rad per cell, sleeves and trouser legs ~0.78, against
//    B / 2 ~ 0.6-0.75 (test_wrinkle_placement prints the table); I needs flatter cloth or
//    wider cells, X thinner tubes or narrower cells.
//
// Regions (named summaries for reports, tests and figures), chosen from rest geometry:
//   l_knee_back, r_knee_back     pants legs, within knee_half_width of the knee joint along the
//                                thigh and facing backwards (normal . -x >= 0.5)
//   l_elbow_inside, r_elbow_inside  sleeves, within elbow_half_width of the elbow joint along
//                                the upper arm, on the side the forearm flexes towards
//   waist                        the trunk patches within waist_half_width of the height of the
//                                waist joint (lower spine), all around
// alpha_region: the region_percentile quantile of its samples' alpha (robust against one
// sample at a seam or the crotch), and for knee and elbow also the same quantile of the
// length ratio of material spans across the joint (RegionCompression explains why both).
#pragma once

#include "dressed_human/core/surfaces/bezier_patch.h"
#include "dressed_human/core/relief/buckling_solution.h"
#include "dressed_human/core/garments/garment.h"
#include "dressed_human/core/relief/relief_map.h"
#include "dressed_human/core/surfaces/tessellation.h"

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace dressed_human {

/// Below this (relative to E G) a first fundamental form counts as singular: a pole, where the
/// patch gives no two independent directions and the stretch is undefined.
constexpr double kSingularMetric = 1e-12;

/// A material point of a garment.
struct SurfacePoint {
  std::uint32_t patch = 0;
  double u = 0.0;
  double v = 0.0;
};

struct PrincipalStretch {
  double alpha = 1.0;     ///< min(1, smallest): the compression coefficient
  double smallest = 1.0;  ///< smallest principal stretch (may exceed 1: stretched everywhere)
  double largest = 1.0;
  Eigen::Vector2d direction_uv =
      Eigen::Vector2d::UnitX();                          ///< compression direction in (u, v), unit in the rest metric
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< the same on the posed surface, unit length
  bool degenerate = false;                               ///< a Jacobian of rank < 2 (a pole): reported as alpha = 1
};

/// Principal stretches of rest -> posed from the two Jacobians [d_du d_dv].
PrincipalStretch principalStretch(const Eigen::Vector3d& rest_du, const Eigen::Vector3d& rest_dv,
                                  const Eigen::Vector3d& posed_du, const Eigen::Vector3d& posed_dv);
/// The same at one material point. Throws std::invalid_argument for different patch counts, a
/// patch index out of range or (u, v) outside [0, 1]^2.
PrincipalStretch measureStretch(const std::vector<BezierPatch>& rest, const std::vector<BezierPatch>& posed,
                                const SurfacePoint& at);

struct WrinklePlacementOptions {
  double alpha_threshold = 0.9;  ///< alpha above this: no wrinkles (see the header comment)
  double region_percentile = 0.1;
  int samples_per_side = 17;      ///< region sampling grid per patch (samples_per_side^2)
  double knee_half_width = 0.10;  ///< metres along the thigh
  double elbow_half_width = 0.08;
  double waist_half_width = 0.08;
  double span_half_length = 0.15;  ///< knee/elbow spans reach this far either side of the joint (m)
  double cell_length = 0.05;       ///< rest 2 L_y of a wrinkle cell along the compression (m)
  int cells_around = 4;            ///< wrinkle cells around each patch (even: "YY" must close)
  double reference_alpha = 0.85;   ///< compression at which the pattern rule compares curls
  OutOfDomainPolicy out_of_domain = OutOfDomainPolicy::clampToDomainEdge;
  double saturation_alpha = 0.6;  ///< VertexCompression: wrinkle strength 1 at and below this
};

/// The chains of cells the pattern rule chooses from, repeated around a patch: I cells (flat),
/// Y-Y (split joints alternating with flat I-I joints: curls by B every other joint), X cells
/// (curl by B at every joint).
enum class FoldChain { kI, kYY, kX };
/// "I", "YY", "X": the chain as the seed and WrinkleMapSpec::chain write it.
const char* chainText(FoldChain chain);

/// alpha -> the wrinkles of one cell.
struct WrinkleChoice {
  bool wrinkled = false;            ///< alpha below the threshold
  FoldChain chain = FoldChain::kI;  ///< repeated around
  double alpha = 1.0;               ///< measured
  double alpha_effective = 1.0;     ///< after the threshold, before the domain clamp
  BucklingSolution solution;        ///< of the chain's first pattern at alpha_effective
  double amplitude = 0.0;           ///< solution.h1 in metres (cell in metres)
};

/// Throws std::invalid_argument naming the first bad option.
void checkWrinklePlacementOptions(const WrinklePlacementOptions& options);

/// Throws std::invalid_argument for alpha outside [0, 1] or a bad cell.
WrinkleChoice chooseWrinkles(double alpha, FoldChain chain, const BucklingCell& cell,
                             const WrinklePlacementOptions& options = {});
/// The pattern rule: the chain whose curl per cell (0, B/2, B at reference_alpha) is nearest
/// turn_per_cell (radians the surface turns across one cell).
FoldChain chooseChain(double turn_per_cell, const BucklingCell& cell, const WrinklePlacementOptions& options = {});

/// Two material points across a joint, on one line along the limb at rest (above and below
/// the knee, ...).
struct MaterialSpan {
  SurfacePoint first, second;  ///< first on the upper bone's side
  double rest_length = 0.0;    ///< metres along the (straight) bone axis at rest
};

struct CompressionRegion {
  std::string name;
  std::vector<SurfacePoint> samples;
  /// Knee and elbow regions: pairs of samples from the region's two ends along the bone axis,
  /// on the same line along the limb at rest (empty for the waist, whose twist shears rather
  /// than shortens it), and the joint's two bones.
  std::vector<MaterialSpan> spans;
  int upper_bone = -1;
  int lower_bone = -1;
  /// The patch holding most of the samples: its layout (chain, cell) is the region's, fixed so
  /// that a pose sequence never switches the region's pattern.
  std::uint32_t main_patch = 0;
};

struct RegionCompression {
  std::string name;
  /// What the region's wrinkles are chosen from: alpha_span where the region has spans, else
  /// alpha_local.
  double alpha = 1.0;
  /// region_percentile quantile of the local measure (principal stretch) over the samples.
  double alpha_local = 1.0;
  /// region_percentile quantile over the spans of clamp(L / L_rest, 0, 1), L the span's
  /// length along the joint's axis in the pose: the bisector of the two bones' z axes (the
  /// bone axis itself at rest). Current versus rest length along the bone axis, in short. For
  /// a span at distance h either side of a hinge and r behind it this is
  /// cos(theta/2) - (r/h) sin(theta/2): strictly falling with the flexion theta, through the
  /// point where the two sides of the garment meet and beyond. The local measure cannot do
  /// that: behind a sharply bent joint the garment surface creases over itself, which as a
  /// parametrization is still regular, so its first fundamental form stops shrinking there.
  double alpha_span = 1.0;
  double alpha_minimum = 1.0;  ///< smallest local alpha
  SurfacePoint most_compressed;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< local compression direction there (posed)
  WrinkleChoice wrinkles;                                ///< at alpha, with the region's chain and cell
};

/// Rest geometry of one garment's wrinkle cells, per patch.
struct PatchWrinkleLayout {
  int rows = 1;                ///< cells along u (down the garment, the bone axis)
  int cells_around = 4;        ///< cells along v
  BucklingCell cell;           ///< metres
  double turn_per_cell = 0.0;  ///< radians, around the limb
  FoldChain chain = FoldChain::kI;
};

class WrinklePlacement {
 public:
  /// `garment` may be in any pose; its rest pose is recomputed from the skeleton and shape it
  /// was built with. Throws std::invalid_argument for bad options.
  WrinklePlacement(const Garment& garment, const Skeleton& skeleton, const BodyShape& shape = BodyShape(),
                   const WrinklePlacementOptions& options = {});

  const std::vector<BezierPatch>& restPatches() const { return rest_patches_; }
  const std::vector<CompressionRegion>& regions() const { return regions_; }
  const std::vector<PatchWrinkleLayout>& layouts() const { return layouts_; }
  const WrinklePlacementOptions& options() const { return options_; }
  /// The region named `name`; throws std::invalid_argument listing the garment's regions.
  const CompressionRegion& region(const std::string& name) const;

  /// Throws std::invalid_argument when `posed` is not this garment's patch count.
  PrincipalStretch stretchAt(const std::vector<BezierPatch>& posed, const SurfacePoint& at) const;
  /// `pose`: the skeleton pose the garment was posed with (for the span's joint axis).
  RegionCompression measureRegion(const std::vector<BezierPatch>& posed, const SkeletonPose& pose,
                                  const CompressionRegion& region) const;
  std::vector<RegionCompression> measureRegions(const std::vector<BezierPatch>& posed, const SkeletonPose& pose) const;

 private:
  WrinklePlacementOptions options_;
  std::vector<BezierPatch> rest_patches_;
  std::vector<CompressionRegion> regions_;
  std::vector<PatchWrinkleLayout> layouts_;
};

/// One pose's wrinkle relief for one garment: an atlas of one square tile per patch, side by
/// side. Inside tile p, columns run along the patch's u and rows along its v, so a vertex's
/// texture coordinate is textureCoordinate(p, u, v) (u along the garment: the compression
/// axis of knee and elbow, the wrinkle rows; v around it: the periodic chain). Heights in metres,
/// slopes physical (relief_map.h). Tiles of neighbouring patches meet at height 0 along u
/// (rows always do) and where their alphas agree along v.
struct PoseWrinkleMap {
  ReliefMap atlas;
  int tile_pixels = 0;
  std::vector<PatchWrinkleLayout> layouts;
  std::vector<std::vector<WrinkleChoice>> rows;  ///< [patch][row]
  Eigen::Vector2f textureCoordinate(std::uint32_t patch, float u, float v) const;
  float maximumHeight() const { return atlas.maximumHeight(); }
};

/// A row's alpha is the region_percentile quantile of the local measure over the row, but where
/// the row holds samples of a knee or elbow region it is that region's alpha_span (the smallest
/// if several), as for the region's pattern choice (hence the pose: the joint's axis). Throws std::invalid_argument for
/// a tile size below 8 or a wrong patch count. Cost: the placement's samples plus one makeWrinkleMap per wrinkled patch
/// (flat tiles are skipped).
PoseWrinkleMap makePoseWrinkleMap(const WrinklePlacement& placement, const std::vector<BezierPatch>& posed,
                                  const SkeletonPose& pose, int tile_pixels = 128);

}  // namespace dressed_human
