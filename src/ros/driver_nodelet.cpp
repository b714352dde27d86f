// Nodelet amigobot_tracking/Driver: the AmigoBot driver in a nodelet manager.
#include <memory>

#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include "amigobot_tracking/ros/driver.h"

namespace amigobot_tracking {
namespace ros_layer {

class DriverNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      driver_ = std::make_unique<AmigobotDriver>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const std::exception& e) {
      // Bad parameters: say which and stay idle rather than take the manager down.
      NODELET_FATAL_STREAM("AmigoBot driver not started: " << e.what());
    }
  }
  std::unique_ptr<AmigobotDriver> driver_;  // destroyed on unload: stops the robot cleanly
};

}  // namespace ros_layer
}  // namespace amigobot_tracking

PLUGINLIB_EXPORT_CLASS(amigobot_tracking::ros_layer::DriverNodelet, nodelet::Nodelet)
