#include "parameters.h"

#include <cmath>
#include <cstdio>

#include <xmlrpcpp/XmlRpcValue.h>

namespace dressed_human {
namespace {

const char* typeName(const XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return "a boolean";
    case XmlRpc::XmlRpcValue::TypeInt:
      return "an integer";
    case XmlRpc::XmlRpcValue::TypeDouble:
      return "a number";
    case XmlRpc::XmlRpcValue::TypeString:
      return "a string";
    case XmlRpc::XmlRpcValue::TypeArray:
      return "a list";
    case XmlRpc::XmlRpcValue::TypeStruct:
      return "a dictionary";
    default:
      return "an unsupported value";
  }
}

}  // namespace

double Parameters::number(const std::string& name, double fallback) const {
  XmlRpc::XmlRpcValue value;
  if (!node_.getParam(name, value)) return fallback;
  double result = 0.0;
  if (value.getType() == XmlRpc::XmlRpcValue::TypeDouble) {
    result = static_cast<double>(value);
  } else if (value.getType() == XmlRpc::XmlRpcValue::TypeInt) {
    result = static_cast<int>(value);
  } else {
    throw ParameterError("parameter " + fullName(name) + " must be a number, got " + typeName(value));
  }
  if (!std::isfinite(result)) throw ParameterError("parameter " + fullName(name) + " must be finite");
  return result;
}

double Parameters::numberIn(const std::string& name, double fallback, double low, double high,
                            const std::string& unit) const {
  const double value = number(name, fallback);
  if (value < low || value > high) {
    char text[160];
    std::snprintf(text, sizeof(text), " must be in [%g, %g]%s%s, got %g", low, high, unit.empty() ? "" : " ",
                  unit.c_str(), value);
    throw ParameterError("parameter " + fullName(name) + text);
  }
  return value;
}

bool Parameters::boolean(const std::string& name, bool fallback) const {
  XmlRpc::XmlRpcValue value;
  if (!node_.getParam(name, value)) return fallback;
  if (value.getType() != XmlRpc::XmlRpcValue::TypeBoolean) {
    throw ParameterError("parameter " + fullName(name) + " must be true or false, got " + typeName(value));
  }
  return static_cast<bool>(value);
}

std::string Parameters::text(const std::string& name, const std::string& fallback) const {
  XmlRpc::XmlRpcValue value;
  if (!node_.getParam(name, value)) return fallback;
  if (value.getType() == XmlRpc::XmlRpcValue::TypeInt) return std::to_string(static_cast<int>(value));
  if (value.getType() != XmlRpc::XmlRpcValue::TypeString) {
    throw ParameterError("parameter " + fullName(name) + " must be a string, got " + typeName(value));
  }
  return static_cast<std::string>(value);
}

std::string Parameters::requiredText(const std::string& name) const {
  if (!node_.hasParam(name)) throw ParameterError("parameter " + fullName(name) + " is not set");
  return text(name, "");
}

bool Parameters::points(const std::string& name, std::vector<Eigen::Vector2d>& points) const {
  XmlRpc::XmlRpcValue value;
  if (!node_.getParam(name, value)) return false;
  const std::string expected = " must be a list of [x, y] pairs in metres, e.g. [[0, 0], [4, 0], [4, 3]]";
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray) {
    throw ParameterError("parameter " + fullName(name) + expected + ", got " + typeName(value));
  }
  points.clear();
  for (int i = 0; i < value.size(); ++i) {
    XmlRpc::XmlRpcValue& pair = value[i];
    if (pair.getType() != XmlRpc::XmlRpcValue::TypeArray || pair.size() != 2) {
      throw ParameterError("parameter " + fullName(name) + expected + "; element " + std::to_string(i) + " is " +
                           (pair.getType() == XmlRpc::XmlRpcValue::TypeArray
                                ? "a list of " + std::to_string(pair.size())
                                : std::string(typeName(pair))));
    }
    Eigen::Vector2d point;
    for (int k = 0; k < 2; ++k) {
      XmlRpc::XmlRpcValue& coordinate = pair[k];
      if (coordinate.getType() == XmlRpc::XmlRpcValue::TypeDouble) {
        point[k] = static_cast<double>(coordinate);
      } else if (coordinate.getType() == XmlRpc::XmlRpcValue::TypeInt) {
        point[k] = static_cast<int>(coordinate);
      } else {
        throw ParameterError("parameter " + fullName(name) + expected + "; element " + std::to_string(i) + " holds " +
                             typeName(coordinate));
      }
    }
    points.push_back(point);
  }
  return true;
}

}  // namespace dressed_human
