#include "properties/crowd_properties.h"

#include <ros/package.h>
#include <rviz/properties/bool_property.h>
#include <rviz/properties/enum_property.h>
#include <rviz/properties/float_property.h>
#include <rviz/properties/ros_topic_property.h>
#include <rviz/properties/string_property.h>
#include "properties/notifying.h"

namespace dressed_human {
namespace {

const char* const kRobotDescription = "Robot Description";
const char* const kEveryHumanInTf = "Every Human in TF";
const char* const kFromTopic = "From Topic";

}  // namespace

CrowdProperties::CrowdProperties(rviz::Property* parent) {
  humans_ = notifying(
      new rviz::EnumProperty(
          "Humans", kRobotDescription,
          "Robot Description: the one human whose skeleton the Robot Description names. Every Human in TF: "
          "each skeleton TF carries (root frames body, body_<id>, checked every second), all with the "
          "Robot Description's skeleton; a human whose TF stops for Human Timeout leaves the display. From Topic: "
          "every human of the dressed_human/Crowd messages on Topic (crowd_publisher), one message for all; a "
          "human absent from the messages for 1 s leaves the display.",
          parent),
      this, &CrowdProperties::humansChanged);
  humans_->addOption(kRobotDescription);
  humans_->addOption(kEveryHumanInTf);
  humans_->addOption(kFromTopic);
  topic_ = notifying(new rviz::RosTopicProperty(
                         "Topic", "/crowd", "dressed_human/Crowd",
                         "The dressed_human/Crowd topic the humans come from (crowd_publisher's /crowd).", parent),
                     this, &CrowdProperties::topicChanged);
  crowd_file_ = notifying(
      new rviz::StringProperty("Crowd File", "",
                               "YAML file of what each human wears, by id, as a path or package://<package>/<path> "
                               "(package://dressed_human/config/crowds/example.yaml); empty: none.",
                               parent),
      this, &CrowdProperties::changed);
  vary_unlisted_ =
      notifying(new rviz::BoolProperty(
                    "Vary Unlisted Humans", true,
                    "Humans the crowd file does not name get an outfit and colours picked from their id (the same "
                    "every run); off: the display's own Outfit and colours.",
                    parent),
                this, &CrowdProperties::changed);
  // Like the TF display's Frame Timeout: a pedestrian removed from a simulation, a stopped node.
  human_timeout_ = new rviz::FloatProperty(
      "Human Timeout", 5.0f, "Seconds without fresh TF (newer than 1 s) before a human leaves the display.", parent);
  human_timeout_->setMin(0.2f);
  updateVisibility();
}

bool CrowdProperties::everyHumanInTf() const { return humans_->getStdString() == kEveryHumanInTf; }

bool CrowdProperties::fromTopic() const { return humans_->getStdString() == kFromTopic; }

std::string CrowdProperties::topic() const { return topic_->getTopicStd(); }

std::string CrowdProperties::crowdFile() const {
  // package://<package>/<path>, as rviz's mesh resources are named, so that a saved config works
  // wherever the package is installed.
  const std::string text = crowd_file_->getStdString();
  const std::string scheme = "package://";
  if (text.rfind(scheme, 0) != 0) return text;
  const std::size_t slash = text.find('/', scheme.size());
  const std::string package =
      text.substr(scheme.size(), slash == std::string::npos ? std::string::npos : slash - scheme.size());
  const std::string root = ros::package::getPath(package);
  if (root.empty()) return text;  // the loader names the file it cannot open
  return root + (slash == std::string::npos ? std::string() : text.substr(slash));
}

bool CrowdProperties::varyUnlisted() const { return vary_unlisted_->getBool(); }

double CrowdProperties::humanTimeout() const { return human_timeout_->getFloat(); }

void CrowdProperties::updateVisibility() {
  topic_->setHidden(!fromTopic());
  crowd_file_->setHidden(!crowd());
  vary_unlisted_->setHidden(!crowd());
  human_timeout_->setHidden(!everyHumanInTf());
}

void CrowdProperties::humansChanged() {
  updateVisibility();
  Q_EMIT changed();
}

}  // namespace dressed_human
