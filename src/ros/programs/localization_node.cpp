// localization_node: mapping or localisation as a standalone node (same code as the nodelet).
#include <ros/ros.h>

#include "amigobot_tracking/ros/localization_node.h"
#include "amigobot_tracking/ros/node_command_line.h"

const amigobot_tracking::ros_layer::NodeHelp kHelp{
    "Localisation on a map_server map (ICP, global relocalisation) or mapping (ICP-SLAM) over MRPT; publishes "
    "tf map -> odom (the same code as the nodelet amigobot_tracking/Localization).",
    "include/amigobot_tracking/localization/localization_config.h (LocalizationConfig), config/localization.yaml."};

int main(int argc, char** argv) {
  amigobot_tracking::ros_layer::initNode(argc, argv, "localization", kHelp);
  return amigobot_tracking::ros_layer::spinNode<amigobot_tracking::ros_layer::LocalizationNode>("localization_node");
}
