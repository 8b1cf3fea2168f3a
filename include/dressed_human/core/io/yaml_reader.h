#pragma once
// Strict reading of the project's YAML files (motions, bodies, garments): every error names the
// file, line and column, and the key path, e.g.
//   walk.yaml:4:25: joints.waist.y.a[2]: expected a finite number, got '.nan'
// and is thrown as the loader's own exception type `Error` (constructible from a string).

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace dressed_human {

template <typename Error>
class YamlReader {
 public:
  explicit YamlReader(std::string source) : source_(std::move(source)) {}

  // Parses the text; syntax errors become Error with their position. `what` names the
  // document in the message for an empty file ("the motion file").
  YAML::Node load(const std::string& text, const std::string& what) const {
    YAML::Node document;
    try {
      document = YAML::Load(text);
    } catch (const YAML::ParserException& error) {
      std::ostringstream message;
      message << source_ << ':' << error.mark.line + 1 << ':' << error.mark.column + 1
              << ": not valid YAML: " << error.msg;
      throw Error(message.str());
    }
    if (!document || document.IsNull()) throw Error(source_ + ": " + what + " is empty");
    requireMap(document, "(top level)");
    rejectDuplicateKeys(document, "");
    return document;
  }

  // yaml-cpp keeps a repeated key and answers lookups with the first one, so the second would be
  // ignored in silence; YAML 1.2 forbids repeated keys. Checked through the whole document.
  void rejectDuplicateKeys(const YAML::Node& node, const std::string& key) const {
    if (node.IsMap()) {
      std::map<std::string, YAML::Mark> seen;
      for (const auto& entry : node) {
        const std::string name = entry.first.IsScalar() ? entry.first.Scalar() : std::string();
        const std::string child_key = join(key, name);
        if (entry.first.IsScalar()) {
          const auto first = seen.emplace(name, entry.first.Mark());
          if (!first.second) {
            fail(entry.first, child_key,
                 "the key appears twice (first at line " + std::to_string(first.first->second.line + 1) +
                     "); YAML does not allow a repeated key");
          }
        }
        rejectDuplicateKeys(entry.second, child_key);
      }
    } else if (node.IsSequence()) {
      for (std::size_t i = 0; i < node.size(); ++i) rejectDuplicateKeys(node[i], key + "[" + std::to_string(i) + "]");
    }
  }

  [[noreturn]] void fail(const YAML::Node& node, const std::string& key, const std::string& message) const {
    std::ostringstream text;
    text << source_;
    const YAML::Mark mark = node.Mark();
    if (mark.line >= 0) text << ':' << mark.line + 1 << ':' << mark.column + 1;
    text << ": " << key << ": " << message;
    throw Error(text.str());
  }

  void requireMap(const YAML::Node& node, const std::string& key) const {
    if (!node.IsMap()) fail(node, key, "expected a mapping (key: value pairs), got " + describe(node));
  }

  void rejectUnknownKeys(const YAML::Node& map, const std::string& key, const std::set<std::string>& allowed) const {
    for (const auto& entry : map) {
      const std::string name = entry.first.Scalar();
      if (allowed.count(name) == 0) {
        std::string list;
        for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
        fail(entry.first, join(key, name), "unknown key; expected one of: " + list);
      }
    }
  }

  YAML::Node require(const YAML::Node& map, const std::string& name, const std::string& key) const {
    const YAML::Node child = map[name];
    if (!child) fail(map, join(key, name), "missing");
    return child;
  }

  double number(const YAML::Node& node, const std::string& key) const {
    if (!node.IsScalar()) fail(node, key, "expected a number, got " + describe(node));
    double value = 0.0;
    try {
      value = node.as<double>();
    } catch (const YAML::Exception&) {
      fail(node, key, "expected a number, got '" + node.Scalar() + "'");
    }
    if (!std::isfinite(value)) fail(node, key, "expected a finite number, got '" + node.Scalar() + "'");
    return value;
  }

  // A number in [low, high] (`unit` after each figure of the message, e.g. " m"): sizes and
  // positions a person or a garment can have, so that no absurd value reaches the geometry.
  double numberWithin(const YAML::Node& node, const std::string& key, double low, double high,
                      const std::string& unit) const {
    const double value = number(node, key);
    if (!(value >= low && value <= high)) {
      std::ostringstream range;
      range << value << unit << " is outside [" << low << ", " << high << "]" << unit;
      fail(node, key, range.str());
    }
    return value;
  }

  // A list of numbers; `count` > 0 demands exactly that many (`what` says what they mean).
  // `first_index` is how the message numbers the elements (1 for a_1..a_m).
  std::vector<double> numbers(const YAML::Node& node, const std::string& key, std::size_t count = 0,
                              const std::string& what = "", int first_index = 0) const {
    if (!node.IsSequence() || (count > 0 && node.size() != count)) {
      const std::string expected = count > 0 ? "a list of " + std::to_string(count) + " numbers" : "a list of numbers";
      fail(node, key, "expected " + expected + (what.empty() ? "" : " " + what) + ", got " + describe(node));
    }
    std::vector<double> values;
    for (std::size_t i = 0; i < node.size(); ++i) {
      values.push_back(number(node[i], key + "[" + std::to_string(static_cast<int>(i) + first_index) + "]"));
    }
    return values;
  }

  bool boolean(const YAML::Node& node, const std::string& key) const {
    bool value = false;
    if (!node.IsScalar() || !YAML::convert<bool>::decode(node, value)) {
      fail(node, key, "expected true or false, got " + describe(node));
    }
    return value;
  }

  std::string text(const YAML::Node& node, const std::string& key) const {
    if (!node.IsScalar()) fail(node, key, "expected a text, got " + describe(node));
    return node.Scalar();
  }

  static std::string describe(const YAML::Node& node) {
    switch (node.Type()) {
      case YAML::NodeType::Null:
        return "nothing (null)";
      case YAML::NodeType::Scalar:
        return "'" + node.Scalar() + "'";
      case YAML::NodeType::Sequence:
        return "a list of " + std::to_string(node.size());
      case YAML::NodeType::Map:
        return "a mapping";
      default:
        return "an undefined value";
    }
  }

 private:
  static std::string join(const std::string& key, const std::string& name) {
    return key.empty() ? name : key + "." + name;
  }

  std::string source_;
};

}  // namespace dressed_human
