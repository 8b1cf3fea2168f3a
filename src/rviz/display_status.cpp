#include "display_status.h"

#include <ros/console.h>
#include <rviz/display.h>

namespace dressed_human {

void DisplayStatus::error(const std::string& name, const std::string& text, bool transient) {
  display_.setStatusStd(rviz::StatusProperty::Error, name, text);
  std::string& last = logged_errors_[name];
  if (last == text) return;
  const std::string display = display_.getName().toStdString();
  if (transient) {
    ROS_WARN_NAMED("dressed_human", "DressedHuman display '%s': %s: %s", display.c_str(), name.c_str(), text.c_str());
  } else {
    ROS_ERROR_NAMED("dressed_human", "DressedHuman display '%s': %s: %s", display.c_str(), name.c_str(), text.c_str());
  }
  last = text;
}

void DisplayStatus::warn(const std::string& name, const std::string& text) {
  display_.setStatusStd(rviz::StatusProperty::Warn, name, text);
  warnings_.insert(name);
}

void DisplayStatus::ok(const std::string& name, const std::string& text) {
  display_.setStatusStd(rviz::StatusProperty::Ok, name, text);
  logged_errors_.erase(name);
  warnings_.insert(name);
}

void DisplayStatus::clear(const std::string& name) {
  const auto reported = logged_errors_.find(name);
  const auto warned = warnings_.find(name);
  if (reported == logged_errors_.end() && warned == warnings_.end()) return;
  display_.deleteStatusStd(name);
  if (reported != logged_errors_.end()) logged_errors_.erase(reported);
  if (warned != warnings_.end()) warnings_.erase(warned);
}

void DisplayStatus::forget() {
  logged_errors_.clear();
  warnings_.clear();
}

}  // namespace dressed_human
