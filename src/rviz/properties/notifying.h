#pragma once
// Connects a property's change to a member of its group (a signal the display listens to, or a
// slot of the group's own), checked when compiled: rviz's Property constructors take that member
// as a SIGNAL()/SLOT() string, which a renamed member breaks only at run time, silently (issue 38).

#include <QObject>
#include <rviz/properties/property.h>

namespace dressed_human {

template <typename PropertyType, typename Receiver, typename Member>
PropertyType* notifying(PropertyType* property, Receiver* receiver, Member member) {
  QObject::connect(property, &rviz::Property::changed, receiver, member);
  return property;
}

}  // namespace dressed_human
