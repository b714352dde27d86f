// nodelet `amigobot_tracking/Tracking`: hosts a TrackingNode in a nodelet manager (the
// driver's, on the robot), on the multi-threaded callback queue.
#pragma once

#include <memory>

#include <nodelet/nodelet.h>

#include "amigobot_tracking/ros/tracking_node.h"

namespace amigobot_tracking {
namespace ros_layer {

class TrackingNodelet : public nodelet::Nodelet {
 public:
  ~TrackingNodelet() override;

 private:
  void onInit() override;

  std::unique_ptr<TrackingNode> node_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
