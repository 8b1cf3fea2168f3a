#include "tf_human_roster.h"

#include <cmath>
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

double statureInTf(const tf2_ros::Buffer& buffer, const Skeleton& skeleton, const std::string& suffix) {
  const Skeleton human = skeleton.withSuffix(suffix);
  const int knee = human.findBone("l_knee");
  if (knee < 0) return 1.0;
  const Bone& shank = human.bone(static_cast<std::size_t>(knee));
  const ArticulatedJoint& joint = human.joint(static_cast<std::size_t>(shank.joint));
  try {
    const auto t = buffer.lookupTransform(human.frameName("l_hip"), joint.intermediate_links[0], ros::Time(0))
                       .transform.translation;
    const double rest = shank.rest_translation.norm();
    const double stature = std::sqrt(t.x * t.x + t.y * t.y + t.z * t.z) / rest;
    return rest > 0.0 && std::isfinite(stature) && stature > 0.5 && stature < 2.0 ? stature : 1.0;
  } catch (const tf2::TransformException&) {
    return 1.0;
  }
}

}  // namespace dressed_human
