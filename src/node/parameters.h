#pragma once
// Typed reading of ROS parameters: a wrong type or value names the parameter.

#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <ros/node_handle.h>

namespace dressed_human {

struct ParameterError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Parameters {
 public:
  explicit Parameters(const ros::NodeHandle& node) : node_(node) {}

  double number(const std::string& name, double fallback) const;
  // The number, which must lie in [low, high] (`unit` names them in the message).
  double numberIn(const std::string& name, double fallback, double low, double high, const std::string& unit) const;
  bool boolean(const std::string& name, bool fallback) const;
  std::string text(const std::string& name, const std::string& fallback) const;
  std::string requiredText(const std::string& name) const;
  // A list of [x, y] pairs of finite numbers; false when the parameter is not set.
  bool points(const std::string& name, std::vector<Eigen::Vector2d>& points) const;
  std::string fullName(const std::string& name) const { return node_.resolveName(name); }

 private:
  ros::NodeHandle node_;
};

}  // namespace dressed_human
