#include "dressed_human/core/motion/capture_units.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "dressed_human/core/motion/motion.h"

namespace dressed_human {
namespace {

struct KnownUnit {
  const char* name;
  double metres;
};
// CMU's BVH files come from ASF skeletons written with "length 0.45": 1 unit = 1/0.45 inch.
constexpr std::array<KnownUnit, 5> kKnownUnits = {
    {{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"in", 0.0254}, {"cmu", 0.0254 / 0.45}}};
// A standing person, children to the tallest adults.
constexpr double kMinStature = 1.0;
constexpr double kMaxStature = 2.3;
constexpr double kTypicalStature = 1.7;

std::string formatted(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

}  // namespace

std::string knownUnitNames() { return "m, cm, mm, in, cmu (ASF units: 1/0.45 in) or metres per unit"; }

CaptureUnits unitsByName(const std::string& name) {
  for (const KnownUnit& unit : kKnownUnits) {
    if (name == unit.name) return {unit.metres, unit.name, "given"};
  }
  char* end = nullptr;
  const double metres = std::strtod(name.c_str(), &end);
  if (!name.empty() && end == name.c_str() + name.size() && std::isfinite(metres) && metres > 0.0) {
    return {metres, name, "given"};
  }
  throw MotionError("unknown length unit '" + name + "': expected one of " + knownUnitNames());
}

double bvhRestStature(const BvhClip& clip) {
  const BvhPose rest = bvhRestPose(clip);
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (std::size_t j = 0; j < clip.joints.size(); ++j) {
    low = std::min(low, rest.position[j].y());
    high = std::max(high, rest.position[j].y());
    for (const Eigen::Vector3d& end : clip.joints[j].end_sites) {
      low = std::min(low, rest.position[j].y() + end.y());
      high = std::max(high, rest.position[j].y() + end.y());
    }
  }
  return clip.joints.empty() ? 0.0 : high - low;
}

CaptureUnits detectBvhUnits(const BvhClip& clip, const std::string& source_name) {
  const double stature = bvhRestStature(clip);
  if (!(stature > 1e-9)) {
    throw MotionError(source_name +
                      ": the rest pose has no height (every OFFSET is zero or horizontal): the body's "
                      "proportions cannot be read from it");
  }
  const KnownUnit* best = nullptr;
  for (const KnownUnit& unit : kKnownUnits) {
    const double metres = stature * unit.metres;
    if (metres < kMinStature || metres > kMaxStature) continue;
    if (!best || std::abs(metres - kTypicalStature) < std::abs(stature * best->metres - kTypicalStature)) best = &unit;
  }
  if (!best) {
    throw MotionError(source_name + ": the rest pose is " + formatted("%.4g", stature) +
                      " units tall, a human height in none of " + knownUnitNames() + ": give the unit with --units");
  }
  return {best->metres, best->name,
          "the rest pose is " + formatted("%.4g", stature) +
              " units tall: " + formatted("%.2f", stature * best->metres) + " m in " + best->name};
}

}  // namespace dressed_human
