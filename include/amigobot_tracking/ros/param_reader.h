// The package's one reader of ROS parameters: a field table (core/support/field_table.h) read from a
// private NodeHandle, nested keys as nested namespaces ("estimator/a1" = ~estimator/a1).
// Type-checked (an integer is accepted for a real; any other mismatch is an error, never a
// silent default), every value logged with its unit and whether it is the default, and the
// first problem returned as "~key: reason" naming the parameter.
#pragma once

#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "amigobot_tracking/core/support/field_table.h"

namespace amigobot_tracking {
namespace ros_layer {

// Unknown keys: every key read (here or noted with noteParamKey) is remembered per private
// namespace; about a second after a namespace's first read, every parameter set under it that
// no reader asked for is warned, naming the key, the node and the nearest known key (a typo
// or a config copied from another driver would otherwise fall back to a default silently).

// Another driver's name for a field ("TicksMM", RosAria's for "ticks_mm"; param_aliases.h):
// read when the field's own key is unset, with an INFO line naming the mapping; ignored, with
// a warning, when both are.
struct ParamAlias {
  std::string alias;
  std::string key;
  std::string origin;  // the driver(s) using the name: "RosAria", "urg_node and rplidar_ros"
};

// Reads ~key as `type`: "" with *present false when unset; "~key: must be ..." on a wrong type.
std::string readParamValue(const ros::NodeHandle& pnh, const std::string& key, core::FieldType type,
                           bool* present, core::FieldValue* out);
// readParamValue of ~key, or of its alias when ~key is unset (*read_as says which was read).
std::string readAliasedValue(const ros::NodeHandle& pnh, const std::string& key, core::FieldType type,
                             const std::vector<ParamAlias>& aliases, bool* present, core::FieldValue* out,
                             std::string* read_as);
// Logs "  /ns/key = value unit" (+ " (default)", or " (from ~alias)").
void logParamValue(const ros::NodeHandle& pnh, const std::string& key, const core::FieldValue& value,
                   const std::string& unit, bool is_default, const std::string& read_as = "");
// A key the node reads without the field tables (a list, a URDF): not an unknown key.
void noteParamKey(const ros::NodeHandle& pnh, const std::string& key);
// The parameters under ~ that no reader of this process asked for (keys relative to ~, sorted).
std::vector<core::UnknownKey> unknownParams(const ros::NodeHandle& pnh);

// Reads every row of `table` under ~prefix ("", or "scan/") over *config, each checked against
// its bounds. Returns "" or "~prefix/key: reason".
// `aliases`: other drivers' names of some keys (ParamAlias).
template <class C>
std::string readFields(const ros::NodeHandle& pnh, const core::FieldTable<C>& table, C* config,
                       const std::string& prefix = "", const std::vector<ParamAlias>& aliases = {}) {
  for (const core::Field<C>& f : table) {
    const std::string key = prefix + f.key;
    bool present = false;
    core::FieldValue value;
    std::string read_as;
    const std::string error = readAliasedValue(pnh, key, f.type, aliases, &present, &value, &read_as);
    if (!error.empty()) return error;
    if (present) {
      const std::string why = core::checkValue(f.type, f.bounds, value);
      if (!why.empty()) return "~" + read_as + ": " + why;
      f.set(*config, value);
    }
    logParamValue(pnh, key, f.get(*config), f.unit, !present, read_as == key ? "" : read_as);
  }
  return "";
}

// readFields, then config->validate() for the rules across fields.
template <class C>
std::string readParams(const ros::NodeHandle& pnh, const core::FieldTable<C>& table, C* config,
                       const std::string& prefix = "", const std::vector<ParamAlias>& aliases = {}) {
  const std::string error = readFields(pnh, table, config, prefix, aliases);
  if (!error.empty()) return error;
  const std::string invalid = config->validate();
  return invalid.empty() ? "" : "~" + prefix + invalid;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
