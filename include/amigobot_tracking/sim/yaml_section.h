// A scenario file's YAML read strictly: a mapping whose keys are read one by one (finish()
// refuses the keys never read), numbers that must be finite, and every error as
// "FILE:LINE: section.key: reason" (ScenarioError).
#pragma once

#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include "amigobot_tracking/sim/scenario.h"

namespace amigobot_tracking {
namespace sim {

[[noreturn]] inline void fail(const std::string& file, const YAML::Node& node, const std::string& key,
                       const std::string& reason) {
  std::ostringstream msg;
  msg << file;
  if (node.IsDefined() && node.Mark().line >= 0) msg << ":" << node.Mark().line + 1;
  msg << ": " << key << ": " << reason;
  throw ScenarioError(msg.str());
}

inline std::string describe(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

// The one number reader of the simulator's files: a scalar that decodes as a double, finite
// unless allow_infinite (a limit's "no limit", .inf), never NaN.
inline double readNumber(const std::string& file, const YAML::Node& node, const std::string& where,
                         bool allow_infinite = false) {
  double value = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, value))
    fail(file, node, where, "expected a number, got " + describe(node));
  if (std::isnan(value) || (!allow_infinite && std::isinf(value)))
    fail(file, node, where, std::string(allow_infinite ? "must be a number or +-.inf" : "must be finite") + ", got " +
                                describe(node));
  return value;
}

// A YAML mapping whose keys are read one by one; finish() refuses the keys never read.
class Section {
 public:
  Section(const YAML::Node& node, std::string path, const std::string& file)
      : node_(node), path_(std::move(path)), file_(file) {
    if (!node.IsMap()) fail(file_, node, path_, "expected a mapping {key: value, ...}, got " + describe(node));
    for (const auto& item : node_) {
      if (!item.first.IsScalar()) fail(file_, item.first, key("(key)"), "a key must be a word, got " + describe(item.first));
    }
  }

  std::string key(const std::string& name) const { return path_.empty() ? name : path_ + "." + name; }
  bool has(const std::string& name) const { return node_[name].IsDefined() && !node_[name].IsNull(); }

  YAML::Node required(const std::string& name) {
    used_.insert(name);
    const YAML::Node value = node_[name];
    if (!value.IsDefined() || value.IsNull()) fail(file_, node_, key(name), "missing (required)");
    return value;
  }
  YAML::Node optional(const std::string& name) {
    used_.insert(name);
    return node_[name];
  }

  double number(const std::string& name) { return toNumber(required(name), key(name)); }
  double number(const std::string& name, double fallback) {
    return has(name) ? toNumber(optional(name), key(name)) : (used_.insert(name), fallback);
  }
  bool boolean(const std::string& name) { return toBool(required(name), key(name)); }
  bool boolean(const std::string& name, bool fallback) {
    return has(name) ? toBool(optional(name), key(name)) : (used_.insert(name), fallback);
  }
  std::string text(const std::string& name) { return toText(required(name), key(name)); }
  std::string text(const std::string& name, const std::string& fallback) {
    return has(name) ? toText(optional(name), key(name)) : (used_.insert(name), fallback);
  }
  std::vector<double> numbers(const std::string& name, size_t count) {
    return toNumbers(required(name), key(name), count);
  }
  Eigen::Vector2d point(const std::string& name) {
    const std::vector<double> v = numbers(name, 2);
    return {v[0], v[1]};
  }

  void finish() const {
    for (const auto& item : node_) {
      const std::string name = item.first.Scalar();  // a word: checked by the constructor
      if (!used_.count(name)) fail(file_, item.first, key(name), "unknown key (misspelt?)");
    }
  }

  double toNumber(const YAML::Node& node, const std::string& where) const { return readNumber(file_, node, where); }
  bool toBool(const YAML::Node& node, const std::string& where) const {
    bool value = false;
    if (!node.IsScalar() || !YAML::convert<bool>::decode(node, value))
      fail(file_, node, where, "expected true or false, got " + describe(node));
    return value;
  }
  std::string toText(const YAML::Node& node, const std::string& where) const {
    if (!node.IsScalar()) fail(file_, node, where, "expected a word, got " + describe(node));
    return node.Scalar();
  }
  std::vector<double> toNumbers(const YAML::Node& node, const std::string& where, size_t count) const {
    if (!node.IsSequence() || node.size() != count)
      fail(file_, node, where, "expected a list of " + std::to_string(count) + " numbers, got " + describe(node));
    std::vector<double> out;
    for (size_t i = 0; i < count; ++i) out.push_back(toNumber(node[i], where + "[" + std::to_string(i) + "]"));
    return out;
  }
  const std::string& file() const { return file_; }
  const YAML::Node& node() const { return node_; }

 private:
  YAML::Node node_;
  std::string path_;
  const std::string& file_;
  std::set<std::string> used_;
};

}  // namespace sim
}  // namespace amigobot_tracking
