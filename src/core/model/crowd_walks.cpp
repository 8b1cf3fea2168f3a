#include "dressed_human/core/model/crowd_walks.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "dressed_human/core/io/text_file.h"
#include "dressed_human/core/io/yaml_reader.h"
#include "dressed_human/core/locomotion/walker.h"
#include "dressed_human/core/model/crowd_appearance.h"

namespace dressed_human {
namespace {

constexpr double kLoopSpacing = 0.7;       // m between nested loops
constexpr double kSpacingAlongLoop = 2.5;  // m of loop per human

struct Loop {
  double half_x, half_y;
  std::size_t capacity;
};

Loop loop(std::size_t ring) {
  const double half_x = 1.6 + kLoopSpacing * static_cast<double>(ring);
  const double half_y = 1.0 + kLoopSpacing * static_cast<double>(ring);
  const auto fits = static_cast<std::size_t>(4.0 * (half_x + half_y) / kSpacingAlongLoop);
  return {half_x, half_y, std::max<std::size_t>(4, fits)};
}

// Human `index` of `on_ring` humans on loop `ring`, `place` of them along it.
CrowdWalk walkOnLoop(std::size_t index, std::size_t ring, std::size_t place, std::size_t on_ring) {
  const Loop l = loop(ring);
  // Corners in walking order: counter-clockwise from (+x, -y) on even loops, clockwise on odd.
  std::array<Eigen::Vector2d, 4> corners = {
      {{l.half_x, -l.half_y}, {l.half_x, l.half_y}, {-l.half_x, l.half_y}, {-l.half_x, -l.half_y}}};
  if (ring % 2 == 1) std::swap(corners[1], corners[3]);
  // Evenly along the loop, each loop's humans shifted by half a spacing against the last loop's.
  const double perimeter = 4.0 * (l.half_x + l.half_y);
  double along = std::fmod(
      (static_cast<double>(place) + 0.5 * static_cast<double>(ring % 2)) * perimeter / static_cast<double>(on_ring),
      perimeter);
  std::size_t edge = 0;
  for (; edge < 3; ++edge) {
    const double length = (corners[(edge + 1) % 4] - corners[edge]).norm();
    if (along < length) break;
    along -= length;
  }
  const Eigen::Vector2d& from = corners[edge];
  const Eigen::Vector2d& to = corners[(edge + 1) % 4];
  CrowdWalk walk;
  walk.id = std::to_string(index);
  walk.start = from + (to - from).normalized() * along;
  for (std::size_t j = 1; j <= 4; ++j) walk.route.waypoints.push_back(corners[(edge + j) % 4]);
  walk.route.closed = true;
  walk.speed = 1.0 + 0.15 * static_cast<double>(ring % 4);
  walk.stature = 0.92 + 0.02 * static_cast<double>((index * 5) % 9);
  walk.start_phase = std::fmod(1.3 * static_cast<double>(index), 2.0 * M_PI) / (2.0 * M_PI);
  return walk;
}

}  // namespace

std::vector<CrowdWalk> defaultCrowdWalks(std::size_t count) {
  std::vector<CrowdWalk> walks;
  for (std::size_t ring = 0; walks.size() < count; ++ring) {
    const std::size_t on_ring = std::min(loop(ring).capacity, count - walks.size());
    for (std::size_t place = 0; place < on_ring; ++place)
      walks.push_back(walkOnLoop(walks.size(), ring, place, on_ring));
  }
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
    CrowdWalk walk = defaultCrowdWalks(walks.size() + 1).back();
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
      if (end != "loop" && end != "stand")
        reader.fail(fields["route_end"], key + ".route_end", "expected loop or stand");
      walk.route.closed = end == "loop";
    }
    try {
      validateRoute(walk.route, path + ": " + key + ".route");
    } catch (const LocomotionError& error) {
      throw CrowdFileError(error.what());
    }
    if (fields["route"]) walk.start = walk.route.closed ? walk.route.waypoints.back() : walk.route.waypoints.front();
    if (fields["speed"])
      walk.speed = reader.numberWithin(fields["speed"], key + ".speed", 0.0, WalkerSettings::kMaxSpeed, " m/s");
    if (fields["stature"]) walk.stature = reader.numberWithin(fields["stature"], key + ".stature", 0.8, 1.2, "");
    if (fields["start_phase"])
      walk.start_phase = reader.numberWithin(fields["start_phase"], key + ".start_phase", 0.0, 1.0, " cycles");
    if (fields["treadmill"]) walk.treadmill = reader.boolean(fields["treadmill"], key + ".treadmill");
    if (walk.treadmill && walk.route.waypoints.size() < 2) {
      reader.fail(fields["treadmill"], key + ".treadmill",
                  "needs a route of two waypoints: where it walks and which way");
    }
    walks.push_back(walk);
  }
  return walks;
}

}  // namespace dressed_human
