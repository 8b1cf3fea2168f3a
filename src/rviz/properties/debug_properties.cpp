#include "properties/debug_properties.h"

#include <rviz/properties/bool_property.h>

namespace dressed_human {

DebugProperties::DebugProperties(rviz::Property* parent) {
  show_skeleton_ = new rviz::BoolProperty("Show Skeleton", false,
                                          "Draw the bones as lines, visible through skin and garments.", parent,
                                          SIGNAL(changed()), this);
}

bool DebugProperties::showSkeleton() const { return show_skeleton_->getBool(); }

}  // namespace dressed_human
