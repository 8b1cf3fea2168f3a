#include "display_status.h"

#include <ros/console.h>
#include <rviz/display.h>

namespace dressed_human {

void DisplayStatus::logOnce(const std::string& name, const std::string& text, bool as_error) {
  std::string& last = logged_[name];
  if (last == text) return;
  const std::string display = display_.getName().toStdString();
  if (as_error) {
    ROS_ERROR_NAMED("dressed_human", "DressedHuman display '%s': %s: %s", display.c_str(), name.c_str(), text.c_str());
  } else {
    ROS_WARN_NAMED("dressed_human", "DressedHuman display '%s': %s: %s", display.c_str(), name.c_str(), text.c_str());
  }
  last = text;
}

void DisplayStatus::error(const std::string& name, const std::string& text, bool transient) {
  display_.setStatusStd(rviz::StatusProperty::Error, name, text);
  shown_.insert(name);
  logOnce(name, text, !transient);
}

void DisplayStatus::warn(const std::string& name, const std::string& text, bool logged) {
  display_.setStatusStd(rviz::StatusProperty::Warn, name, text);
  shown_.insert(name);
  if (logged) logOnce(name, text, false);
}

void DisplayStatus::ok(const std::string& name, const std::string& text) {
  display_.setStatusStd(rviz::StatusProperty::Ok, name, text);
  shown_.insert(name);
  logged_.erase(name);  // the same problem again is news
}

void DisplayStatus::clear(const std::string& name) {
  const auto shown = shown_.find(name);
  if (shown == shown_.end()) return;
  display_.deleteStatusStd(name);
  shown_.erase(shown);
  logged_.erase(name);
}

}  // namespace dressed_human
