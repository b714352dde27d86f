// Standalone `tracking_node`: the tracking nodelet's logic in its own process.
#include <exception>

#include <ros/ros.h>

#include "amigobot_tracking/ros/tracking_node.h"
#include "amigobot_tracking/ros/node_command_line.h"

const amigobot_tracking::ros_layer::NodeHelp kHelp{
    "The tracking controller (the nodelet amigobot_tracking/Tracking) in its own process.",
    "config/tracking.yaml and the parameter tables of docs/ros_api.md."};

int main(int argc, char** argv) {
  amigobot_tracking::ros_layer::initNode(argc, argv, "tracking", kHelp);
  ros::NodeHandle nh, pnh("~");
  amigobot_tracking::ros_layer::TrackingNode node(nh, pnh);
  try {
    node.start();
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM("tracking not started: " << e.what() << ". Nothing is enabled; fix it and restart.");
    return 1;
  }
  ros::AsyncSpinner spinner(2);  // timer and services/feedback may run side by side
  spinner.start();
  ros::waitForShutdown();
  return 0;
}
