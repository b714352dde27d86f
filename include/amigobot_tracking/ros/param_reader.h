// The package's one reader of ROS parameters: a field table (core/field_table.h) read from a
// private NodeHandle, nested keys as nested namespaces ("estimator/a1" = ~estimator/a1).
// Type-checked (an integer is accepted for a real; any other mismatch is an error, never a
// silent default), every value logged with its unit and whether it is the default, and the
// first problem returned as "~key: reason" naming the parameter.
#pragma once

#include <string>

#include <ros/node_handle.h>

#include "amigobot_tracking/core/field_table.h"

namespace amigobot_tracking {
namespace ros_layer {

// Reads ~key as `type`: "" with *present false when unset; "~key: must be ..." on a wrong type.
std::string readParamValue(const ros::NodeHandle& pnh, const std::string& key, core::FieldType type,
                           bool* present, core::FieldValue* out);
// Logs "  /ns/key = value unit" (+ " (default)").
void logParamValue(const ros::NodeHandle& pnh, const std::string& key, const core::FieldValue& value,
                   const std::string& unit, bool is_default);

// Reads every row of `table` under ~prefix ("", or "scan/") over *config, each checked against
// its bounds. Returns "" or "~prefix/key: reason".
template <class C>
std::string readFields(const ros::NodeHandle& pnh, const core::FieldTable<C>& table, C* config,
                       const std::string& prefix = "") {
  for (const core::Field<C>& f : table) {
    const std::string key = prefix + f.key;
    bool present = false;
    core::FieldValue value;
    const std::string error = readParamValue(pnh, key, f.type, &present, &value);
    if (!error.empty()) return error;
    if (present) {
      const std::string why = core::checkValue(f.type, f.bounds, value);
      if (!why.empty()) return "~" + key + ": " + why;
      f.set(*config, value);
    }
    logParamValue(pnh, key, f.get(*config), f.unit, !present);
  }
  return "";
}

// readFields, then config->validate() for the rules across fields.
template <class C>
std::string readParams(const ros::NodeHandle& pnh, const core::FieldTable<C>& table, C* config,
                       const std::string& prefix = "") {
  const std::string error = readFields(pnh, table, config, prefix);
  if (!error.empty()) return error;
  const std::string invalid = config->validate();
  return invalid.empty() ? "" : "~" + prefix + invalid;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
