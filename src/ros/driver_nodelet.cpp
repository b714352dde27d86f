// Nodelet amigobot_tracking/Driver: AmigobotDriver in a nodelet manager (nodelet_host.h).
#include <pluginlib/class_list_macros.hpp>

#include "amigobot_tracking/ros/driver.h"
#include "amigobot_tracking/ros/nodelet_host.h"

namespace amigobot_tracking {
namespace ros_layer {

constexpr char kDriverNodeletName[] = "AmigoBot driver";
using DriverNodelet = NodeletHost<AmigobotDriver, kDriverNodeletName>;

}  // namespace ros_layer
}  // namespace amigobot_tracking

PLUGINLIB_EXPORT_CLASS(amigobot_tracking::ros_layer::DriverNodelet, nodelet::Nodelet)
