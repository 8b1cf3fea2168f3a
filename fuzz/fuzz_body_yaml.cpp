// libFuzzer target: parseBodyDescriptionYaml must either return a body or throw
// BodyDescriptionError; a body it returns must build a skin or be refused with SkinError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "dressed_human/core/skeleton/body_description.h"
#include "dressed_human/core/skeleton/skeleton.h"
#include "dressed_human/core/surfaces/skin.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const dressed_human::Skeleton skeleton =
      dressed_human::Skeleton::fromUrdfFile(std::string(DRESSED_HUMAN_SOURCE_DIR) + "/urdf/human.urdf");
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const dressed_human::BodyDescription body = dressed_human::parseBodyDescriptionYaml(text, skeleton, "fuzz.yaml");
    const dressed_human::Skin skin(skeleton, body);
  } catch (const dressed_human::BodyDescriptionError&) {
  } catch (const dressed_human::SkinError&) {
  }
  return 0;
}
