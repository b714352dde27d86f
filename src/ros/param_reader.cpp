#include "amigobot_tracking/ros/param_reader.h"

#include <ros/console.h>

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

}  // namespace

std::string readParamValue(const ros::NodeHandle& pnh, const std::string& key, core::FieldType type,
                           bool* present, core::FieldValue* out) {
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
                   const std::string& unit, bool is_default) {
  const bool show_unit = !unit.empty() && unit != "-";
  ROS_INFO_STREAM_NAMED("params", "  " << pnh.resolveName(key) << " = " << core::formatValue(value)
                                       << (show_unit ? " " + unit : "") << (is_default ? " (default)" : ""));
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
