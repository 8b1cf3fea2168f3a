#pragma once
// A crowd display's roster: which humans TF carries now.

#include <string>
#include <vector>

namespace tf2_ros {
class Buffer;
}  // namespace tf2_ros

namespace dressed_human {

// The suffixes ("" for body, "_<id>" for body_<id>) of the skeletons in `buffer` (a root frame
// with its waist, humanSuffixesAmong) whose root frame's newest transform from `fixed_frame` is
// at most DrawnHuman::kFreshSeconds old: tf2 keeps a stopped publisher's last transform for ever.
// Frames come from tf2's public listing.
std::vector<std::string> freshHumansInTf(const tf2_ros::Buffer& buffer, const std::string& fixed_frame);

}  // namespace dressed_human
