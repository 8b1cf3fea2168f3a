#pragma once
// A display's statuses with their log lines: each error is also logged once per new text, so
// that headless runs and tests see what went wrong; clearing what was never reported costs a
// map lookup (bones are cleared every frame).

#include <map>
#include <set>
#include <string>

namespace rviz {
class Display;
}  // namespace rviz

namespace dressed_human {

class DisplayStatus {
 public:
  explicit DisplayStatus(rviz::Display& display) : display_(display) {}

  // An Error status; logged as a warning if `transient` (missing TF: startup, a stopped
  // publisher), else as an error.
  void error(const std::string& name, const std::string& text, bool transient = false);
  // A Warn status, not logged (its text may change every frame).
  void warn(const std::string& name, const std::string& text);
  // An Ok status (what is going well: counts, rates), replacing an error or warning of that name.
  void ok(const std::string& name, const std::string& text);
  // Removes the status `name` if error() or warn() set it.
  void clear(const std::string& name);
  // Forgets what was reported, after rviz::Display::reset() removed every status.
  void forget();

 private:
  rviz::Display& display_;
  std::map<std::string, std::string> logged_errors_;
  std::set<std::string> warnings_;  // and Ok statuses: every status clear() must remove
};

}  // namespace dressed_human
