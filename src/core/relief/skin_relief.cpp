#include "dressed_human/core/relief/skin_relief.h"

#include <algorithm>

namespace dressed_human {

SkinRelief::SkinRelief(const SkinReliefParameters& parameters)
    : parameters_(parameters),
      hierarchy_(std::make_shared<const SkinCellHierarchy>(parameters)),
      sampler_(hierarchy_, parameters),
      rasterizer_(*hierarchy_, sampler_) {}

ReliefSample SkinRelief::sample(const Eigen::Vector2d& point, int level_limit) const {
  const int end = level_limit < 0 ? levelCount() : std::min(level_limit, levelCount());
  return sampler_.sample(point, 0, end);
}

ReliefSample SkinRelief::sampleLevel(const Eigen::Vector2d& point, int level) const {
  levelAt(level);
  return sampler_.sample(point, level, level + 1);
}

std::vector<int> SkinRelief::cellsAt(const Eigen::Vector2d& point) const { return sampler_.cellsAt(point); }

ReliefMap SkinRelief::render(int width, int height, int only_level) const {
  if (only_level >= 0) levelAt(only_level);
  if (rasterizer_.ready() && sampler_.packed()) return rasterizer_.render(sampler_, width, height, only_level);
  return sampler_.render(width, height, only_level, false);
}

ReliefMap SkinRelief::renderBruteForce(int width, int height) const { return sampler_.render(width, height, -1, true); }

}  // namespace dressed_human
