#pragma once
// A display's statuses with their log lines: each error is also logged once per new text, so
// that headless runs and tests see what went wrong; clearing what was never reported costs a
// map lookup (bones are cleared every frame). The display's one way to set a status.

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
  // A Warn status; logged once per new text if `logged` (else its text may change every frame).
  void warn(const std::string& name, const std::string& text, bool logged = false);
  // An Ok status (what is going well: counts, rates), replacing an error or warning of that name.
  void ok(const std::string& name, const std::string& text);
  // Removes the status `name` if error(), warn() or ok() set it.
  void clear(const std::string& name);

 private:
  // Logs "DressedHuman display '<name>': <status>: <text>" unless that text was the last logged.
  void logOnce(const std::string& name, const std::string& text, bool as_error);

  rviz::Display& display_;
  std::map<std::string, std::string> logged_;  // the last text logged, by status
  std::set<std::string> shown_;                // every status clear() must remove
};

}  // namespace dressed_human
