// Close-ups of the garment folds inside the left elbow (jacket) and behind the left knee (pants),
// bent and straight (the walk cycle's most and least bent poses), three ways (issue 21's figure):
//   exact      the exact buckling folds (the piecewise-planar tiles) moved into the geometry,
//              laid (fold_coordinates.h) and weighted as the renderer does (displaced geometry,
//              level 64);
//   bump       what the display draws now: the smooth folds laid by the fold coordinates tilting
//              only the normals, per vertex of the same fine mesh (the shader does it per pixel);
//   before     what it drew before issue 21: the exact Y-Y tile once per patch, not oriented,
//              weighted with the old threshold (0.98), tilting the normals.
// Writes <out>/closeup_<joint>_<state>_<method>.png and closeups.csv (joint, state, bend);
// scripts/make_relief_figures.py composes docs/relief/fold_closeups.png.
//
// Usage: fold_closeups <source_directory> <output_directory>
#include "dressed_human/core/garments/garment.h"
#include "dressed_human/core/garments/garment_file.h"
#include "dressed_human/core/model/relief_map_jobs.h"
#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"
#include "dressed_human/core/relief/fold_coordinates.h"
#include "dressed_human/core/relief/mesh_displacement.h"
#include "dressed_human/core/relief/vertex_compression.h"
#include "dressed_human/core/render/mesh_rasterizer.h"
#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/surfaces/patch_corner_split.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace dressed_human;

struct Joint {
  std::string name;     // "elbow", "knee"
  std::string garment;  // its garment file
  std::string upper, lower;
  Eigen::Vector3d colour;
};

Eigen::Vector3d boneAxis(const SkeletonPose& pose, const Skeleton& skeleton, const std::string& bone) {
  return pose.bone_in_world[static_cast<std::size_t>(skeleton.findBone(bone))].rotation * Eigen::Vector3d::UnitZ();
}

double bendDegrees(const SkeletonPose& pose, const Skeleton& skeleton, const Joint& joint) {
  return std::acos(
             std::clamp(boneAxis(pose, skeleton, joint.upper).dot(boneAxis(pose, skeleton, joint.lower)), -1.0, 1.0)) *
         180.0 / M_PI;
}

// The walk's poses, one per 1/120 of the cycle.
std::vector<SkeletonPose> walkPoses(const std::string& source, const Skeleton& skeleton, const BodyShape& shape) {
  MotionEvaluator evaluator(loadMotionFile(source + "/config/motions/walk.yaml"));
  ForwardKinematics fk(skeleton, shape);
  std::vector<SkeletonPose> poses(120);
  for (std::size_t k = 0; k < poses.size(); ++k) {
    JointAngles angles{};
    RigidTransform root;
    evaluator.evaluate(evaluator.motion().period * static_cast<double>(k) / poses.size(), angles, root);
    fk.compute(root, angles, poses[k]);
  }
  return poses;
}

// The garment's map before issue 21: the exact Y-Y tile with L_y = L_x, once per patch.
ReliefMap previousWrinkleMap() {
  WrinkleMapSpec spec = garmentWrinkleMapSpec(0.0);
  spec.cell.half_length_y = spec.cell.half_width_x;
  return transposed(makeWrinkleMap(spec));
}

void render(const TriangleMesh& mesh, const SkeletonPose& pose, const Skeleton& skeleton, const Joint& joint,
            const Eigen::Vector3d& view, const std::string& path) {
  RasterCamera camera;
  camera.target = pose.bone_in_world[static_cast<std::size_t>(skeleton.findBone(joint.lower))].translation;
  camera.eye = camera.target + 0.42 * view;
  camera.up = Eigen::Vector3d::UnitZ();
  camera.vertical_fov_radians = 40.0 * M_PI / 180.0;
  MeshRasterizer rasterizer(360, 360, camera);
  rasterizer.clear(Eigen::Vector3d(0.18, 0.18, 0.18));
  RasterMaterial material;
  material.colour = joint.colour;
  rasterizer.draw(mesh, material, view + Eigen::Vector3d(0.0, 0.0, 0.6));  // from above the camera
  rasterizer.writePng(path);
}

int run(const std::string& source, const std::string& directory) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(source + "/urdf/human.urdf");
  const BodyDescription body = loadBodyDescriptionFile(source + "/config/bodies/default.yaml", skeleton);
  const std::vector<SkeletonPose> poses = walkPoses(source, skeleton, body.shape);
  const FoldTiles smooth = garmentFoldTiles();
  const FoldTiles exact = garmentFoldTiles(512, 0.0);
  const ReliefMap before = previousWrinkleMap();
  WrinklePlacementOptions previous_options;
  previous_options.alpha_threshold = 0.98;
  std::ofstream csv(directory + "/closeups.csv");
  csv << "joint,state,bend_deg\n";
  for (const Joint& joint : {Joint{"elbow", "jacket", "l_shoulder", "l_elbow", {0.25, 0.38, 0.78}},
                             Joint{"knee", "pants", "l_hip", "l_knee", {0.35, 0.35, 0.42}}}) {
    Garment garment(loadGarmentFile(source + "/config/garments/" + joint.garment + ".yaml", skeleton), skeleton,
                    body.shape);
    const std::vector<BezierPatch> rest = garment.patches();
    std::size_t bent = 0, straight = 0;
    for (std::size_t k = 0; k < poses.size(); ++k) {
      if (bendDegrees(poses[k], skeleton, joint) > bendDegrees(poses[bent], skeleton, joint)) bent = k;
      if (bendDegrees(poses[k], skeleton, joint) < bendDegrees(poses[straight], skeleton, joint)) straight = k;
    }
    // Into the crook of the bent joint (between the bones), half from outside the body, level.
    const SkeletonPose& pose = poses[bent];
    const Eigen::Vector3d crook =
        (boneAxis(pose, skeleton, joint.lower) - boneAxis(pose, skeleton, joint.upper)).normalized();
    Eigen::Vector3d outward = pose.bone_in_world[static_cast<std::size_t>(skeleton.findBone(joint.lower))].translation -
                              pose.root.translation;
    outward.z() = 0.0;
    Eigen::Vector3d view = crook + outward.normalized();
    view.z() = 0.25 * view.head<2>().norm();
    view.normalize();
    for (const auto& [state, k] : {std::make_pair("bent", bent), std::make_pair("straight", straight)}) {
      garment.pose(poses[k]);
      Tessellator tessellator;
      const TriangleMesh mesh =
          tessellator.tessellateUniform(garment.patches(), garment.topology(), Tessellator::kMaxLevel);
      VertexCompression compression, previous(previous_options);
      compression.prepare(mesh, rest);
      previous.prepare(mesh, rest);
      std::vector<float> strength(mesh.vertexCount()), previous_strength(mesh.vertexCount());
      std::vector<Eigen::Vector2f> axes(mesh.vertexCount());
      compression.evaluate(mesh, nullptr, strength.data(), axes.data());
      previous.evaluate(mesh, nullptr, previous_strength.data());
      // The fold coordinates as the display solves them: on the garment's own grid, sampled here.
      Tessellator grid_tessellator;
      const TriangleMesh& grid = grid_tessellator.tessellate(
          garment.patches(), garment.topology(), std::vector<int>(garment.patches().size(), FoldCoordinates::kGridLevel));
      PatchCornerSplit grid_split;
      splitPatchCorners(grid, grid_tessellator.triangleCornerParameters(), grid_split);
      VertexCompression grid_compression;
      grid_compression.prepare(grid, rest);
      std::vector<float> grid_strength(grid.vertexCount());
      std::vector<Eigen::Vector2f> grid_axes(grid.vertexCount()), fold_tiles, fold_directions;
      grid_compression.evaluate(grid, nullptr, grid_strength.data(), grid_axes.data());
      FoldCoordinates folds;
      folds.prepare(grid, grid_split);
      folds.solve(grid_axes, grid_strength);
      folds.sample(mesh, fold_tiles, fold_directions);
      const float height_to_tile = ReliefMapJobs::clothHeightToTile();
      TriangleMesh exact_mesh, bump_mesh, before_mesh;
      ReliefDisplacement exact_folds{&exact.strong, 1.0f, height_to_tile, 1.0f, &strength, &exact, &axes};
      exact_folds.fold_tiles = &fold_tiles;
      exact_folds.fold_directions = &fold_directions;
      displaceMesh(mesh, exact_folds, exact_mesh);
      ReliefDisplacement smooth_folds = exact_folds;
      smooth_folds.map = &smooth.strong;
      smooth_folds.folds = &smooth;
      displaceMesh(mesh, smooth_folds, bump_mesh);
      displaceMesh(mesh, ReliefDisplacement{&before, 1.0f, height_to_tile, 1.0f, &previous_strength, nullptr, nullptr},
                   before_mesh);
      bump_mesh.positions = mesh.positions;  // bump mapping tilts normals only
      before_mesh.positions = mesh.positions;
      const std::string stem = directory + "/closeup_" + joint.name + "_" + state + "_";
      render(exact_mesh, poses[k], skeleton, joint, view, stem + "exact.png");
      render(bump_mesh, poses[k], skeleton, joint, view, stem + "bump.png");
      render(before_mesh, poses[k], skeleton, joint, view, stem + "before.png");
      csv << joint.name << "," << state << "," << bendDegrees(poses[k], skeleton, joint) << "\n";
    }
  }
  std::cout << "wrote " << directory << "/closeups.csv and 12 close-ups\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: fold_closeups <source_directory> <output_directory>\n";
    return 2;
  }
  try {
    return run(argv[1], argv[2]);
  } catch (const std::exception& error) {
    std::cerr << "fold_closeups: " << error.what() << "\n";
    return 1;
  }
}
