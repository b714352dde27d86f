// Standalone `tracking_node`: the tracking nodelet's logic in its own process.
#include <ros/ros.h>

#include "amigobot_tracking/ros/tracking_node.h"
#include "amigobot_tracking/ros/node_command_line.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "tracking");
  amigobot_tracking::ros_layer::parseNodeCommandLine(
      argc, argv, "tracking_node",
      "The tracking controller (the nodelet amigobot_tracking/Tracking) in its own process.",
      "config/tracking.yaml and the README's parameter tables.");
  ros::NodeHandle nh, pnh("~");
  amigobot_tracking::ros_layer::TrackingNode node(nh, pnh);
  if (!node.start()) return 1;  // configuration error: logged, nothing enabled
  ros::AsyncSpinner spinner(2);  // timer and services/feedback may run side by side
  spinner.start();
  ros::waitForShutdown();
  return 0;
}
