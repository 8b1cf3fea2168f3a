// Scene budget (issue 8): what the automatic level of detail saves, and what error it costs,
// for one dressed human at 1, 5 and 20 m and for rows of 1, 5 and 10 humans seen from 5 m.
// Prints CSV rows; scripts/make_evaluation.py turns them into a table and a chart.
//
// Each configuration poses the model over `poses` walk phases (config/motions/walk.yaml), twice,
// and reports for the second cycle the median update time (pose + tessellate, one core), the triangle count and the
// tessellation error: per patch the calibrated bound (HumanModel::partErrorBound) in mm,
// and that bound projected to pixels at the patch's nearest distance to the camera (fov 0.8 rad,
// 1000 px viewport, as rviz's default view at that window height). The human's own settings:
// jacket + skirt, its level of detail calibrated in the walk as the display's (calibration_poses.h).
// Automatic level of detail is measured twice: with the CPU evaluating every
// vertex ("cpu") and with the renderer's vertex shader doing it ("gpu", VertexEvaluation::
// kGpu: the update then poses control points and lays out the mesh only).
//
//   scene_budget [package directory, default .] [--poses N]
#include "dressed_human/core/model/calibration_poses.h"
#include "dressed_human/core/model/human_model.h"
#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

using namespace dressed_human;

namespace {

struct Scene {
  const Skeleton& skeleton;
  const BodyDescription& body;
  std::vector<SkeletonPose> poses;
};

struct Measurement {
  double median_update_ms = 0.0;
  std::size_t triangles = 0;
  double max_error_mm = 0.0;
  double max_error_pixels = 0.0;
};

// `humans` models side by side along y, 1 m apart, centred on the origin; the camera looks at
// them from `distance` along x.
Measurement measure(const Scene& scene, const HumanModelSettings& settings, int humans, double distance, bool automatic,
                    int fixed_level, VertexEvaluation evaluation) {
  std::vector<std::unique_ptr<HumanModel>> models;
  for (int h = 0; h < humans; ++h) {
    models.push_back(std::make_unique<HumanModel>(scene.skeleton, scene.body, settings));
    models.back()->setVertexEvaluation(evaluation);
  }
  LevelOfDetail lod;
  lod.automatic = automatic;
  lod.level = fixed_level;
  lod.camera = CameraView{Eigen::Vector3d(distance, 0.0, 1.0), 0.8, 1000.0};
  std::vector<double> times;
  Measurement result;
  // Two gait cycles, the second one timed: the first settles the automatic levels (they only
  // drop after a while, human_model.cpp), as they are settled in a running display.
  for (std::size_t step = 0; step < 2 * scene.poses.size(); ++step) {
    const SkeletonPose& pose = scene.poses[step % scene.poses.size()];
    const bool timed = step >= scene.poses.size();
    const auto start = std::chrono::steady_clock::now();
    for (int h = 0; h < humans; ++h) {
      // The walk advances along x; keep every human at its place, facing the camera's side.
      RigidTransform root = pose.root;
      root.translation = Eigen::Vector3d(0.0, (h - 0.5 * (humans - 1)) * 1.0, root.translation.z());
      std::array<RigidTransform, kBoneCount> bones = pose.bone_in_world;
      for (RigidTransform& bone : bones) bone.translation += root.translation - pose.root.translation;
      models[static_cast<std::size_t>(h)]->update(root, bones, lod);
    }
    if (!timed) continue;
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    result.triangles = 0;
    for (const auto& model : models) {
      result.triangles += model->triangleCount();
      for (std::size_t part = 0; part < model->parts().size(); ++part) {
        const std::vector<BezierPatch>& patches = model->partPatches(part);
        const std::vector<int>& levels = model->partLevels(part);
        for (std::size_t p = 0; p < patches.size(); ++p) {
          const double bound = model->partErrorBound(part).bound(p, patches[p], levels[p]);
          result.max_error_mm = std::max(result.max_error_mm, 1e3 * bound);
          result.max_error_pixels =
              std::max(result.max_error_pixels,
                       bound * pixelsPerMetre(lod.camera, distanceToPatchBounds(patches[p], lod.camera.position)));
        }
      }
    }
  }
  std::sort(times.begin(), times.end());
  result.median_update_ms = times[times.size() / 2];
  return result;
}

}  // namespace

int main(int argc, char** argv) {
  int pose_count = 60;
  std::string source = ".";
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--poses") == 0 && i + 1 < argc) {
      pose_count = std::atoi(argv[++i]);
    } else if (argv[i][0] != '-') {
      source = argv[i];
    } else {
      std::fprintf(stderr, "usage: scene_budget [package directory] [--poses N]  (unknown argument '%s')\n", argv[i]);
      return 2;
    }
  }
  if (pose_count < 3) {
    std::fprintf(stderr, "scene_budget: --poses must be >= 3\n");
    return 2;
  }
  try {
    const Skeleton skeleton = Skeleton::fromUrdfFile(source + "/urdf/human.urdf");
    const BodyDescription body = loadBodyDescriptionFile(source + "/config/bodies/default.yaml", skeleton);
    MotionEvaluator walk(loadMotionFile(source + "/config/motions/walk.yaml"));
    ForwardKinematics fk(skeleton, body.shape);
    Scene scene{skeleton, body, {}};
    for (int k = 0; k < pose_count; ++k) {
      JointAngles angles{};
      RigidTransform root;
      walk.evaluate(walk.motion().period * k / pose_count, angles, root);
      scene.poses.emplace_back();
      fk.compute(root, angles, scene.poses.back());
    }
    HumanModelSettings settings;
    settings.garment_directory = source + "/config/garments";
    settings.calibration_poses = calibrationPoses(walk.motion());
    std::printf("humans,distance_m,lod,level,vertices,median_update_ms,triangles,max_error_mm,max_error_px\n");
    const auto row = [&](int humans, double distance, bool automatic, int level,
                         VertexEvaluation evaluation = VertexEvaluation::kCpu) {
      const Measurement m = measure(scene, settings, humans, distance, automatic, level, evaluation);
      std::printf("%d,%.1f,%s,%d,%s,%.4f,%zu,%.3f,%.3f\n", humans, distance, automatic ? "automatic" : "fixed",
                  automatic ? -1 : level, evaluation == VertexEvaluation::kCpu ? "cpu" : "gpu", m.median_update_ms,
                  m.triangles, m.max_error_mm, m.max_error_pixels);
      std::fflush(stdout);
    };
    const auto rows = [&](int humans, double distance) {
      row(humans, distance, true, 0);
      row(humans, distance, true, 0, VertexEvaluation::kGpu);
      row(humans, distance, false, Skin::kDefaultLevel);
      row(humans, distance, false, Tessellator::kDefaultLevel);
    };
    for (const double distance : {1.0, 5.0, 20.0}) rows(1, distance);
    for (const int humans : {5, 10}) rows(humans, 5.0);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "scene_budget: %s\n", error.what());
    return 1;
  }
  return 0;
}
