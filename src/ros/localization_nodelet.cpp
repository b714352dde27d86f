// Nodelet amigobot_tracking/Localization: mapping or localisation in a nodelet manager.
#include <memory>

#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include "amigobot_tracking/ros/localization_node.h"

namespace amigobot_tracking {
namespace ros_layer {

class LocalizationNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    try {
      node_ = std::make_unique<LocalizationNode>(getNodeHandle(), getPrivateNodeHandle());
    } catch (const std::exception& e) {
      // Bad parameters or map: say which and stay idle rather than take the manager down.
      NODELET_FATAL_STREAM("Localization not started: " << e.what());
    }
  }
  std::unique_ptr<LocalizationNode> node_;  // destroyed on unload: stops its threads
};

}  // namespace ros_layer
}  // namespace amigobot_tracking

PLUGINLIB_EXPORT_CLASS(amigobot_tracking::ros_layer::LocalizationNodelet, nodelet::Nodelet)
