// render_skin: the posed skin (config/bodies/default.yaml on urdf/human.urdf) at three times of
// the walk (config/motions/walk.yaml), side by side, seen from the body's right, to a PNG.
//
//   render_skin [--root DIR] [--level N] [--size WxH] --out docs/skin_walk.png
#include "dressed_human/core/render/mesh_rasterizer.h"
#include "dressed_human/core/motion/motion_evaluator.h"
#include "dressed_human/core/motion/motion_file.h"
#include "dressed_human/core/surfaces/skin.h"

#include <cstdio>
#include <iostream>
#include <string>

using namespace dressed_human;

int main(int argc, char** argv) {
  std::string root = ".";
  std::string out;
  int level = 8;
  int width = 1200, height = 800;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) {
      std::cerr << "usage: render_skin [--root DIR] [--level N] [--size WxH] --out FILE.png\n";
      return 2;
    }
    const std::string value = argv[++i];
    if (arg == "--root")
      root = value;
    else if (arg == "--out")
      out = value;
    else if (arg == "--level")
      level = std::stoi(value);
    else if (arg == "--size")
      std::sscanf(value.c_str(), "%dx%d", &width, &height);
    else {
      std::cerr << "render_skin: unknown option " << arg << "\n";
      return 2;
    }
  }
  if (out.empty()) {
    std::cerr << "usage: render_skin [--root DIR] [--level N] [--size WxH] --out FILE.png\n";
    return 2;
  }
  try {
    const Skeleton skeleton = Skeleton::fromUrdfFile(root + "/urdf/human.urdf");
    const BodyDescription body = loadBodyDescriptionFile(root + "/config/bodies/default.yaml", skeleton);
    const ForwardKinematics kinematics(skeleton, body.shape);
    MotionEvaluator walk(loadMotionFile(root + "/config/motions/walk.yaml"));
    Skin skin(skeleton, body);
    Tessellator tessellator;
    RasterCamera camera;
    const double spacing = 0.9;
    camera.eye = Eigen::Vector3d(spacing, -5.0, 0.9);
    camera.target = Eigen::Vector3d(spacing, 0.0, 0.9);
    camera.ortho_height = 2.0;
    MeshRasterizer raster(width, height, camera);
    raster.clear(Eigen::Vector3d(1.0, 1.0, 1.0));
    RasterMaterial material;
    material.colour = Eigen::Vector3d(0.87, 0.70, 0.60);
    for (int k = 0; k < 3; ++k) {
      JointAngles angles;
      RigidTransform pelvis;
      walk.evaluate(walk.motion().period * k / 3.0, angles, pelvis);
      pelvis.translation.x() = spacing * k;  // side by side instead of walking away
      pelvis.translation.y() = 0.0;
      SkeletonPose pose;
      kinematics.compute(pelvis, angles, pose);
      skin.pose(pose);
      raster.draw(tessellator.tessellateUniform(skin.patches(), skin.topology(), level), material,
                  Eigen::Vector3d(0.4, -1.0, 0.6));
    }
    raster.writePng(out);
    std::printf("wrote %s (%d x %d, level %d, %zu triangles per pose)\n", out.c_str(), width, height, level,
                tessellator.mesh().triangleCount());
  } catch (const std::exception& error) {
    std::cerr << "render_skin: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
