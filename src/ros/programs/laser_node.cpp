// laser_node: the laser driver as a standalone node (same code as the nodelet).
#include <ros/ros.h>

#include "amigobot_tracking/ros/laser_node.h"
#include "amigobot_tracking/ros/node_command_line.h"

const amigobot_tracking::ros_layer::NodeHelp kHelp{
    "The laser driver (Hokuyo URG over SCIP 2.0, SICK TiM5xx over CoLa-A) as a standalone node "
    "(the same code as the nodelet amigobot_tracking/Laser).",
    "include/amigobot_tracking/ros/laser_scan.h (LaserParams)."};

int main(int argc, char** argv) {
  amigobot_tracking::ros_layer::initNode(argc, argv, "laser", kHelp);
  return amigobot_tracking::ros_layer::spinNode<amigobot_tracking::ros_layer::LaserNode>("laser_node");
}
