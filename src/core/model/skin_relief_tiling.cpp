#include "dressed_human/core/model/skin_relief_tiling.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dressed_human {
namespace {

// Mid-line lengths of a patch along u (at v = 1/2) and along v (at u = 1/2), by 16 chords.
Eigen::Vector2d midLineLengths(const BezierPatch& patch) {
  constexpr int kChords = 16;
  Eigen::Vector2d lengths = Eigen::Vector2d::Zero();
  Eigen::Vector3d previous_u = patch.position(0.0, 0.5), previous_v = patch.position(0.5, 0.0);
  for (int k = 1; k <= kChords; ++k) {
    const double t = static_cast<double>(k) / kChords;
    const Eigen::Vector3d along_u = patch.position(t, 0.5), along_v = patch.position(0.5, t);
    lengths.x() += (along_u - previous_u).norm();
    lengths.y() += (along_v - previous_v).norm();
    previous_u = along_u;
    previous_v = along_v;
  }
  return lengths;
}

float wholeTiles(double length, double tile) { return static_cast<float>(std::max(1.0, std::round(length / tile))); }

}  // namespace

const std::vector<SkinRegion>& skinRegions() {
  // Skin cells (closed polygons of the primary and secondary lines) per mm^2 of volar forearm,
  // imaged with a Visioscan VC98 in 38 subjects: 3.1 (SD 1.1) in children, 1.0 (SD 0.7) in young
  // adults, 1.0 (SD 0.9) in older adults: Trojahn C, Dobos G, Schario M, et al., Skin Res Technol,
  // published online 3 June 2014 (as summarised at dermakos.it; the paper itself was not
  // reachable here). Abdomen against medial forearm: plateaus "deeper and wider", 14.37 against
  // 10.27 rete ridges per plateau: "3D reconstruction of skin pathological tissue: the
  // understanding of microrelief pattern and dermal ridge", Skin Res Technol 20(2):213-217, 2014
  // (PMID 23981137); the area ratio 1.40 assumes the same rete ridge density at both sites. No
  // measured size of the face's or the back of the hand's cells was found in the sources reachable
  // here (README, the rviz display): those regions take the forearm's.
  static const std::vector<SkinRegion> regions{
      {"forearm",
       {"l_elbow", "r_elbow"},
       1.0,
       "Trojahn et al. 2014: 1.0 closed polygons per mm^2, adult volar forearm"},
      {"hand", {"l_wrist", "r_wrist"}, 1.0, "not measured here: the forearm's"},
      {"face and neck", {"head", "neck"}, 1.0, "not measured here: the forearm's"},
      {"trunk",
       {"body", "waist", "torso"},
       1.0 * 14.37 / 10.27,
       "Skin Res Technol 2014;20:213: abdominal plateaus hold 14.37/10.27 the forearm's rete ridges"},
      {"limbs", {}, 1.0, "not measured here: the forearm's"},
  };
  return regions;
}

double cellSpacingForArea(double area_mm2) { return 1e-3 * std::sqrt(2.0 * area_mm2 / std::sqrt(3.0)); }

double SkinReliefTiling::measuredForearmSpacing() { return cellSpacingForArea(skinRegions().front().cell_area_mm2); }

SkinReliefTiling::SkinReliefTiling(const Skin& skin) : segments_(skin.segments()) {
  const std::vector<BezierPatch>& patches = skin.patches();
  lengths_.resize(patches.size());
  for (std::size_t p = 0; p < patches.size(); ++p) lengths_[p] = midLineLengths(patches[p]);
  const std::vector<SkinRegion>& regions = skinRegions();
  segment_region_.resize(segments_.size());
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    int region = static_cast<int>(regions.size()) - 1;
    for (std::size_t r = 0; r < regions.size(); ++r) {
      const std::vector<std::string>& bones = regions[r].bones;
      if (std::find(bones.begin(), bones.end(), segments_[s].name) != bones.end()) region = static_cast<int>(r);
    }
    segment_region_[s] = region;
  }
  setForearmCellSpacing(measuredForearmSpacing());
}

void SkinReliefTiling::setForearmCellSpacing(double forearm_cell_spacing) {
  if (!(forearm_cell_spacing > 0.0) || !std::isfinite(forearm_cell_spacing)) {
    throw std::invalid_argument("skin cell size " + std::to_string(forearm_cell_spacing) + " m must be finite and > 0");
  }
  const std::vector<SkinRegion>& regions = skinRegions();
  std::vector<double> region_spacing;
  for (const SkinRegion& region : regions) {
    region_spacing.push_back(forearm_cell_spacing * cellSpacingForArea(region.cell_area_mm2) /
                             measuredForearmSpacing());
  }
  largest_spacing_ = *std::max_element(region_spacing.begin(), region_spacing.end());
  tiles_.assign(lengths_.size(), Eigen::Vector2f::Ones());
  for (std::size_t s = 0; s < segments_.size(); ++s) {
    const SkinSegment& segment = segments_[s];
    const double tile = region_spacing[static_cast<std::size_t>(segment_region_[s])] * kSkinCellsPerTile;
    // Around: one count per quarter for the whole segment (its stacks and caps), from the mean.
    for (std::uint32_t q = 0; q < 4; ++q) {
      double around = 0.0;
      for (std::uint32_t stack = 0; stack < segment.stack_count; ++stack) {
        around += lengths_[segment.first_patch + 4 * stack + q].x();
      }
      const float count = wholeTiles(around / std::max<std::uint32_t>(segment.stack_count, 1), tile);
      for (std::uint32_t stack = 0; stack < segment.stack_count; ++stack) {
        tiles_[segment.first_patch + 4 * stack + q].x() = count;
      }
      if (segment.has_proximal_cap) tiles_[segment.proximal_cap_first + q].x() = count;
      if (segment.has_distal_cap) tiles_[segment.distal_cap_first + q].x() = count;
    }
    // Along: one count per stack (or cap) for its four quarters, from their mean.
    const auto along = [&](std::uint32_t first) {
      double length = 0.0;
      for (std::uint32_t q = 0; q < 4; ++q) length += lengths_[first + q].y();
      const float count = wholeTiles(length / 4.0, tile);
      for (std::uint32_t q = 0; q < 4; ++q) tiles_[first + q].y() = count;
    };
    for (std::uint32_t stack = 0; stack < segment.stack_count; ++stack) along(segment.first_patch + 4 * stack);
    if (segment.has_proximal_cap) along(segment.proximal_cap_first);
    if (segment.has_distal_cap) along(segment.distal_cap_first);
  }
}

Eigen::Vector2d SkinReliefTiling::cellSpacing(std::size_t patch) const {
  return lengths_.at(patch).cwiseQuotient(tiles_.at(patch).cast<double>()) / kSkinCellsPerTile;
}

}  // namespace dressed_human
