// A node's own command line after ros::init: --help, or a refusal naming what is not understood.
#include "amigobot_tracking/ros/node_command_line.h"

#include <CLI/CLI.hpp>

namespace amigobot_tracking {
namespace ros_layer {

void initNode(int& argc, char** argv, const std::string& node_name, const NodeHelp& help, uint32_t options) {
  ros::init(argc, argv, node_name, options);
  const std::string program = argv[0];
  CLI::App app(help.about, program.substr(program.find_last_of('/') + 1));
  app.footer(std::string("Parameters (private ROS parameters, ~name): ") + help.parameters);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    std::exit(app.exit(e) == 0 ? 0 : 2);
  }
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
