// human_urdf: the robot_description of a human, shaped to a fitted motion's body (urdf_body_shape.h).
// Launch files set robot_description from it, so that rviz's RobotModel, robot_state_publisher,
// the skeleton_publisher node and the DressedHuman display all see the captured person's
// proportions. A motion without a body_shape gives the URDF unchanged. --stature scales the whole
// body (a crowd of people of different heights, crowd_member.launch).

#include <cmath>
#include <iostream>
#include <string>

#include "dressed_human/core/io/text_file.h"
#include "dressed_human/core/motion/motion_file.h"
#include "dressed_human/core/skeleton/skeleton.h"
#include "dressed_human/core/skeleton/urdf_body_shape.h"

namespace dh = dressed_human;

namespace {

const char* const kUsage =
    "Usage: human_urdf URDF [--motion FILE | --stature FACTOR]\n"
    "Writes the URDF to standard output, with the body_shape of the motion file (written by\n"
    "fit_motion) applied to its joint origins and bone visuals and recorded for the node and the\n"
    "DressedHuman display. Without --motion, or for a motion without body_shape: the URDF as it is.\n"
    "--stature FACTOR scales every bone by FACTOR in [0.8, 1.2] (a person 0.8 to 1.2 times as tall).\n";

}  // namespace

int main(int argc, char** argv) {
  std::string urdf_path;
  std::string motion_path;
  std::string stature_text;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      return 0;
    } else if (arg == "--motion" && i + 1 < argc) {
      motion_path = argv[++i];
    } else if (arg == "--stature" && i + 1 < argc) {
      stature_text = argv[++i];
    } else if (!arg.empty() && arg[0] != '-' && urdf_path.empty()) {
      urdf_path = arg;
    } else {
      std::cerr << "human_urdf: unexpected argument '" << arg << "'\n\n" << kUsage;
      return 2;
    }
  }
  if (urdf_path.empty()) {
    std::cerr << "human_urdf: no URDF given\n\n" << kUsage;
    return 2;
  }
  double stature = 1.0;
  if (!stature_text.empty()) {
    char* end = nullptr;
    stature = std::strtod(stature_text.c_str(), &end);
    if (end == stature_text.c_str() || *end != '\0' || !(stature >= 0.8 && stature <= 1.2)) {
      std::cerr << "human_urdf: --stature must be a number in [0.8, 1.2], got '" << stature_text << "'\n";
      return 2;
    }
    if (!motion_path.empty()) {
      std::cerr << "human_urdf: --motion and --stature both shape the body: give one\n";
      return 2;
    }
  }
  try {
    const std::string urdf = dh::readWholeFileOrThrow<dh::SkeletonError>(urdf_path, "the URDF file");
    dh::Skeleton::fromUrdf(urdf);  // a human URDF, or the error says which part is not
    const dh::Motion motion = motion_path.empty() ? dh::Motion() : dh::loadMotionFile(motion_path);
    if (stature != 1.0) {
      dh::BodyShape shape;
      for (Eigen::Vector3d& scale : shape.scale) scale.setConstant(stature);
      std::cout << dh::shapedUrdf(urdf, shape);
    } else {
      std::cout << (motion.body_shape ? dh::shapedUrdf(urdf, *motion.body_shape) : urdf);
    }
  } catch (const std::exception& error) {
    std::cerr << "human_urdf: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
