// The command line of a ROS node whose settings are all ROS parameters: `--help` tells what
// the node does and where its parameters are described; anything else is refused by name.
// Call after ros::init, which removes roslaunch's remappings (__name:=, topic:=...).
#pragma once

#include <cstdlib>
#include <string>

#include <CLI/CLI.hpp>

namespace amigobot_tracking {
namespace ros_layer {

// Returns when the command line is empty; exits 0 after --help, 2 on anything else.
inline void parseNodeCommandLine(int argc, char** argv, const std::string& name, const std::string& description,
                                 const std::string& parameters) {
  CLI::App app(description, name);
  app.footer("Parameters (private ROS parameters, ~name): " + parameters);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    std::exit(app.exit(e) == 0 ? 0 : 2);
  }
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
