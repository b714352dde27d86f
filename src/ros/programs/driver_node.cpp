// amigobot_driver_node: the AmigoBot driver as a standalone node (same code as the nodelet).
#include <ros/ros.h>

#include "amigobot_tracking/ros/driver.h"
#include "amigobot_tracking/ros/node_command_line.h"

const amigobot_tracking::ros_layer::NodeHelp kHelp{
    "The AmigoBot driver as a standalone node (the same code as the nodelet amigobot_tracking/Driver).",
    "include/amigobot_tracking/ros/driver.h and config/robots/*.yaml."};

int main(int argc, char** argv) {
  amigobot_tracking::ros_layer::initNode(argc, argv, "amigobot_driver", kHelp);
  return amigobot_tracking::ros_layer::spinNode<amigobot_tracking::ros_layer::AmigobotDriver>("amigobot_driver");
}
