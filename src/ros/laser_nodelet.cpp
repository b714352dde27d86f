// Nodelet amigobot_tracking/Laser: the laser driver in a nodelet manager.
#include <memory>

#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include "amigobot_tracking/ros/laser_node.h"

namespace amigobot_tracking {
namespace ros_layer {

class LaserNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      laser_ = std::make_unique<LaserNode>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const std::exception& e) {
      // Bad parameters: say which and stay idle rather than take the manager down.
      NODELET_FATAL_STREAM("Laser not started: " << e.what());
    }
  }
  std::unique_ptr<LaserNode> laser_;  // destroyed on unload: stops the I/O thread, closes the device
};

}  // namespace ros_layer
}  // namespace amigobot_tracking

PLUGINLIB_EXPORT_CLASS(amigobot_tracking::ros_layer::LaserNodelet, nodelet::Nodelet)
