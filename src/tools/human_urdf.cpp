// human_urdf: the robot_description of a human, shaped to a fitted motion's body (urdf_body_shape.h).
// Launch files set robot_description from it, so that rviz's RobotModel, robot_state_publisher,
// the skeleton_publisher node and the DressedHuman display all see the captured person's
// proportions. A motion without a body_shape gives the URDF unchanged.

#include <iostream>
#include <string>

#include "dressed_human/core/io/text_file.h"
#include "dressed_human/core/motion/motion_file.h"
#include "dressed_human/core/skeleton/skeleton.h"
#include "dressed_human/core/skeleton/urdf_body_shape.h"

namespace dh = dressed_human;

namespace {

const char* const kUsage =
    "Usage: human_urdf URDF [--motion FILE]\n"
    "Writes the URDF to standard output, with the body_shape of the motion file (written by\n"
    "fit_motion) applied to its joint origins and bone visuals and recorded for the node and the\n"
    "DressedHuman display. Without --motion, or for a motion without body_shape: the URDF as it is.\n";

}  // namespace

int main(int argc, char** argv) {
  std::string urdf_path;
  std::string motion_path;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      return 0;
    } else if (arg == "--motion" && i + 1 < argc) {
      motion_path = argv[++i];
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
  try {
    const std::string urdf = dh::readWholeFileOrThrow<dh::SkeletonError>(urdf_path, "the URDF file");
    dh::Skeleton::fromUrdf(urdf);  // a human URDF, or the error says which part is not
    const dh::Motion motion = motion_path.empty() ? dh::Motion() : dh::loadMotionFile(motion_path);
    std::cout << (motion.body_shape ? dh::shapedUrdf(urdf, *motion.body_shape) : urdf);
  } catch (const std::exception& error) {
    std::cerr << "human_urdf: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
