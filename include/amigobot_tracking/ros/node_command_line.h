// The start of a ROS node whose settings are all ROS parameters: ros::init (which removes
// roslaunch's remappings: __name:=, topic:=...), then the node's own command line, where
// `--help` tells what the node does and where its parameters are described and anything
// else is refused by name.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>

#include <ros/console.h>
#include <ros/init.h>
#include <ros/node_handle.h>

namespace amigobot_tracking {
namespace ros_layer {

struct NodeHelp {
  const char* about;       // what the node does
  const char* parameters;  // its private parameters, or where they are described
};

// Returns when the command line is empty; exits 0 after --help, 2 on anything else.
// `options`: ros::init_options (NoSigintHandler for a node that stops the robot itself).
// Compiled once (node_command_line.cpp): CLI11 is header-only, and its parser inlined into
// each node's main cost ~8 CPU-s of a node's ~20 at -O3.
void initNode(int& argc, char** argv, const std::string& node_name, const NodeHelp& help, uint32_t options = 0);

// A program's parameter loader returned `error` ("" when all is well): on an error it is
// logged as FATAL under the program's name, and main() should return 1.
inline bool configLoaded(const std::string& program, const std::string& error) {
  if (error.empty()) return true;
  ROS_FATAL_STREAM(program << ": " << error);
  return false;
}

// The main of a node whose constructor wires everything (and throws on a configuration
// error): builds Node(nh, ~) and spins; 1 after ROS_FATAL naming the program on an error.
// roscpp is shut down before returning. Left to roscpp's atexit handler (a node handle
// outlived the half-built node), its poll thread still accepted connections (rosout
// subscribing) while exit() destroyed rosconsole's statics: logging through a destroyed
// mutex threw boost::lock_error, SIGABRT, in 2-3 of 20 runs after the FATAL.
template <class Node>
int spinNode(const std::string& program) {
  int status = 0;
  {
    ros::NodeHandle nh, pnh("~");
    try {
      Node node(nh, pnh);
      ros::spin();
    } catch (const std::exception& e) {
      ROS_FATAL_STREAM(program << ": " << e.what());
      status = 1;
    }
  }
  ros::shutdown();
  return status;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
