#include "dressed_human/core/model/crowd_walks.h"

#include <array>
#include <cmath>

#include "dressed_human/core/io/text_file.h"
#include "dressed_human/core/io/yaml_reader.h"
#include "dressed_human/core/locomotion/walker.h"
#include "dressed_human/core/model/crowd_appearance.h"

namespace dressed_human {
namespace {

// The default layout's place `index`: its ring's rectangle, walked from the corner before its own.
CrowdWalk defaultWalk(std::size_t index) {
  const std::size_t ring = index / 4, corner = index % 4;
  const double half_x = 1.6 + 0.7 * static_cast<double>(ring), half_y = 1.0 + 0.7 * static_cast<double>(ring);
  // Corner k: 0 (+x, -y), 1 (+x, +y), 2 (-x, +y), 3 (-x, -y); odd rings clockwise.
  const std::array<Eigen::Vector2d, 4> corners = {
      {{half_x, -half_y}, {half_x, half_y}, {-half_x, half_y}, {-half_x, -half_y}}};
  CrowdWalk walk;
  walk.id = std::to_string(index);
  for (std::size_t j = 0; j < 4; ++j) {
    const std::size_t k = ring % 2 == 0 ? (corner + j) % 4 : 3 - (corner + j) % 4;
    walk.route.waypoints.push_back(corners[k]);
  }
  walk.route.closed = true;
  walk.speed = 1.0 + 0.15 * static_cast<double>(ring % 4);
  walk.stature = 0.92 + 0.02 * static_cast<double>((index * 5) % 9);
  walk.start_phase = std::fmod(1.3 * static_cast<double>(index), 2.0 * M_PI) / (2.0 * M_PI);
  return walk;
}

}  // namespace

std::vector<CrowdWalk> defaultCrowdWalks(std::size_t count) {
  std::vector<CrowdWalk> walks;
  for (std::size_t i = 0; i < count; ++i) walks.push_back(defaultWalk(i));
  return walks;
}

std::vector<CrowdWalk> loadCrowdWalks(const std::string& path) {
  loadCrowdFile(path);  // the same file, checked as a whole: appearance keys too
  const std::string text = readWholeFileOrThrow<CrowdFileError>(path, "the crowd file");
  const YamlReader<CrowdFileError> reader(path);
  const YAML::Node humans = reader.load(text, "the crowd file")["humans"];
  std::vector<CrowdWalk> walks;
  for (const auto& entry : humans) {
    const std::string id = entry.first.Scalar();
    const std::string key = "humans." + id;
    const YAML::Node& fields = entry.second;
    CrowdWalk walk = defaultWalk(walks.size());
    walk.id = id;
    if (fields["route"]) {
      const YAML::Node route = fields["route"];
      if (!route.IsSequence()) reader.fail(route, key + ".route", "expected a list of [x, y] pairs in metres");
      walk.route.waypoints.clear();
      for (std::size_t i = 0; i < route.size(); ++i) {
        const std::vector<double> xy = reader.numbers(route[i], key + ".route[" + std::to_string(i) + "]", 2, "(x, y)");
        walk.route.waypoints.emplace_back(xy[0], xy[1]);
      }
    }
    if (fields["route_end"]) {
      const std::string end = reader.text(fields["route_end"], key + ".route_end");
      if (end != "loop" && end != "stand") reader.fail(fields["route_end"], key + ".route_end", "expected loop or stand");
      walk.route.closed = end == "loop";
    }
    try {
      validateRoute(walk.route, path + ": " + key + ".route");
    } catch (const LocomotionError& error) {
      throw CrowdFileError(error.what());
    }
    if (fields["speed"]) walk.speed = reader.numberWithin(fields["speed"], key + ".speed", 0.0, WalkerSettings::kMaxSpeed, " m/s");
    if (fields["stature"]) walk.stature = reader.numberWithin(fields["stature"], key + ".stature", 0.8, 1.2, "");
    if (fields["start_phase"]) walk.start_phase = reader.numberWithin(fields["start_phase"], key + ".start_phase", 0.0, 1.0, " cycles");
    walks.push_back(walk);
  }
  return walks;
}

}  // namespace dressed_human
