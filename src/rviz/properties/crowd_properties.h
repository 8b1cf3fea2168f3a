#pragma once
// The DressedHuman display's crowd properties: draw the one human of the robot description,
// every human TF carries (frames body, body_<id>), or every human of a crowd topic
// (dressed_human/Crowd), with what each wears from a crowd file or picked from its id.

#include <string>

#include <QObject>

#include "properties/rviz_properties_fwd.h"

namespace dressed_human {

class CrowdProperties : public QObject {
  Q_OBJECT
 public:
  explicit CrowdProperties(rviz::Property* parent);

  // Every human in TF (found by their frames).
  bool everyHumanInTf() const;
  // Every human of the crowd messages on topic().
  bool fromTopic() const;
  // Either of the two: humans by id, dressed from the crowd file.
  bool crowd() const { return everyHumanInTf() || fromTopic(); }
  std::string topic() const;
  std::string crowdFile() const;  // empty: none
  bool varyUnlisted() const;
  double humanTimeout() const;  // seconds without fresh TF before a human leaves the display
  // The crowd-only properties show only for a crowd, the topic only for From Topic.
  void updateVisibility();

 Q_SIGNALS:
  void changed();
  void topicChanged();

 private Q_SLOTS:
  void humansChanged();

 private:
  rviz::EnumProperty* humans_;
  rviz::RosTopicProperty* topic_;
  rviz::StringProperty* crowd_file_;
  rviz::BoolProperty* vary_unlisted_;
  rviz::FloatProperty* human_timeout_;
};

}  // namespace dressed_human
