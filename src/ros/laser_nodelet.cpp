// Nodelet amigobot_tracking/Laser: LaserNode in a nodelet manager (nodelet_host.h).
#include <pluginlib/class_list_macros.hpp>

#include "amigobot_tracking/ros/laser_node.h"
#include "amigobot_tracking/ros/nodelet_host.h"

namespace amigobot_tracking {
namespace ros_layer {

constexpr char kLaserNodeletName[] = "Laser";
using LaserNodelet = NodeletHost<LaserNode, kLaserNodeletName>;

}  // namespace ros_layer
}  // namespace amigobot_tracking

PLUGINLIB_EXPORT_CLASS(amigobot_tracking::ros_layer::LaserNodelet, nodelet::Nodelet)
