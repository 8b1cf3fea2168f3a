// render_mesh: draws garments (config/garments/*.yaml) on the body in a walk pose or at rest,
// with the core's MeshRasterizer, to a PNG. Used by scripts/make_garment_figures.py.
//
//   render_mesh --garment config/garments/jacket.yaml --garment config/garments/skirt.yaml
//               [--length 0.2|knee] [--time 0.3 | --rest] [--view front|side|three_quarter|back]
//               [--size 400x800] [--no-body] --out out.png
//
// The body is the real skin (skin.h: config/bodies/default.yaml on urdf/human.urdf), posed by
// Skin::pose and tessellated like src/tools/render_skin.cpp; --no-body leaves it out.
#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/forward_kinematics.h"
#include "dressed_human/core/garments/garment.h"
#include "dressed_human/core/garments/garment_file.h"
#include "dressed_human/core/render/mesh_rasterizer.h"
#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"
#include "dressed_human/core/surfaces/skin.h"
#include "dressed_human/core/surfaces/tessellation.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using namespace dressed_human;

namespace {

void usage() {
  std::cerr << "usage: render_mesh --garment FILE [--garment FILE ...] [--length C|knee] [--time T | --rest]\n"
               "                   [--view front|side|three_quarter|back] [--size WxH] [--no-body]\n"
               "                   [--source-dir DIR] --out FILE.png\n";
}

// The posed skin, tessellated uniformly at `level`.
void drawBody(Skin& skin, const SkeletonPose& pose, MeshRasterizer& raster, const Eigen::Vector3d& light) {
  Tessellator tessellator;
  RasterMaterial material;
  material.colour = Eigen::Vector3d(0.93, 0.76, 0.64);
  skin.pose(pose);
  raster.draw(tessellator.tessellateUniform(skin.patches(), skin.topology(), 8), material, light);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> garment_files;
  std::string out, view = "three_quarter", length, source = ".";
  double time = 0.0;
  bool rest = false, body = true;
  int width = 400, height = 800;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        usage();
        std::exit(2);
      }
      return argv[++i];
    };
    if (arg == "--garment")
      garment_files.push_back(value());
    else if (arg == "--out")
      out = value();
    else if (arg == "--view")
      view = value();
    else if (arg == "--length")
      length = value();
    else if (arg == "--time")
      time = std::stod(value());
    else if (arg == "--rest")
      rest = true;
    else if (arg == "--no-body")
      body = false;
    else if (arg == "--source-dir")
      source = value();
    else if (arg == "--size") {
      if (std::sscanf(value().c_str(), "%dx%d", &width, &height) != 2) {
        usage();
        return 2;
      }
    } else {
      usage();
      return 2;
    }
  }
  if (out.empty()) {
    usage();
    return 2;
  }
  try {
    const Skeleton skeleton = Skeleton::fromUrdfFile(source + "/urdf/human.urdf");
    const BodyDescription description = loadBodyDescriptionFile(source + "/config/bodies/default.yaml", skeleton);
    ForwardKinematics fk(skeleton, description.shape);
    JointAngles angles{};
    angles.fill(0.0);
    RigidTransform root;
    if (!rest) {
      MotionEvaluator evaluator(loadMotionFile(source + "/config/motions/walk.yaml"));
      evaluator.evaluate(time, angles, root);
    }
    SkeletonPose pose;
    fk.compute(root, angles, pose);

    const Eigen::Vector3d centre = root.translation + Eigen::Vector3d(0, 0, -0.05);
    RasterCamera camera;
    Eigen::Vector3d direction(1.0, 0.0, 0.0);
    if (view == "side")
      direction = Eigen::Vector3d(0.0, 1.0, 0.0);
    else if (view == "back")
      direction = Eigen::Vector3d(-1.0, 0.0, 0.0);
    else if (view == "three_quarter")
      direction = Eigen::Vector3d(1.0, 0.7, 0.15).normalized();
    else if (view != "front")
      throw std::invalid_argument("unknown view '" + view + "'");
    camera.eye = centre + 5.0 * direction;
    camera.target = centre;
    camera.ortho_height = 2.0;
    MeshRasterizer raster(width, height, camera);
    raster.clear(Eigen::Vector3d(1.0, 1.0, 1.0));
    const Eigen::Vector3d light = direction + Eigen::Vector3d(0.3, -0.4, 0.8);

    if (body) {
      Skin skin(skeleton, description);
      drawBody(skin, pose, raster, light);
    }
    Tessellator tessellator;
    for (const std::string& file : garment_files) {
      GarmentDescription g = loadGarmentFile(file, skeleton);
      if (!length.empty() && g.type != GarmentType::kJacket) {
        g.legs.at_knee = length == "knee";
        if (!g.legs.at_knee) g.legs.length = std::stod(length);
      }
      Garment garment(g, skeleton, description.shape);
      garment.pose(pose);
      RasterMaterial material;
      material.colour = g.colour;
      raster.draw(tessellator.tessellateUniform(garment.patches(), garment.topology(), 12), material, light);
      std::cout << g.name << ": " << garment.patches().size() << " patches";
      if (g.type != GarmentType::kJacket)
        std::cout << ", c = " << garment.length() << " (c_k = " << garment.kneeLength() << ")";
      std::cout << '\n';
    }
    raster.writePng(out);
  } catch (const std::exception& error) {
    std::cerr << "render_mesh: " << error.what() << '\n';
    return 1;
  }
  return 0;
}
