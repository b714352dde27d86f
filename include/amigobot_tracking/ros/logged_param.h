// Reads one private parameter (absent: keeps the default) and logs the value in use, so a
// node's log shows its whole configuration.
#pragma once

#include <string>

#include <ros/console.h>
#include <ros/node_handle.h>

namespace amigobot_tracking {
namespace ros_layer {

template <typename T>
void loggedParam(const ros::NodeHandle& pnh, const std::string& name, T* value) {
  pnh.param(name, *value, *value);
  ROS_INFO_STREAM("  " << pnh.resolveName(name) << " = " << *value);
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
