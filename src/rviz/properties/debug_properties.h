#pragma once
// The DressedHuman display's debugging aids: the skeleton drawn as lines.

#include <QObject>

#include "properties/rviz_properties_fwd.h"

namespace dressed_human {

class DebugProperties : public QObject {
  Q_OBJECT
 public:
  explicit DebugProperties(rviz::Property* parent);

  bool showSkeleton() const;

 Q_SIGNALS:
  void changed();

 private:
  rviz::BoolProperty* show_skeleton_;
};

}  // namespace dressed_human
