#include "amigobot_tracking/ros/param_reader.h"

#include <algorithm>
#include <map>
#include <mutex>
#include <set>

#include <ros/console.h>
#include <ros/param.h>
#include <ros/this_node.h>

namespace amigobot_tracking {
namespace ros_layer {
namespace {

std::string xmlTypeName(XmlRpc::XmlRpcValue::Type type) {
  switch (type) {
    case XmlRpc::XmlRpcValue::TypeBoolean: return "a boolean";
    case XmlRpc::XmlRpcValue::TypeInt: return "an integer";
    case XmlRpc::XmlRpcValue::TypeDouble: return "a number";
    case XmlRpc::XmlRpcValue::TypeString: return "a string";
    case XmlRpc::XmlRpcValue::TypeArray: return "a list";
    case XmlRpc::XmlRpcValue::TypeStruct: return "a namespace";
    default: return "another type";
  }
}

// Keys read per private namespace, and one pending unknown-key check per namespace. Never
// destroyed: a timer must not outlive ROS's timer manager at exit.
std::mutex keys_mutex;
std::map<std::string, std::set<std::string>>& keysRead() {
  static auto* keys = new std::map<std::string, std::set<std::string>>();
  return *keys;
}
std::map<std::string, ros::WallTimer>& pendingChecks() {
  static auto* timers = new std::map<std::string, ros::WallTimer>();
  return *timers;
}
// Long enough for a node's (or nodelet's) start-up to read all its tables.
constexpr double kUnknownCheckDelay = 1.0;

void warnUnknownParams(const ros::NodeHandle& pnh) {
  for (const core::UnknownKey& u : unknownParams(pnh)) {
    ROS_WARN_STREAM_NAMED("params", "~" << u.key << " (" << pnh.resolveName(u.key) << ") is not a parameter of "
                                        << pnh.getNamespace() << " (" << ros::this_node::getName()
                                        << "): ignored"
                                        << (u.nearest.empty() ? std::string(" (docs/ros_api.md lists the parameters)")
                                                              : "; did you mean ~" + u.nearest + "?"));
  }
}

void rememberKey(const ros::NodeHandle& pnh, const std::string& key) {
  const std::string ns = pnh.getNamespace();
  std::lock_guard<std::mutex> lock(keys_mutex);
  keysRead()[ns].insert(key);
  if (pendingChecks().count(ns)) return;
  // The global queue (not the nodelet's, which dies with it): spun by every node and manager.
  static auto* global = new ros::NodeHandle();
  pendingChecks()[ns] = global->createWallTimer(
      ros::WallDuration(kUnknownCheckDelay), [pnh](const ros::WallTimerEvent&) { warnUnknownParams(pnh); }, true);
}

}  // namespace

void noteParamKey(const ros::NodeHandle& pnh, const std::string& key) { rememberKey(pnh, key); }

std::vector<core::UnknownKey> unknownParams(const ros::NodeHandle& pnh) {
  const std::string ns = pnh.getNamespace();
  std::vector<std::string> all, present, known;
  if (!ros::param::getParamNames(all)) return {};
  const std::string under = ns == "/" ? "/" : ns + "/";
  for (const std::string& name : all)
    if (name.compare(0, under.size(), under) == 0) present.push_back(name.substr(under.size()));
  std::sort(present.begin(), present.end());  // the server's order is none
  {
    std::lock_guard<std::mutex> lock(keys_mutex);
    const auto it = keysRead().find(ns);
    if (it != keysRead().end()) known.assign(it->second.begin(), it->second.end());
  }
  return core::unknownKeys(present, known);
}

std::string readAliasedValue(const ros::NodeHandle& pnh, const std::string& key, core::FieldType type,
                             const std::vector<ParamAlias>& aliases, bool* present, core::FieldValue* out,
                             std::string* read_as) {
  *read_as = key;
  const std::string error = readParamValue(pnh, key, type, present, out);
  if (!error.empty()) return error;
  for (const ParamAlias& a : aliases) {
    if (a.key != key) continue;
    bool alias_present = false;
    core::FieldValue alias_value;
    if (*present) {
      rememberKey(pnh, a.alias);
      if (pnh.hasParam(a.alias))
        ROS_WARN_STREAM_NAMED("params", "~" << a.alias << " (~" << key << "'s name in " << a.origin
                                            << ") ignored: ~" << key << " is set too");
      continue;
    }
    const std::string alias_error = readParamValue(pnh, a.alias, type, &alias_present, &alias_value);
    if (!alias_error.empty()) return alias_error;
    if (alias_present) {
      *present = true;
      *out = alias_value;
      *read_as = a.alias;
      ROS_INFO_STREAM_NAMED("params", "~" << a.alias << " read as ~" << key << " (its name in " << a.origin << ")");
      return "";
    }
  }
  return "";
}

std::string readParamValue(const ros::NodeHandle& pnh, const std::string& key, core::FieldType type,
                           bool* present, core::FieldValue* out) {
  rememberKey(pnh, key);
  XmlRpc::XmlRpcValue v;
  *present = pnh.getParam(key, v);
  if (!*present) return "";
  const XmlRpc::XmlRpcValue::Type got = v.getType();
  using X = XmlRpc::XmlRpcValue;
  if (type == core::FieldType::kReal && got == X::TypeDouble) {
    *out = static_cast<double>(v);
  } else if (type == core::FieldType::kReal && got == X::TypeInt) {
    *out = static_cast<double>(static_cast<int>(v));
  } else if (type == core::FieldType::kInteger && got == X::TypeInt) {
    *out = static_cast<int>(v);
  } else if (type == core::FieldType::kBoolean && got == X::TypeBoolean) {
    *out = static_cast<bool>(v);
  } else if (type == core::FieldType::kText && got == X::TypeString) {
    *out = static_cast<std::string>(v);
  } else {
    return "~" + key + ": must be " + core::typeName(type) + ", got " + xmlTypeName(got);
  }
  return "";
}

void logParamValue(const ros::NodeHandle& pnh, const std::string& key, const core::FieldValue& value,
                   const std::string& unit, bool is_default, const std::string& read_as) {
  const bool show_unit = !unit.empty() && unit != "-";
  ROS_INFO_STREAM_NAMED("params", "  " << pnh.resolveName(key) << " = " << core::formatValue(value)
                                       << (show_unit ? " " + unit : "") << (is_default ? " (default)" : "")
                                       << (read_as.empty() ? "" : " (from ~" + read_as + ")"));
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
