// HumanModel (human_model.h): outfits become the expected surface parts, the level of detail is
// validated, and the displaced-geometry relief mode moves each part by no more than its map
// allows while leaving bump-mapped parts untouched.
#include "dressed_human/core/model/human_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "garment_test_support.h"

namespace dressed_human {
namespace {

using namespace garment_test;

HumanModelSettings settingsFor(Outfit outfit) {
  HumanModelSettings settings;
  settings.outfit = outfit;
  settings.garment_directory = sourcePath("config/garments");
  return settings;
}

TEST(HumanModel, OutfitsBecomeTheirParts) {
  const SkeletonPose pose = walkPoses(1, body().shape)[0];
  const std::vector<std::pair<Outfit, std::vector<std::string>>> expected{
      {Outfit::kNone, {"skin"}},
      {Outfit::kOnePiece, {"skin", "one_piece"}},
      {Outfit::kJacketSkirt, {"skin", "skirt", "jacket"}},
      {Outfit::kJacketPants, {"skin", "pants", "jacket"}}};
  for (const auto& outfit : expected) {
    HumanModel model(skeleton(), body(), settingsFor(outfit.first));
    model.update(pose.root, pose.bone_in_world, LevelOfDetail());
    ASSERT_EQ(model.parts().size(), outfit.second.size());
    for (std::size_t p = 0; p < outfit.second.size(); ++p) {
      EXPECT_EQ(model.parts()[p].name, outfit.second[p]);
      EXPECT_EQ(model.parts()[p].relief, p == 0 ? ReliefKind::kSkin : ReliefKind::kCloth);
      ASSERT_NE(model.parts()[p].mesh, nullptr);
      EXPECT_GT(model.parts()[p].mesh->triangleCount(), 100u);
    }
  }
  EXPECT_THROW(outfitFromName("bikini"), std::invalid_argument);
  EXPECT_EQ(outfitFromName("jacket_pants"), Outfit::kJacketPants);
}

TEST(HumanModel, RejectsABadFixedLevel) {
  const SkeletonPose pose = walkPoses(1, body().shape)[0];
  HumanModel model(skeleton(), body(), settingsFor(Outfit::kNone));
  LevelOfDetail lod;
  lod.level = 0;
  EXPECT_THROW(model.update(pose.root, pose.bone_in_world, lod), std::invalid_argument);
  lod.level = 6;
  EXPECT_NO_THROW(model.update(pose.root, pose.bone_in_world, lod));
}

// The box a renderer culls by (SurfacePart::bounds) holds every vertex of the posed part, in
// every vertex-evaluation mode, level of detail, outfit and relief setting, in every pose of a
// walk that moves the human away from where it started: a box that stays behind hides the human
// (issue "The human stays on screen").
TEST(HumanModel, BoundsEncloseThePosedPartInEveryModeAndPose) {
  std::vector<SkeletonPose> poses = walkPoses(4, body().shape);
  for (std::size_t k = 0; k < poses.size(); ++k) {
    // Far from the origin, as after a minute of walking, and further each pose.
    const Eigen::Vector3d shift(40.0 + 3.0 * static_cast<double>(k), -7.0, 0.0);
    poses[k].root.translation += shift;
    for (RigidTransform& bone : poses[k].bone_in_world) bone.translation += shift;
  }
  auto map = std::make_shared<ReliefMap>(32, 32);
  for (int r = 0; r < 32; ++r) {
    for (int c = 0; c < 32; ++c)
      map->heights[map->index(c, r)] = 0.3f * static_cast<float>(std::cos(0.4 * c - 0.7 * r));
  }
  std::vector<LevelOfDetail> lods;
  for (const int level : {1, 3, 16}) {
    LevelOfDetail fixed;
    fixed.level = level;
    lods.push_back(fixed);
  }
  for (const double distance : {0.5, 60.0}) {
    LevelOfDetail automatic;
    automatic.automatic = true;
    automatic.camera.position = Eigen::Vector3d(40.0 + distance, -7.0 + distance, 1.5);
    lods.push_back(automatic);
  }
  std::size_t checked = 0;
  for (const Outfit outfit : {Outfit::kNone, Outfit::kOnePiece, Outfit::kJacketSkirt, Outfit::kJacketPants}) {
    for (const VertexEvaluation evaluation : {VertexEvaluation::kCpu, VertexEvaluation::kGpu}) {
      for (const bool displaced : {false, true}) {
        HumanModel model(skeleton(), body(), settingsFor(outfit));
        model.setVertexEvaluation(evaluation);
        if (displaced) {
          model.setDisplacement(ReliefKind::kSkin, map, 2.0f, 1.0f, 1.0f);
          model.setDisplacement(ReliefKind::kCloth, map, 1.0f, 1.0f, 1.0f);
        }
        for (const LevelOfDetail& lod : lods) {
          for (const SkeletonPose& pose : poses) {
            model.update(pose.root, pose.bone_in_world, lod);
            for (const SurfacePart& part : model.parts()) {
              ASSERT_FALSE(part.bounds.isEmpty()) << part.name;
              const Eigen::AlignedBox3f box = part.bounds;
              // A box that encloses the human wherever it has ever been would never hide it, but
              // would never let Ogre cull it either: the box is this pose's (a person, a few m).
              EXPECT_LT(box.diagonal().norm(), 3.0f) << part.name;
              for (std::size_t i = 0; i < part.mesh->vertexCount(); ++i) {
                Eigen::Vector3f position;
                if (part.cpuVertices() != nullptr) {
                  position = part.mesh->positions[i];
                } else {  // as the vertex shader evaluates it
                  const BezierPatch& patch = (*part.patches)[part.mesh->vertex_patch[i]];
                  position = patch.position(part.mesh->uv[i].x(), part.mesh->uv[i].y()).cast<float>();
                }
                ASSERT_TRUE(box.contains(position))
                    << part.name << " vertex " << i << " at " << position.transpose() << " outside ["
                    << box.min().transpose() << "] - [" << box.max().transpose() << "]";
                ++checked;
              }
            }
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 500000u);
}

TEST(HumanModel, DisplacedGeometryMovesOnlyTheDisplacedKindWithinItsBound) {
  const SkeletonPose pose = walkPoses(3, body().shape)[1];
  HumanModel plain(skeleton(), body(), settingsFor(Outfit::kJacketSkirt));
  HumanModel displaced(skeleton(), body(), settingsFor(Outfit::kJacketSkirt));
  auto map = std::make_shared<ReliefMap>(64, 64);
  for (int r = 0; r < 64; ++r) {
    // One period per tile each way: the level-8 vertices (4 per tile at tiling 2) carry it;
    // finer relief is filtered out of displaced geometry (mesh_displacement.h).
    for (int c = 0; c < 64; ++c)
      map->heights[map->index(c, r)] = 0.05f * static_cast<float>(std::sin(2.0 * M_PI * (c + r) / 64.0));
  }
  displaced.setDisplacement(ReliefKind::kCloth, map, 2.0f, 1.0f, 1.0f);
  LevelOfDetail lod;
  lod.level = 8;
  plain.update(pose.root, pose.bone_in_world, lod);
  displaced.update(pose.root, pose.bone_in_world, lod);
  ASSERT_EQ(plain.parts().size(), displaced.parts().size());
  for (std::size_t p = 0; p < plain.parts().size(); ++p) {
    const TriangleMesh& a = *plain.parts()[p].mesh;
    const TriangleMesh& b = *displaced.parts()[p].mesh;
    ASSERT_EQ(a.vertexCount(), b.vertexCount());
    double largest = 0.0;
    for (std::size_t i = 0; i < a.vertexCount(); ++i) {
      const double moved = (a.positions[i] - b.positions[i]).norm();
      // |d| <= amplitude * max|h| * sqrt(|F_u| |F_v|) / tiling
      const double bound = 0.05 * std::sqrt(a.tangents_u[i].norm() * a.tangents_v[i].norm()) / 2.0;
      EXPECT_LE(moved, bound + 1e-6) << plain.parts()[p].name << " vertex " << i;
      largest = std::max(largest, moved);
    }
    if (plain.parts()[p].relief == ReliefKind::kSkin) {
      EXPECT_EQ(largest, 0.0) << "the skin is not displaced";
    } else {
      EXPECT_GT(largest, 1e-3) << plain.parts()[p].name << " should move by millimetres";
    }
  }
  // Off again: the same surfaces as the plain model.
  displaced.setDisplacement(ReliefKind::kCloth, nullptr, 1.0f, 1.0f, 1.0f);
  displaced.update(pose.root, pose.bone_in_world, lod);
  for (std::size_t p = 0; p < plain.parts().size(); ++p) {
    EXPECT_EQ(plain.parts()[p].mesh->positions, displaced.parts()[p].mesh->positions);
  }
  EXPECT_THROW(displaced.setDisplacement(ReliefKind::kSkin, map, 0.0f, 1.0f, 1.0f), std::invalid_argument);
}

}  // namespace
}  // namespace dressed_human

namespace dressed_human {
namespace {

using namespace garment_test;

// Garment relief follows compression (wrinkle_placement.h): none in the rest pose, some behind
// a bent knee; the skin has no weights (all of its relief shows).
TEST(HumanModel, GarmentReliefWeightsFollowTheKnee) {
  HumanModelSettings settings;
  settings.outfit = Outfit::kJacketPants;
  settings.garment_directory = sourcePath("config/garments");
  HumanModel model(skeleton(), body(), settings);
  ForwardKinematics fk(skeleton(), body().shape);
  const auto poseWithKnee = [&](double angle) {
    JointAngles angles{};
    angles[static_cast<std::size_t>(skeleton().findJoint("l_knee") * 3)] = angle;  // y: flexion axis
    SkeletonPose pose;
    fk.compute(RigidTransform(), angles, pose);
    return pose;
  };
  // Anatomical flexion swings the ankle backwards (-x); pick the sign of the y angle that does.
  const std::size_t ankle = static_cast<std::size_t>(skeleton().findBone("l_ankle"));
  const double sign =
      poseWithKnee(0.3).bone_in_world[ankle].translation.x() < poseWithKnee(0.0).bone_in_world[ankle].translation.x()
          ? 1.0
          : -1.0;
  const auto strongest = [&](double knee_flexion) {
    const SkeletonPose pose = poseWithKnee(sign * knee_flexion);
    model.update(pose.root, pose.bone_in_world, LevelOfDetail());
    EXPECT_EQ(model.parts()[0].cpuVertices()->relief_weight, nullptr);
    const SurfacePart& pants = model.parts()[1];
    EXPECT_EQ(pants.name, "pants");
    const std::vector<float>* weights = pants.cpuVertices()->relief_weight;
    if (weights == nullptr) return -1.0f;
    EXPECT_EQ(weights->size(), pants.mesh->vertexCount());
    float largest = 0.0f;
    for (const float w : *weights) {
      EXPECT_GE(w, 0.0f);
      EXPECT_LE(w, 1.0f);
      largest = std::max(largest, w);
    }
    return largest;
  };
  EXPECT_LT(strongest(0.0), 1e-3f) << "no wrinkles at rest";
  EXPECT_GT(strongest(1.2), 0.5f) << "wrinkles behind a knee bent 70 degrees";
  // Every split vertex (SurfacePart::corners) copies a mesh vertex; the fold axes come along.
  const SurfacePart& pants = model.parts()[1];
  ASSERT_NE(pants.corners, nullptr);
  ASSERT_NE(pants.cpuVertices()->fold_axis, nullptr);
  EXPECT_EQ(pants.cpuVertices()->fold_axis->size(), pants.mesh->vertexCount());
  EXPECT_GE(pants.corners->source.size(), pants.mesh->vertexCount());
  // A renderer not drawing the wrinkles (too small to see) is spared their per-vertex work.
  model.setWrinklesWanted(false);
  EXPECT_EQ(strongest(1.2), -1.0f);
  EXPECT_EQ(model.parts()[1].cpuVertices()->fold_axis, nullptr);
  model.setWrinklesWanted(true);
  EXPECT_GT(strongest(1.2), 0.5f);
}

// VertexEvaluation::kGpu hands the renderer the layout, the posed patches and the rest
// metric instead of vertices. What a vertex shader computes from them -- the patch at
// (vertex_patch, uv), the wrinkle strength from the rest metric -- must be what kCpu delivers.
TEST(HumanModel, RendererEvaluationGetsWhatTheCpuPathEvaluates) {
  HumanModelSettings settings;
  settings.outfit = Outfit::kJacketPants;
  settings.garment_directory = sourcePath("config/garments");
  HumanModel cpu(skeleton(), body(), settings);
  HumanModel renderer(skeleton(), body(), settings);
  renderer.setVertexEvaluation(VertexEvaluation::kGpu);
  LevelOfDetail lod;  // fixed: both paths lay the mesh out alike
  lod.level = 5;
  const std::vector<SkeletonPose> poses = walkPoses(4, body().shape);
  float strongest = 0.0f;
  for (const SkeletonPose& pose : poses) {
    cpu.update(pose.root, pose.bone_in_world, lod);
    renderer.update(pose.root, pose.bone_in_world, lod);
    ASSERT_EQ(cpu.parts().size(), renderer.parts().size());
    for (std::size_t p = 0; p < cpu.parts().size(); ++p) {
      const SurfacePart& expected = cpu.parts()[p];
      const SurfacePart& part = renderer.parts()[p];
      ASSERT_NE(expected.cpuVertices(), nullptr);
      ASSERT_NE(part.gpuVertices(), nullptr);
      const GpuVertices& gpu = *part.gpuVertices();
      EXPECT_NE(part.layout_id, expected.layout_id) << "layout ids are unique across tessellators";
      ASSERT_EQ(part.mesh->indices, expected.mesh->indices) << part.name;
      ASSERT_EQ(part.mesh->vertex_patch.size(), expected.mesh->vertexCount());
      ASSERT_EQ(part.mesh->uv.size(), expected.mesh->vertexCount());
      ASSERT_NE(part.patches, nullptr);
      EXPECT_EQ(p > 0, gpu.inverse_rest_metric != nullptr);
      double worst_position = 0.0, worst_weight = 0.0;
      for (std::size_t i = 0; i < part.mesh->vertexCount(); ++i) {
        const BezierPatch& patch = (*part.patches)[part.mesh->vertex_patch[i]];
        const PatchDerivatives d = patch.derivatives(part.mesh->uv[i].x(), part.mesh->uv[i].y());
        worst_position = std::max(worst_position, (d.position - expected.mesh->positions[i].cast<double>()).norm());
        if (p == 0) continue;
        // What relief_surface.vert computes from the renderer's inputs.
        const float strength = vertexStretchAt((*gpu.inverse_rest_metric)[i], d.d_du.cast<float>(),
                                               d.d_dv.cast<float>(), gpu.wrinkle_constants)
                                   .strength;
        worst_weight = std::max(worst_weight,
                                static_cast<double>(std::abs(strength - (*expected.cpuVertices()->relief_weight)[i])));
        strongest = std::max(strongest, (*expected.cpuVertices()->relief_weight)[i]);
      }
      EXPECT_LT(worst_position, 1e-5) << part.name;  // float storage of the CPU mesh
      EXPECT_LT(worst_weight, 1e-3) << part.name;
    }
    // Same pose again: same levels, so the renderer's copy of the layout stays valid.
    const std::uint64_t skin_layout = renderer.parts()[0].layout_id;
    renderer.update(pose.root, pose.bone_in_world, lod);
    EXPECT_EQ(renderer.parts()[0].layout_id, skin_layout);
  }
  EXPECT_GT(strongest, 0.1f) << "the walk must bend a knee enough to test the wrinkle weights";

  // Automatic levels for the renderer move on a coarse ladder (fewer layout changes), never
  // below what the screen-space error asks for by the part's calibrated bound, and below what
  // the a-priori bound would have drawn on some patches.
  LevelOfDetail automatic;
  automatic.automatic = true;
  automatic.camera.position = Eigen::Vector3d(3.0, -2.0, 1.2);
  std::size_t coarser_than_apriori = 0;
  for (const SkeletonPose& pose : poses) {
    renderer.update(pose.root, pose.bone_in_world, automatic);
    for (std::size_t p = 0; p < renderer.parts().size(); ++p) {
      const std::vector<BezierPatch>& patches = renderer.partPatches(p);
      const std::vector<int>& levels = renderer.partLevels(p);
      std::vector<int> wanted;
      renderer.partErrorBound(p).levelsForScreenError(patches, automatic.camera, automatic.max_error_pixels,
                                                      automatic.max_level, wanted);
      for (std::size_t k = 0; k < patches.size(); ++k) {
        EXPECT_GE(levels[k], wanted[k]) << renderer.parts()[p].name << " patch " << k;
        const int apriori =
            levelForScreenError(patches[k], automatic.camera, automatic.max_error_pixels, automatic.max_level);
        coarser_than_apriori += levels[k] < apriori ? 1 : 0;
        const std::vector<int> ladder{1, 2, 3, 4, 6, 8, 12, 16};
        EXPECT_TRUE(std::count(ladder.begin(), ladder.end(), levels[k]) == 1 || levels[k] == automatic.max_level)
            << levels[k];
      }
    }
  }

  EXPECT_GT(coarser_than_apriori, 0u);

  // Displaced relief needs vertices: those parts are evaluated even in kGpu mode.
  ReliefMap map(8, 8);
  renderer.setDisplacement(ReliefKind::kCloth, std::make_shared<const ReliefMap>(map), 1.0f, 1.0f, 0.01f);
  renderer.update(poses[0].root, poses[0].bone_in_world, lod);
  EXPECT_NE(renderer.parts()[0].gpuVertices(), nullptr);
  ASSERT_NE(renderer.parts()[1].cpuVertices(), nullptr);
  EXPECT_NE(renderer.parts()[1].cpuVertices()->relief_weight, nullptr);
}

}  // namespace
}  // namespace dressed_human
