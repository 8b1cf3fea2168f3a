#include "tf_human_roster.h"

#include <sstream>

#include <ros/time.h>
#include <tf2_ros/buffer.h>

#include "dressed_human/core/skeleton/skeleton.h"
#include "drawn_human.h"

namespace dressed_human {
namespace {

// Every frame tf2 knows, from its listing ("Frame <child> exists with parent <parent>.").
std::vector<std::string> framesInTf(const tf2_ros::Buffer& buffer) {
  std::vector<std::string> frames;
  std::istringstream listing(buffer.allFramesAsString());
  for (std::string word, frame; listing >> word;) {
    if (word == "Frame" && listing >> frame) frames.push_back(frame);
  }
  return frames;
}

bool freshInTf(const tf2_ros::Buffer& buffer, const std::string& fixed, const std::string& frame) {
  try {
    return DrawnHuman::fresh(buffer.lookupTransform(fixed, frame, ros::Time(0)).header.stamp);
  } catch (const tf2::TransformException&) {
    return false;
  }
}

}  // namespace

std::vector<std::string> freshHumansInTf(const tf2_ros::Buffer& buffer, const std::string& fixed_frame) {
  std::vector<std::string> fresh;
  for (const std::string& suffix : humanSuffixesAmong(framesInTf(buffer))) {
    if (freshInTf(buffer, fixed_frame, "body" + suffix)) fresh.push_back(suffix);
  }
  return fresh;
}

}  // namespace dressed_human
