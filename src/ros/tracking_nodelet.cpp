#include "amigobot_tracking/ros/tracking_nodelet.h"

#include <pluginlib/class_list_macros.hpp>

namespace amigobot_tracking {
namespace ros_layer {

TrackingNodelet::~TrackingNodelet() { node_.reset(); }

void TrackingNodelet::onInit() {
  node_ = std::make_unique<TrackingNode>(getMTNodeHandle(), getMTPrivateNodeHandle());
  if (!node_->start()) {
    // The error naming the parameter is already logged. Stay loaded but inert: no
    // subscriptions, no timer, no services, so nothing can ever enable tracking.
    NODELET_FATAL("%s: not started because of a configuration error", getName().c_str());
    node_.reset();
  }
}

}  // namespace ros_layer
}  // namespace amigobot_tracking

PLUGINLIB_EXPORT_CLASS(amigobot_tracking::ros_layer::TrackingNodelet, nodelet::Nodelet)
