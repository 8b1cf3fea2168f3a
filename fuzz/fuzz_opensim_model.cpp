// libFuzzer target: parseOpenSimModel must either return a model or throw OpenSimModelError; a
// model it returns must put every body at a finite place for its default coordinates and for
// coordinates a radian or a metre away from them.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "dressed_human/core/motion/opensim_model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  dressed_human::OpenSimModel model;
  try {
    model = dressed_human::parseOpenSimModel(text, "fuzz.osim");
  } catch (const dressed_human::OpenSimModelError&) {
    return 0;
  }
  for (const double offset : {0.0, 1.0, -1.0}) {
    std::vector<double> q = model.defaultCoordinates();
    for (double& value : q) value += offset;
    for (const Eigen::Isometry3d& body : model.bodyTransforms(q)) {
      if (!body.matrix().allFinite()) std::abort();
    }
    model.scaled(1.1).bodyTransforms(q);
  }
  return 0;
}
