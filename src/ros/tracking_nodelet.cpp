// Nodelet amigobot_tracking/Tracking: a TrackingNode in a nodelet manager (the driver's, on
// the robot), on the multi-threaded callback queue (nodelet_host.h).
#include <pluginlib/class_list_macros.hpp>

#include "amigobot_tracking/ros/nodelet_host.h"
#include "amigobot_tracking/ros/tracking_node.h"

namespace amigobot_tracking {
namespace ros_layer {

constexpr char kTrackingNodeletName[] = "Tracking";
using TrackingNodelet = NodeletHost<TrackingNode, kTrackingNodeletName, true>;

}  // namespace ros_layer
}  // namespace amigobot_tracking

PLUGINLIB_EXPORT_CLASS(amigobot_tracking::ros_layer::TrackingNodelet, nodelet::Nodelet)
