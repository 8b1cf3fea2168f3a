// libFuzzer target: parseBvh must either return a clip or throw BvhError, never crash or hang;
// a parsed clip must be usable (forward kinematics of its first frame).
#include <cstddef>
#include <cstdint>
#include <string>

#include "dressed_human/core/motion/bvh_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const dressed_human::BvhClip clip = dressed_human::parseBvh(text, "fuzz.bvh");
    if (!clip.frames.empty()) dressed_human::bvhForwardKinematics(clip, 0);
    dressed_human::bvhRestPose(clip);
  } catch (const dressed_human::BvhError&) {
  }
  return 0;
}
