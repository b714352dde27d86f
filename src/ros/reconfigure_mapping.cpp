#include "amigobot_tracking/ros/reconfigure_mapping.h"

namespace amigobot_tracking {
namespace ros_layer {
namespace reconfigure_detail {

std::string entryError(const std::string& name, bool found, bool live, bool same_type) {
  if (!found) return "reconfigure entry '" + name + "' names no field";
  if (!live) return "reconfigure entry '" + name + "' is no live field";
  if (!same_type) return "reconfigure entry '" + name + "' has another type than its field";
  return "";
}

}  // namespace reconfigure_detail
}  // namespace ros_layer
}  // namespace amigobot_tracking
