// Displaced geometry (mesh_displacement.h): positions move along the normal by the scaled
// relief height, normals tilt by the relief slope; checked against the analytic displaced
// surface of a flat patch and against the displaced mesh's own finite differences.
#include "dressed_human/core/relief/mesh_displacement.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

namespace dressed_human {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A flat 1 m x 1 m patch in the xy plane, u along x, v along y (normal +z).
BezierPatch flatPatch() {
  BezierPatch::ControlPoints points;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) points[BezierPatch::index(i, j)] = Eigen::Vector3d(i / 3.0, j / 3.0, 0.0);
  }
  return BezierPatch(points);
}

// h(U, V) = a sin(2 pi U): one period per tile along u, exact slopes.
ReliefMap sineMap(int size, double a) {
  ReliefMap map(size, size);
  for (int r = 0; r < size; ++r) {
    for (int c = 0; c < size; ++c) {
      const double u = (c + 0.5) / size;
      map.heights[map.index(c, r)] = static_cast<float>(a * std::sin(2.0 * kPi * u));
      map.slope_u[map.index(c, r)] = static_cast<float>(a * 2.0 * kPi * std::cos(2.0 * kPi * u));
      map.slope_v[map.index(c, r)] = 0.0f;
    }
  }
  return map;
}

// Largest distances of `displaced` (the flat 1 m patch `base` displaced by amplitude 1.5 with
// sineMap(_, 0.01)) from the analytic surface z = 1.5 * 0.01 * sin(4 pi x) * metres_per_tile,
// positions and unit normals; its slope is the derivative of that height.
struct SineSurfaceErrors {
  double position = 0.0;
  double normal = 0.0;
};

SineSurfaceErrors errorsAgainstSine(const TriangleMesh& base, const TriangleMesh& displaced, double metres_per_tile) {
  SineSurfaceErrors worst;
  const double height = 1.5 * 0.01 * metres_per_tile;
  for (std::size_t i = 0; i < base.vertexCount(); ++i) {
    const double x = base.positions[i].x();
    const double z = height * std::sin(4.0 * kPi * x);
    const double dzdx = height * 4.0 * kPi * std::cos(4.0 * kPi * x);
    worst.position = std::max(
        worst.position, (displaced.positions[i].cast<double>() - Eigen::Vector3d(x, base.positions[i].y(), z)).norm());
    worst.normal = std::max(worst.normal,
                            (displaced.normals[i].cast<double>() - Eigen::Vector3d(-dzdx, 0, 1).normalized()).norm());
  }
  return worst;
}

TEST(MeshDisplacement, SamplesPixelCentresExactlyAndWraps) {
  ReliefMap map(4, 2);
  for (std::size_t i = 0; i < map.heights.size(); ++i) map.heights[i] = static_cast<float>(i);
  EXPECT_DOUBLE_EQ(sampleReliefMap(map, 0.125, 0.25).height, 0.0);
  EXPECT_DOUBLE_EQ(sampleReliefMap(map, 0.375, 0.75).height, 5.0);
  EXPECT_DOUBLE_EQ(sampleReliefMap(map, 0.25, 0.25).height, 0.5);  // halfway between columns 0 and 1
  EXPECT_DOUBLE_EQ(sampleReliefMap(map, 2.375, -0.25).height, sampleReliefMap(map, 0.375, 0.75).height);
  // Across the seam: halfway between the last column (3) and the first (0).
  EXPECT_DOUBLE_EQ(sampleReliefMap(map, 1.0, 0.25).height, 1.5);
}

TEST(MeshDisplacement, FlatPatchFollowsTheAnalyticDisplacedSurface) {
  const std::vector<BezierPatch> patches{flatPatch()};
  Tessellator tessellator;
  const TriangleMesh& base = tessellator.tessellateUniform(patches, PatchTopology(1), 32);
  const ReliefMap map = sineMap(512, 0.01);
  ReliefDisplacement displacement;
  displacement.map = &map;
  displacement.tiling = 2.0f;
  displacement.amplitude = 1.5f;
  TriangleMesh displaced;
  displaceMesh(base, displacement, displaced);
  ASSERT_EQ(displaced.vertexCount(), base.vertexCount());
  EXPECT_EQ(displaced.indices, base.indices);
  // z = amplitude * h(x * tiling) * (1 m / tiling): a tile is half a metre here.
  const SineSurfaceErrors worst = errorsAgainstSine(base, displaced, 0.5);
  // Bilinear interpolation of a 512-pixel sine: relative error ~ (2 pi / 512)^2 / 8.
  EXPECT_LT(worst.position, 2e-6);
  EXPECT_LT(worst.normal, 1e-3);
}

TEST(MeshDisplacement, NormalsAgreeWithTheDisplacedPositions) {
  // The normal is derived from slopes, the position from heights: a consistent map makes them
  // agree with a finite difference of the displaced surface itself.
  const std::vector<BezierPatch> patches{flatPatch()};
  Tessellator tessellator;
  const TriangleMesh& base = tessellator.tessellateUniform(patches, PatchTopology(1), 32);
  const ReliefMap map = sineMap(256, 0.02);
  ReliefDisplacement displacement{&map, 1.0f, 1.0f, 2.0f};
  TriangleMesh displaced;
  displaceMesh(base, displacement, displaced);
  int checked = 0;
  for (std::size_t t = 0; t < displaced.triangleCount(); ++t) {
    const Eigen::Vector3f& a = displaced.positions[displaced.indices[3 * t]];
    const Eigen::Vector3f& b = displaced.positions[displaced.indices[3 * t + 1]];
    const Eigen::Vector3f& c = displaced.positions[displaced.indices[3 * t + 2]];
    const Eigen::Vector3f face = (b - a).cross(c - a).normalized();
    const Eigen::Vector3f vertex_mean =
        (displaced.normals[displaced.indices[3 * t]] + displaced.normals[displaced.indices[3 * t + 1]] +
         displaced.normals[displaced.indices[3 * t + 2]])
            .normalized();
    EXPECT_GT(face.dot(vertex_mean), std::cos(0.02)) << "triangle " << t;
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

TEST(MeshDisplacement, ZeroAmplitudeKeepsTheMesh) {
  const std::vector<BezierPatch> patches{flatPatch()};
  Tessellator tessellator;
  const TriangleMesh& base = tessellator.tessellateUniform(patches, PatchTopology(1), 8);
  const ReliefMap map = sineMap(64, 0.05);
  TriangleMesh displaced;
  displaceMesh(base, {&map, 3.0f, 1.0f, 0.0f}, displaced);
  for (std::size_t i = 0; i < base.vertexCount(); ++i) {
    EXPECT_EQ(displaced.positions[i], base.positions[i]);
    EXPECT_LT((displaced.normals[i] - base.normals[i]).norm(), 1e-6f);
  }
}

TEST(MeshDisplacement, RejectsBadSettingsByName) {
  const std::vector<BezierPatch> patches{flatPatch()};
  Tessellator tessellator;
  const TriangleMesh& base = tessellator.tessellateUniform(patches, PatchTopology(1), 4);
  const ReliefMap map = sineMap(8, 0.05);
  TriangleMesh out;
  const auto message = [&](const ReliefDisplacement& d) {
    try {
      displaceMesh(base, d, out);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({nullptr, 1.0f, 1.0f, 1.0f}).find("no relief map"), std::string::npos);
  EXPECT_NE(message({&map, 0.0f, 1.0f, 1.0f}).find("tiling"), std::string::npos);
  EXPECT_NE(message({&map, 1.0f, -1.0f, 1.0f}).find("height_to_tile"), std::string::npos);
  EXPECT_NE(message({&map, 1.0f, 1.0f, -0.5f}).find("amplitude"), std::string::npos);
  EXPECT_NE(message({&map, 1.0f, 1.0f, std::nanf("")}).find("amplitude"), std::string::npos);
}

// Tiles per patch (the skin's, skin_relief_tiling.h): 2 tiles along u and 3 along v on the 1 m
// patch, so a tile is 0.5 m x 0.33 m and heights scale by their geometric mean; positions and
// normals against the analytic surface z = A h(2 x) sqrt(1/6), dz/dx = A h'(2 x) 2 sqrt(1/6).
// The same tiles along u and v give exactly what the scalar tiling gives.
TEST(MeshDisplacement, TilesPerPatchFollowTheAnalyticDisplacedSurface) {
  const std::vector<BezierPatch> patches{flatPatch()};
  Tessellator tessellator;
  const TriangleMesh& base = tessellator.tessellateUniform(patches, PatchTopology(1), 32);
  const ReliefMap map = sineMap(512, 0.01);
  const std::vector<Eigen::Vector2f> tiles{Eigen::Vector2f(2.0f, 3.0f)};
  ReliefDisplacement displacement;
  displacement.map = &map;
  displacement.amplitude = 1.5f;
  displacement.patch_tiles = &tiles;
  TriangleMesh displaced;
  displaceMesh(base, displacement, displaced);
  const SineSurfaceErrors worst = errorsAgainstSine(base, displaced, std::sqrt(1.0 / 6.0));
  EXPECT_LT(worst.position, 2e-6);
  EXPECT_LT(worst.normal, 1e-3);

  const std::vector<Eigen::Vector2f> square{Eigen::Vector2f(2.0f, 2.0f)};
  displacement.patch_tiles = &square;
  TriangleMesh per_patch, scalar;
  displaceMesh(base, displacement, per_patch);
  displacement.patch_tiles = nullptr;
  displacement.tiling = 2.0f;
  displaceMesh(base, displacement, scalar);
  for (std::size_t i = 0; i < base.vertexCount(); ++i) {
    EXPECT_LT((per_patch.positions[i] - scalar.positions[i]).norm(), 1e-7f) << i;
    EXPECT_LT((per_patch.normals[i] - scalar.normals[i]).norm(), 1e-6f) << i;
  }
}

TEST(MeshDisplacement, RejectsBadTilesPerPatchByName) {
  const std::vector<BezierPatch> patches{flatPatch()};
  Tessellator tessellator;
  const TriangleMesh& base = tessellator.tessellateUniform(patches, PatchTopology(1), 4);
  const ReliefMap map = sineMap(8, 0.05);
  TriangleMesh out;
  const auto message = [&](const std::vector<Eigen::Vector2f>& tiles, const FoldTiles* folds = nullptr) {
    ReliefDisplacement displacement;
    displacement.map = &map;
    displacement.patch_tiles = &tiles;
    displacement.folds = folds;
    try {
      displaceMesh(base, displacement, out);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({Eigen::Vector2f(1.0f, 4.0f)}), "no error");
  EXPECT_NE(message({Eigen::Vector2f(0.0f, 1.0f)}).find("tiles per patch must be finite and > 0"), std::string::npos);
  EXPECT_NE(message({Eigen::Vector2f(1.0f, std::nanf(""))}).find("tiles per patch"), std::string::npos);
  EXPECT_NE(message({}).find("vertex on patch 0 of 0 with tiles"), std::string::npos);
  const FoldTiles folds(map, map);
  EXPECT_NE(message({Eigen::Vector2f(1.0f, 1.0f)}, &folds).find("no tiles per patch"), std::string::npos);
}

}  // namespace
}  // namespace dressed_human

namespace dressed_human {
namespace {

TEST(MeshDisplacement, VertexWeightsScaleTheAmplitude) {
  const std::vector<BezierPatch> patches{flatPatch()};
  Tessellator tessellator;
  const TriangleMesh& base = tessellator.tessellateUniform(patches, PatchTopology(1), 8);
  const ReliefMap map = sineMap(64, 0.05);
  std::vector<float> weights(base.vertexCount());
  for (std::size_t i = 0; i < weights.size(); ++i) weights[i] = i % 2 ? 1.0f : 0.0f;
  ReliefDisplacement displacement{&map, 1.0f, 1.0f, 2.0f};
  TriangleMesh full, weighted;
  displaceMesh(base, displacement, full);
  displacement.weights = &weights;
  displaceMesh(base, displacement, weighted);
  for (std::size_t i = 0; i < base.vertexCount(); ++i) {
    EXPECT_EQ(weighted.positions[i], i % 2 ? full.positions[i] : base.positions[i]) << i;
  }
  weights.pop_back();
  EXPECT_THROW(displaceMesh(base, displacement, weighted), std::invalid_argument);
}

}  // namespace
}  // namespace dressed_human

namespace dressed_human {
namespace {

// Fold tiles (oriented_folds.h) displace by orientedFolds at each vertex, weighted by the wrinkle
// strength; a tiling other than 1 and fold axes of another count are refused by name.
TEST(MeshDisplacement, FoldTilesDisplaceByTheOrientedFolds) {
  const std::vector<BezierPatch> patches{flatPatch()};
  Tessellator tessellator;
  const TriangleMesh& base = tessellator.tessellateUniform(patches, PatchTopology(1), 8);
  const FoldTiles folds(sineMap(32, 0.05), sineMap(32, 0.08));
  std::vector<float> strength(base.vertexCount(), 0.7f);
  std::vector<Eigen::Vector2f> axes(base.vertexCount(), Eigen::Vector2f(0.3f, 0.2f));
  ReliefDisplacement displacement{&folds.strong, 1.0f, 1.0f, 1.0f, &strength, &folds, &axes};
  TriangleMesh out;
  displaceMesh(base, displacement, out);
  for (std::size_t i = 0; i < base.vertexCount(); ++i) {
    const double height = orientedFolds(folds, base.uv[i].cast<double>(), axes[i], strength[i]).height;
    const double moved = (out.positions[i] - base.positions[i]).cast<double>().dot(base.normals[i].cast<double>());
    const double metres_per_tile = std::sqrt(base.tangents_u[i].norm() * base.tangents_v[i].norm());
    EXPECT_NEAR(moved, height * metres_per_tile, 1e-5) << i;
  }
  displacement.tiling = 2.0f;
  try {
    displaceMesh(base, displacement, out);
    ADD_FAILURE() << "tiling 2 with fold tiles accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("tiling"), std::string::npos) << error.what();
  }
  displacement.tiling = 1.0f;
  axes.pop_back();
  try {
    displaceMesh(base, displacement, out);
    ADD_FAILURE() << "too few fold axes accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("fold axes"), std::string::npos) << error.what();
  }
}

// h(U, V) = a sin(2 pi cycles U): `cycles` periods per tile along u.
ReliefMap waveMap(int size, int cycles, double a) {
  ReliefMap map(size, size);
  for (int r = 0; r < size; ++r) {
    for (int c = 0; c < size; ++c) {
      const double phase = 2.0 * kPi * cycles * (c + 0.5) / size;
      map.heights[map.index(c, r)] = static_cast<float>(a * std::sin(phase));
      map.slope_u[map.index(c, r)] = static_cast<float>(a * 2.0 * kPi * cycles * std::cos(phase));
    }
  }
  return map;
}

// Amplitude of the vertices' displacement along one row of a flat 1 m patch cut 16 x 16 (RMS
// times sqrt 2, over the 16 vertices of a period of the grid).
double displacedAmplitude(const ReliefMap& map, const std::vector<ReliefMap>* mips) {
  const std::vector<BezierPatch> patches{flatPatch()};
  Tessellator tessellator;
  const int level = 16;
  const TriangleMesh& base = tessellator.tessellateUniform(patches, PatchTopology(1), level);
  const std::vector<int> levels{level};
  ReliefDisplacement displacement{&map, 1.0f, 1.0f, 1.0f};
  displacement.map_mips = mips;
  displacement.patch_levels = mips ? &levels : nullptr;
  TriangleMesh out;
  displaceMesh(base, displacement, out);
  double squares = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < base.vertexCount(); ++i) {
    if (std::abs(base.uv[i].y() - 0.5f) > 1e-6f || base.uv[i].x() > 1.0f - 1e-6f) continue;
    const double moved = (out.positions[i] - base.positions[i]).z();
    squares += moved * moved;
    ++count;
  }
  EXPECT_EQ(count, level);
  return std::sqrt(2.0 * squares / count);
}

TEST(MeshDisplacement, ReliefFinerThanTheVerticesFadesInsteadOfAliasing) {
  // Vertices 1/16 of a tile apart carry at most 8 periods per tile. 13 periods sampled there
  // read as 3 periods at full height: a coarse false relief that crawls as the surface moves.
  const ReliefMap fine = waveMap(512, 13, 0.01);
  const std::vector<ReliefMap> fine_mips = buildMipChain(fine);
  EXPECT_GT(displacedAmplitude(fine, nullptr), 0.009);  // unfiltered: the alias, full height
  EXPECT_LT(displacedAmplitude(fine, &fine_mips), 0.003);
  // Relief the vertices can carry (2 periods, 8 vertices each) keeps most of its height.
  const ReliefMap coarse = waveMap(512, 2, 0.01);
  const std::vector<ReliefMap> coarse_mips = buildMipChain(coarse);
  EXPECT_NEAR(displacedAmplitude(coarse, nullptr), 0.01, 0.0005);
  EXPECT_GT(displacedAmplitude(coarse, &coarse_mips), 0.008);
}

TEST(MeshDisplacement, FilteredLookupsReadLevelZeroAtTexelSpacing) {
  const ReliefMap map = waveMap(64, 3, 0.02);
  const std::vector<ReliefMap> mips = buildMipChain(map);
  for (const double u : {0.1, 0.37, 0.9}) {
    EXPECT_DOUBLE_EQ(sampleReliefLevels(mips, u, 0.3, 1.0).height, sampleReliefMap(map, u, 0.3).height);
    EXPECT_DOUBLE_EQ(sampleReliefLevels(mips, u, 0.3, 4.0).height, sampleReliefMap(mips[2], u, 0.3).height);
    const double between = sampleReliefLevels(mips, u, 0.3, std::pow(2.0, 2.5)).height;
    EXPECT_NEAR(between, 0.5 * (sampleReliefMap(mips[2], u, 0.3).height + sampleReliefMap(mips[3], u, 0.3).height),
                1e-12);
  }
  EXPECT_THROW(sampleReliefLevels({}, 0.1, 0.1, 1.0), std::invalid_argument);
  const FoldTiles folds(sineMap(32, 0.05), sineMap(32, 0.08));
  const FoldTileMips fold_mips = buildFoldTileMips(folds);
  const Eigen::Vector2d at(0.3, 0.7);
  EXPECT_DOUBLE_EQ(orientedFolds(fold_mips, at, Eigen::Vector2f(0.3f, 0.1f), 0.6f, 0.0).height,
                   orientedFolds(folds, at, Eigen::Vector2f(0.3f, 0.1f), 0.6f).height);
}

TEST(MeshDisplacement, FilteringNeedsEveryVertexPatchsLevel) {
  const std::vector<BezierPatch> patches{flatPatch()};
  Tessellator tessellator;
  const TriangleMesh& base = tessellator.tessellateUniform(patches, PatchTopology(1), 4);
  const ReliefMap map = waveMap(16, 1, 0.01);
  const std::vector<ReliefMap> mips = buildMipChain(map);
  ReliefDisplacement displacement{&map, 1.0f, 1.0f, 1.0f};
  displacement.map_mips = &mips;
  TriangleMesh out;
  EXPECT_THROW(displaceMesh(base, displacement, out), std::invalid_argument);  // no levels
  const std::vector<int> none;
  displacement.patch_levels = &none;
  try {
    displaceMesh(base, displacement, out);
    ADD_FAILURE() << "a patch without a level accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("tessellation level"), std::string::npos) << error.what();
  }
  const std::vector<ReliefMap> other = buildMipChain(waveMap(8, 1, 0.01));
  const std::vector<int> levels{4};
  displacement.patch_levels = &levels;
  displacement.map_mips = &other;
  EXPECT_THROW(displaceMesh(base, displacement, out), std::invalid_argument);
}

}  // namespace
}  // namespace dressed_human
