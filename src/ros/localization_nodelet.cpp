// Nodelet amigobot_tracking/Localization: LocalizationNode in a nodelet manager (nodelet_host.h).
#include <pluginlib/class_list_macros.hpp>

#include "amigobot_tracking/ros/localization_node.h"
#include "amigobot_tracking/ros/nodelet_host.h"

namespace amigobot_tracking {
namespace ros_layer {

constexpr char kLocalizationNodeletName[] = "Localization";
using LocalizationNodelet = NodeletHost<LocalizationNode, kLocalizationNodeletName>;

}  // namespace ros_layer
}  // namespace amigobot_tracking

PLUGINLIB_EXPORT_CLASS(amigobot_tracking::ros_layer::LocalizationNodelet, nodelet::Nodelet)
