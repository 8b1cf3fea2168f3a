#pragma once
// The DressedHuman display's crowd properties: draw the one human of the robot description, or
// every human TF carries (frames body, body_<id>) with what each wears from a crowd file or
// picked from its id.

#include <string>

#include <QObject>

#include "properties/rviz_properties_fwd.h"

namespace dressed_human {

class CrowdProperties : public QObject {
  Q_OBJECT
 public:
  explicit CrowdProperties(rviz::Property* parent);

  // true: every human in TF; false: the one the robot description names.
  bool everyHumanInTf() const;
  std::string crowdFile() const;  // empty: none
  bool varyUnlisted() const;
  double humanTimeout() const;  // seconds without fresh TF before a human leaves the display
  // The crowd-only properties show only when every human in TF is drawn.
  void updateVisibility();

 Q_SIGNALS:
  void changed();

 private Q_SLOTS:
  void humansChanged();

 private:
  rviz::EnumProperty* humans_;
  rviz::StringProperty* crowd_file_;
  rviz::BoolProperty* vary_unlisted_;
  rviz::FloatProperty* human_timeout_;
};

}  // namespace dressed_human
