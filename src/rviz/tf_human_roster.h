#pragma once
// A crowd display's roster: which humans TF carries now.

#include <string>
#include <vector>

#include "dressed_human/core/skeleton/skeleton.h"

namespace tf2_ros {
class Buffer;
}  // namespace tf2_ros

namespace dressed_human {

// The suffixes ("" for body, "_<id>" for body_<id>) of the skeletons in `buffer` (a root frame
// with its waist, humanSuffixesAmong) whose root frame's newest transform from `fixed_frame` is
// at most DrawnHuman::kFreshSeconds old: tf2 keeps a stopped publisher's last transform for ever.
// Frames come from tf2's public listing.
std::vector<std::string> freshHumansInTf(const tf2_ros::Buffer& buffer, const std::string& fixed_frame);

// How tall the human of `suffix` is against `skeleton` (the display's robot description), from
// its TF: the knee's offset in the thigh over the skeleton's. 1 when TF does not say yet. Crowd
// humans may each have their own proportions (crowd_member.launch's stature) in one TF tree.
double statureInTf(const tf2_ros::Buffer& buffer, const Skeleton& skeleton, const std::string& suffix);

}  // namespace dressed_human
