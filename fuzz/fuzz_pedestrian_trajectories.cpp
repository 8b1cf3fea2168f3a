// libFuzzer target: parsePedestrianTrajectories must either return trajectories that a
// RecordedCrowd can play, or throw PedestrianTrajectoryError; the first byte picks the options
// (format forced or detected, a frame rate given or not).
#include <cstddef>
#include <cstdint>
#include <string>

#include "dressed_human/core/io/pedestrian_trajectories.h"
#include "dressed_human/core/model/recorded_crowd.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  dressed_human::TrajectoryReadOptions options;
  options.format = static_cast<dressed_human::TrajectoryFormat>(data[0] % 3);
  options.frame_rate = (data[0] & 4) != 0 ? 25.0 : 0.0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    const dressed_human::PedestrianTrajectories trajectories =
        dressed_human::parsePedestrianTrajectories(text, "fuzz.txt", options);
    const dressed_human::RecordedCrowd crowd(trajectories, {});
    std::size_t present = 0;
    for (std::size_t sample = 0; sample < crowd.sampleCount(); ++sample) present += crowd.countAt(sample);
    (void)present;
  } catch (const dressed_human::PedestrianTrajectoryError&) {
  }
  return 0;
}
