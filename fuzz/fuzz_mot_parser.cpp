// libFuzzer target: parseOpenSimMotion must either return a table or throw OpenSimError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "dressed_human/core/motion/opensim_motion_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const dressed_human::OpenSimTable table = dressed_human::parseOpenSimMotion(text, "fuzz.mot");
    if (table.labels.size() > 1) table.column(1);
  } catch (const dressed_human::OpenSimError&) {
  }
  return 0;
}
