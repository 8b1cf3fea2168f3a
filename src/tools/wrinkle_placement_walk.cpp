// Wrinkle placement over one walk cycle (issue 6): per pose, the compression alpha of every
// region of the pants and the jacket (wrinkle_placement.h) with the chosen pattern and
// amplitude, the knee and elbow bend, and the shaded pose wrinkle tile behind the left knee at
// the least, a middle and the most compressed pose. scripts/make_relief_figures.py draws
// docs/relief/wrinkle_placement_walk.png from this. wrinkle_walk_strength.csv: the wrinkle
// strength the renderer shows (vertex_compression.h: the fraction of the fold tile's height
// drawn) at each region's sample points, mean and largest, against the knee and elbow bend, for
// docs/relief/fold_strength_vs_flexion.png.
//
// Usage: wrinkle_placement_walk <source_directory> <output_directory> [poses (default 60)]
#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/garments/garment_file.h"
#include "dressed_human/core/relief/lambert_shading.h"
#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"
#include "dressed_human/core/io/png_writer.h"
#include "dressed_human/core/relief/vertex_compression.h"
#include "dressed_human/core/relief/wrinkle_placement.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace dressed_human;

double bendDegrees(const SkeletonPose& pose, const Skeleton& skeleton, const char* upper, const char* lower) {
  const Eigen::Vector3d a =
      pose.bone_in_world[static_cast<std::size_t>(skeleton.findBone(upper))].rotation * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d b =
      pose.bone_in_world[static_cast<std::size_t>(skeleton.findBone(lower))].rotation * Eigen::Vector3d::UnitZ();
  return std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * 180.0 / M_PI;
}

// The shown strength at one region's samples (what relief_surface.vert computes at vertices
// there): mean and largest.
std::pair<double, double> shownStrength(const WrinklePlacement& placement, const std::vector<BezierPatch>& posed,
                                        const CompressionRegion& region) {
  const WrinkleStrengthConstants constants = VertexCompression(placement.options()).strengthConstants();
  double sum = 0.0, largest = 0.0;
  for (const SurfacePoint& at : region.samples) {
    const PatchDerivatives rest = placement.restPatches()[at.patch].derivatives(at.u, at.v);
    const PatchDerivatives now = posed[at.patch].derivatives(at.u, at.v);
    const double strength = vertexStretchAt(inverseRestMetric(rest.d_du, rest.d_dv), now.d_du.cast<float>(),
                                            now.d_dv.cast<float>(), constants)
                                .strength;
    sum += strength;
    largest = std::max(largest, strength);
  }
  return {sum / static_cast<double>(region.samples.size()), largest};
}

int run(const std::string& source, const std::string& directory, int count) {
  const Skeleton skeleton = Skeleton::fromUrdfFile(source + "/urdf/human.urdf");
  const BodyDescription body = loadBodyDescriptionFile(source + "/config/bodies/default.yaml", skeleton);
  MotionEvaluator evaluator(loadMotionFile(source + "/config/motions/walk.yaml"));
  ForwardKinematics fk(skeleton, body.shape);
  const std::vector<std::string> names{"pants", "jacket"};
  std::vector<Garment> garments;
  std::vector<WrinklePlacement> placements;
  for (const std::string& name : names) {
    garments.emplace_back(loadGarmentFile(source + "/config/garments/" + name + ".yaml", skeleton), skeleton,
                          body.shape);
    placements.emplace_back(garments.back(), skeleton, body.shape);
  }

  std::ofstream csv(directory + "/wrinkle_walk.csv");
  csv << "pose,phase,l_knee_bend_deg,l_elbow_bend_deg";
  for (std::size_t g = 0; g < names.size(); ++g) {
    for (const CompressionRegion& region : placements[g].regions()) {
      const std::string key = names[g] + "_" + region.name;
      csv << "," << key << "_alpha," << key << "_chain," << key << "_h1_mm";
    }
  }
  csv << "\n";
  std::ofstream options(directory + "/wrinkle_walk_options.csv");
  options << "alpha_threshold,saturation_alpha\n"
          << placements[0].options().alpha_threshold << "," << placements[0].options().saturation_alpha << "\n";
  std::ofstream shown(directory + "/wrinkle_walk_strength.csv");
  shown << "pose,phase,time_s,l_knee_bend_deg,l_elbow_bend_deg";
  for (std::size_t g = 0; g < names.size(); ++g) {
    for (const CompressionRegion& region : placements[g].regions()) {
      shown << "," << names[g] << "_" << region.name << "_mean," << names[g] << "_" << region.name << "_max";
    }
  }
  shown << "\n";
  std::vector<SkeletonPose> poses(static_cast<std::size_t>(count));
  std::vector<double> knee_alpha;
  for (int k = 0; k < count; ++k) {
    JointAngles angles{};
    RigidTransform root;
    evaluator.evaluate(evaluator.motion().period * k / count, angles, root);
    fk.compute(root, angles, poses[static_cast<std::size_t>(k)]);
    const SkeletonPose& pose = poses[static_cast<std::size_t>(k)];
    csv << k << "," << static_cast<double>(k) / count << "," << bendDegrees(pose, skeleton, "l_hip", "l_knee") << ","
        << bendDegrees(pose, skeleton, "l_shoulder", "l_elbow");
    shown << k << "," << static_cast<double>(k) / count << "," << evaluator.motion().period * k / count << ","
          << bendDegrees(pose, skeleton, "l_hip", "l_knee") << ","
          << bendDegrees(pose, skeleton, "l_shoulder", "l_elbow");
    for (std::size_t g = 0; g < names.size(); ++g) {
      garments[g].pose(pose);
      for (const RegionCompression& region : placements[g].measureRegions(garments[g].patches(), pose)) {
        csv << "," << region.alpha << "," << chainText(region.wrinkles.chain) << ","
            << region.wrinkles.amplitude * 1000.0;
        if (g == 0 && region.name == "l_knee_back") knee_alpha.push_back(region.alpha);
      }
      for (const CompressionRegion& region : placements[g].regions()) {
        const auto [mean, largest] = shownStrength(placements[g], garments[g].patches(), region);
        shown << "," << mean << "," << largest;
      }
    }
    csv << "\n";
    shown << "\n";
  }

  // The pose wrinkle map's tile behind the left knee at three poses.
  const std::size_t most =
      static_cast<std::size_t>(std::min_element(knee_alpha.begin(), knee_alpha.end()) - knee_alpha.begin());
  const std::size_t least =
      static_cast<std::size_t>(std::max_element(knee_alpha.begin(), knee_alpha.end()) - knee_alpha.begin());
  std::vector<std::size_t> order(knee_alpha.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return knee_alpha[a] < knee_alpha[b]; });
  const std::size_t middle = order[order.size() / 2];
  const CompressionRegion& knee_region = placements[0].region("l_knee_back");
  const std::uint32_t patch = knee_region.samples[knee_region.samples.size() / 2].patch;
  std::ofstream tiles(directory + "/wrinkle_walk_tiles.csv");
  tiles << "name,pose,alpha,chain,patch,max_height_mm\n";
  constexpr int kTile = 256;
  for (const auto& [name, k] :
       {std::make_pair("least", least), std::make_pair("middle", middle), std::make_pair("most", most)}) {
    garments[0].pose(poses[k]);
    const PoseWrinkleMap map = makePoseWrinkleMap(placements[0], garments[0].patches(), poses[k], kTile);
    ReliefMap tile(kTile, kTile);
    for (int row = 0; row < kTile; ++row) {
      for (int column = 0; column < kTile; ++column) {
        const std::size_t from = map.atlas.index(static_cast<int>(patch) * kTile + column, row);
        const std::size_t to = tile.index(column, row);
        tile.heights[to] = map.atlas.heights[from];
        tile.slope_u[to] = map.atlas.slope_u[from];
        tile.slope_v[to] = map.atlas.slope_v[from];
      }
    }
    writePng8(directory + "/wrinkle_walk_tile_" + name + ".png", kTile, kTile, 1,
              shadeReliefMap(tile, Eigen::Vector3d(-0.45, -0.55, 1.0)));
    tiles << name << "," << k << "," << knee_alpha[k] << "," << chainText(map.layouts[patch].chain) << "," << patch
          << "," << tile.maximumHeight() * 1000.0 << "\n";
  }
  std::cout << "wrote " << directory
            << "/wrinkle_walk.csv, wrinkle_walk_strength.csv, wrinkle_walk_tiles.csv and 3 tiles\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: wrinkle_placement_walk <source_directory> <output_directory> [poses]\n";
    return 2;
  }
  try {
    const int count = argc > 3 ? std::stoi(argv[3]) : 60;
    if (count < 3) throw std::invalid_argument("poses must be >= 3, got " + std::to_string(count));
    return run(argv[1], argv[2], count);
  } catch (const std::exception& error) {
    std::cerr << "wrinkle_placement_walk: " << error.what() << "\n";
    return 1;
  }
}
