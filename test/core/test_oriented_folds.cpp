// Oriented folds (issue 21, part 2): the folds run across the compression on a compressed patch,
// uncompressed cloth is smooth, and the relief is continuous across patch edges and as the fold
// axis or the strength change (regions, frames).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <random>

#include <Eigen/Eigenvalues>

#include "dressed_human/core/model/relief_map_jobs.h"
#include "dressed_human/core/relief/oriented_folds.h"
#include "dressed_human/core/relief/vertex_compression.h"
#include "dressed_human/core/relief/wrinkle_placement.h"

namespace dressed_human {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The fold tiles at a fold softness (garmentWrinkleMapSpec), built once each.
const FoldTiles& tiles(double softness = kDefaultFoldSoftness) {
  static std::map<double, FoldTiles> built;
  auto found = built.find(softness);
  if (found == built.end()) found = built.emplace(softness, garmentFoldTiles(128, softness)).first;
  return found->second;
}

// A flat patch, `width` along u (x) and `height` along v (y), squeezed to `alpha` of its length
// along the in-plane direction at `angle` from x (and free across it).
struct CompressedPatch {
  Eigen::Vector3d rest_du, rest_dv, posed_du, posed_dv, compression;
  CompressedPatch(double width, double height, double angle, double alpha) {
    compression = Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
    const Eigen::Matrix3d squeeze = Eigen::Matrix3d::Identity() - (1.0 - alpha) * compression * compression.transpose();
    rest_du = Eigen::Vector3d(width, 0.0, 0.0);
    rest_dv = Eigen::Vector3d(0.0, height, 0.0);
    posed_du = squeeze * rest_du;
    posed_dv = squeeze * rest_dv;
  }
  VertexStretch stretch() const {
    return vertexStretchAt(inverseRestMetric(rest_du, rest_dv), posed_du.cast<float>(), posed_dv.cast<float>(),
                           VertexCompression().strengthConstants());
  }
};

// The direction the drawn folds run, on the posed surface: the level-set tangent of the dominant
// slope over one tile (structure tensor of the slopes in texture coordinates), mapped to 3D.
Eigen::Vector3d drawnFoldDirection(const CompressedPatch& patch, const VertexStretch& stretch,
                                   double softness = kDefaultFoldSoftness) {
  Eigen::Matrix2d tensor = Eigen::Matrix2d::Zero();
  constexpr int kSide = 48;
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      const Eigen::Vector2d at((i + 0.5) / kSide, (j + 0.5) / kSide);  // one patch
      const Eigen::Vector2d slope = orientedFolds(tiles(softness), at, stretch.fold_axis, stretch.strength).slope;
      tensor += slope * slope.transpose();
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(tensor);
  const Eigen::Vector2d across = solver.eigenvectors().col(1);  // the dominant slope
  const Eigen::Vector2d along(-across.y(), across.x());         // where the height stays
  return (along.x() * patch.posed_du + along.y() * patch.posed_dv).normalized();
}

double degreesBetweenLines(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * 180.0 / kPi;
}

TEST(OrientedFolds, OrientationsAreLatticeSimilaritiesOfNearlyOneScale) {
  const auto& table = foldOrientations();
  for (int k = 0; k < kFoldOrientations; ++k) {
    const FoldOrientation& o = table[static_cast<std::size_t>(k)];
    const double tiles_across = o.scale * std::hypot(o.p, o.q);
    EXPECT_GE(tiles_across, 2.8) << k;
    EXPECT_LE(tiles_across, 3.7) << k;
    const double next = k + 1 < kFoldOrientations ? table[static_cast<std::size_t>(k + 1)].degrees : 180.0;
    EXPECT_GT(next, o.degrees);
    EXPECT_LE(next - o.degrees, 18.5) << "gap after orientation " << k;
    // Folds run along (p, q): the lookup sends it onto the tile's v axis.
    const Eigen::Vector2d along = foldTileCoordinate(k, Eigen::Vector2d(o.p, o.q));
    EXPECT_NEAR(along.x(), 0.0, 1e-12);
    EXPECT_GT(along.y(), 0.0);
  }
  EXPECT_EQ(table[kFoldOrientations / 2].p, 0);  // the tile as laid out: folds along v
}

TEST(OrientedFolds, BlendIsTheTwoNeighboursSummingToOne) {
  for (int step = 0; step < 720; ++step) {
    const double double_angle = step * kPi / 360.0;
    // Long axes: the bias towards the tile as laid out (kFoldAxisBias) is negligible.
    const FoldBlend blend =
        foldOrientationBlend(1e4f * Eigen::Vector2f(std::cos(double_angle), std::sin(double_angle)));
    EXPECT_NEAR(blend.first_weight + blend.second_weight, 1.0f, 1e-6f);
    EXPECT_EQ(blend.second, (blend.first + 1) % kFoldOrientations);
    const double folds = std::fmod(double_angle * 90.0 / kPi + 180.0, 180.0);
    const double first = foldOrientations()[static_cast<std::size_t>(blend.first)].degrees;
    EXPECT_LE(first, folds + 1e-3);
  }
  // At an orientation's own angle, that orientation alone.
  for (int k = 0; k < kFoldOrientations; ++k) {
    const double double_angle = 2.0 * foldOrientations()[static_cast<std::size_t>(k)].degrees * kPi / 180.0;
    const FoldBlend blend =
        foldOrientationBlend(1e4f * Eigen::Vector2f(std::cos(double_angle), std::sin(double_angle)));
    // Rounding may put the angle a hair below k's: then k is the second, at full weight.
    EXPECT_NEAR(blend.first == k    ? blend.first_weight
                : blend.second == k ? blend.second_weight
                                    : 0.0f,
                1.0f, 1e-3f)
        << k;
  }
  // No preferred direction: the tile as laid out (folds along v).
  const FoldBlend none = foldOrientationBlend(Eigen::Vector2f::Zero());
  EXPECT_EQ(none.first, kFoldOrientations / 2);
  EXPECT_FLOAT_EQ(none.first_weight, 1.0f);
}

TEST(OrientedFolds, FoldAxisFollowsTheCompressionAndIsContinuous) {
  Eigen::Vector2f previous = Eigen::Vector2f::Zero();
  for (int step = 0; step <= 360; ++step) {
    const double angle = step * kPi / 360.0;
    const VertexStretch stretch = CompressedPatch(0.2, 0.2, angle, 0.8).stretch();
    // On a square patch (u, v) angles are space angles: the folds run at angle + 90 degrees.
    const double fold = angle + kPi / 2.0;
    const float anisotropy = (1.0f - 0.64f) / (1.0f + 0.64f);
    EXPECT_NEAR(stretch.fold_axis.x(), anisotropy * std::cos(2.0 * fold), 1e-4) << "at " << step / 2.0 << " deg";
    EXPECT_NEAR(stretch.fold_axis.y(), anisotropy * std::sin(2.0 * fold), 1e-4) << "at " << step / 2.0 << " deg";
    if (step > 0) {
      EXPECT_LT((stretch.fold_axis - previous).norm(), 0.01f) << "a jump at " << step / 2.0 << " deg";
    }
    previous = stretch.fold_axis;
  }
  // Shortened alike in every direction: no fold axis.
  CompressedPatch uniform(0.2, 0.1, 0.0, 1.0);
  uniform.posed_du *= 0.8;
  uniform.posed_dv *= 0.8;
  EXPECT_LT(uniform.stretch().fold_axis.norm(), 1e-5f);
  EXPECT_GT(uniform.stretch().strength, 0.5f);
}

// The test: folds perpendicular to the compression within 15 degrees, here on a patch
// twice as long as wide (its (u, v) angles are not space angles) and at slight, middle and
// strong compression (the I tile, both blended, the Y-Y tile).
TEST(OrientedFolds, FoldsRunAcrossTheCompressionWithin15Degrees) {
  // Softness from issue 21's (20 harmonics a cell) to the default and the softest a user may set
  // (issue 40). The exact folds (softness 0, the seed's profile) do not pass: their diamond creases
  // outweigh the ridges, which is why the display blurs them.
  for (const double softness : {smoothFoldBlur(20), kDefaultFoldSoftness, kMaxFoldSoftness}) {
    double worst = 90.0;
    for (const double alpha : {0.87, 0.8, 0.6}) {
      for (int degrees = 0; degrees < 180; degrees += 15) {
        const CompressedPatch patch(0.3, 0.15, degrees * kPi / 180.0, alpha);
        const VertexStretch stretch = patch.stretch();
        ASSERT_GT(stretch.strength, 0.1f);
        const Eigen::Vector3d compression =
            principalStretch(patch.rest_du, patch.rest_dv, patch.posed_du, patch.posed_dv).direction;
        const double angle = degreesBetweenLines(drawnFoldDirection(patch, stretch, softness), compression);
        worst = std::min(worst, angle);
        EXPECT_GE(angle, 75.0) << "softness " << softness << ", compression at " << degrees << " deg, alpha " << alpha
                               << ": folds at " << angle << " deg to it";
      }
    }
    std::printf("softness %.2f: folds at %.1f deg or more to the compression (90 = across)\n", softness, worst);
  }
}

TEST(OrientedFolds, UncompressedOrStretchedClothIsSmooth) {
  for (const double alpha : {1.0, 1.2}) {
    const CompressedPatch patch(0.3, 0.15, 0.4, alpha);
    const VertexStretch stretch = patch.stretch();
    EXPECT_EQ(stretch.strength, 0.0f);
    for (int i = 0; i < 16; ++i) {
      const ReliefSample sample =
          orientedFolds(tiles(), Eigen::Vector2d(i / 16.0, i / 7.0), stretch.fold_axis, stretch.strength);
      EXPECT_EQ(sample.height, 0.0);
      EXPECT_EQ(sample.slope.norm(), 0.0);
    }
  }
}

// Patches meet at integer texture coordinates: every orientation's lookup must map the lattice
// onto itself, else the folds break at every patch edge.
TEST(OrientedFolds, ReliefIsPeriodicOnThePatchLattice) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double t = unit(random), angle = 2.0 * kPi * unit(random);
    const Eigen::Vector2f axis = Eigen::Vector2f(std::cos(angle), std::sin(angle)) * static_cast<float>(unit(random));
    const float strength = static_cast<float>(unit(random));
    for (const auto& edge : {std::make_pair(Eigen::Vector2d(0.0, t), Eigen::Vector2d(1.0, t)),
                             std::make_pair(Eigen::Vector2d(t, 0.0), Eigen::Vector2d(t, 1.0)),
                             std::make_pair(Eigen::Vector2d(t, 0.0), Eigen::Vector2d(t + 3.0, -2.0))}) {
      const ReliefSample a = orientedFolds(tiles(), edge.first, axis, strength);
      const ReliefSample b = orientedFolds(tiles(), edge.second, axis, strength);
      EXPECT_NEAR(a.height, b.height, 1e-9);
      EXPECT_NEAR((a.slope - b.slope).norm(), 0.0, 1e-9);
    }
  }
}

// Across a region boundary (or from one frame to the next) the fold axis and the strength change
// continuously; so must the relief: no step larger than the change's own size allows.
TEST(OrientedFolds, ReliefChangesContinuouslyWithAxisAndStrength) {
  double largest_slope = 0.0;
  for (int i = 0; i < 64; ++i) {
    const Eigen::Vector2d at(i / 64.0, i * 0.37);
    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector2f axis(std::cos(k * kPi / 4.0), std::sin(k * kPi / 4.0));
      largest_slope = std::max(largest_slope, orientedFolds(tiles(), at, axis, 1.0f).slope.norm());
    }
  }
  ASSERT_GT(largest_slope, 0.1);
  constexpr int kSteps = 1000;
  for (int i = 0; i < 16; ++i) {
    const Eigen::Vector2d at(0.13 + i / 16.0, 0.71 * i);
    ReliefSample previous;
    for (int step = 0; step <= kSteps; ++step) {
      const double angle = 2.0 * kPi * step / kSteps;  // the double angle: folds turn by 180 degrees
      const ReliefSample sample =
          orientedFolds(tiles(), at, 0.3f * Eigen::Vector2f(std::cos(angle), std::sin(angle)), 0.7f);
      if (step > 0) {
        EXPECT_LT((sample.slope - previous.slope).norm(), 0.05 * largest_slope) << "axis step " << step;
      }
      previous = sample;
    }
    for (int step = 0; step <= kSteps; ++step) {
      const ReliefSample sample =
          orientedFolds(tiles(), at, Eigen::Vector2f(0.2f, 0.1f), static_cast<float>(step) / kSteps);
      if (step > 0) {
        EXPECT_LT((sample.slope - previous.slope).norm(), 0.05 * largest_slope) << "strength step " << step;
      }
      previous = sample;
    }
  }
}

TEST(OrientedFolds, PatternGoesFromIToYYWithStrength) {
  EXPECT_EQ(strongPatternWeight(0.0f), 0.0f);
  EXPECT_EQ(strongPatternWeight(0.4f), 0.0f);
  EXPECT_EQ(strongPatternWeight(0.8f), 1.0f);
  EXPECT_NEAR(strongPatternWeight(0.6f), 0.5f, 1e-6f);
  // Slight compression draws the I tile, strong the Y-Y tile (at the as-laid-out orientation).
  const Eigen::Vector2d at(0.3, 0.6);
  const ReliefSample slight = orientedFolds(tiles(), at, Eigen::Vector2f::Zero(), 0.3f);
  const ReliefSample strong = orientedFolds(tiles(), at, Eigen::Vector2f::Zero(), 1.0f);
  // Orientation 6 alone: the tile as laid out, kFoldTilesPerPatch times per patch, heights shrunk alike.
  const double scale = 1.0 / kFoldTilesPerPatch;
  const Eigen::Vector2d tile = at * kFoldTilesPerPatch;
  EXPECT_NEAR(slight.height, 0.3 * scale * sampleReliefMap(tiles().slight, tile.x(), tile.y()).height, 1e-6);
  EXPECT_NEAR(strong.height, scale * sampleReliefMap(tiles().strong, tile.x(), tile.y()).height, 1e-6);
}

TEST(OrientedFolds, TilesOfDifferentSizesAreRefused) {
  EXPECT_THROW(FoldTiles(ReliefMap(8, 8), ReliefMap(8, 16)), std::invalid_argument);
  EXPECT_THROW(FoldTiles(ReliefMap(), ReliefMap()), std::invalid_argument);
  const std::vector<std::uint8_t> rgba = encodeFoldTilesRgba(tiles());
  ASSERT_EQ(rgba.size(), static_cast<std::size_t>(128 * 128 * 4));
}

TEST(OrientedFolds, TextureLevelsAreBothTilesFiltered) {
  const FoldTiles fold_tiles = tiles();
  const EncodedNormalMap encoded = encodeFoldTilesMips(fold_tiles);
  ASSERT_EQ(encoded.levels.size(), 8u);  // 128 down to 1 x 1
  EXPECT_EQ(encoded.channels, 4);
  EXPECT_EQ(encoded.levels[0], encodeFoldTilesRgba(fold_tiles));
  const std::vector<ReliefMap> slight = buildMipChain(fold_tiles.slight), strong = buildMipChain(fold_tiles.strong);
  EXPECT_EQ(encoded.levels[3], encodeFoldTilesRgba(FoldTiles(slight[3], strong[3])));
  EXPECT_EQ(encoded.levels.back().size(), 4u);
}

}  // namespace
}  // namespace dressed_human
