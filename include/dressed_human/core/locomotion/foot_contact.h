#pragma once
// How a walk's feet meet the ground (issue 39): per foot, the share of frames it stands on the
// ground (stance: its lowest sole point within kDownBand of the floor), the share it stands flat
// (heel and toe both within the band), how many of its stances began on the heel and how many
// ended on the toe, the heel already up. The floor is z = 0, where PlantedFeet puts the carrying
// point. Used by the walk's tests and walk_speed_table.

#include <array>
#include <cstddef>

#include "dressed_human/core/skeleton/foot_sole.h"

namespace dressed_human {

class FootContactMeter {
 public:
  // A sole point this near the floor is down: issue 39 judges the walk so ("heel and toe within
  // 1 cm of the floor"); PlantedFeet::kContactBand (5 mm) is where the walker holds a foot.
  static constexpr double kDownBand = 0.01;  // m

  void add(const FootSoles& soles, const SkeletonPose& pose) {
    ++frames_;
    for (std::size_t side = 0; side < 2; ++side) {
      const bool heel_down = soles.point(pose, soles.heel(side)).z() < kDownBand;
      // The ball, or the toe cap beyond it as the foot rolls over it.
      const bool toe_down = soles.forefoot(pose, side) < kDownBand;
      const bool down = soles.lowest(pose, side) < kDownBand;
      if (down) ++stance_[side];
      if (heel_down && toe_down) ++flat_[side];
      if (down && !was_down_[side]) {
        ++stances_[side];
        if (heel_down) ++heel_first_[side];
      }
      if (!down && was_down_[side] && was_on_toe_[side]) ++toe_last_[side];
      was_down_[side] = down;
      was_on_toe_[side] = toe_down && !heel_down;
    }
  }
  double stanceShare(std::size_t side) const { return share(stance_[side], frames_); }
  double flatShare(std::size_t side) const { return share(flat_[side], frames_); }
  double flatShareOfStance(std::size_t side) const { return share(flat_[side], stance_[side]); }
  std::size_t stances(std::size_t side) const { return stances_[side]; }
  std::size_t heelFirstStances(std::size_t side) const { return heel_first_[side]; }
  std::size_t toeLastStances(std::size_t side) const { return toe_last_[side]; }

 private:
  static double share(std::size_t part, std::size_t whole) {
    return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
  }
  std::size_t frames_ = 0;
  std::array<std::size_t, 2> stance_{}, flat_{}, stances_{}, heel_first_{}, toe_last_{};
  std::array<bool, 2> was_down_{}, was_on_toe_{};
};

}  // namespace dressed_human
