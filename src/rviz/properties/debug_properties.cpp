#include "properties/debug_properties.h"

#include <rviz/properties/bool_property.h>
#include "properties/notifying.h"

namespace dressed_human {

DebugProperties::DebugProperties(rviz::Property* parent) {
  show_skeleton_ =
      notifying(new rviz::BoolProperty("Show Skeleton", false,
                                       "Draw the bones as lines, visible through skin and garments.", parent),
                this, &DebugProperties::changed);
}

bool DebugProperties::showSkeleton() const { return show_skeleton_->getBool(); }

}  // namespace dressed_human
