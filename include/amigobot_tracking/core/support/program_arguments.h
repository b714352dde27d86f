// The command line of a ROS-free tool that roslaunch may start.
#pragma once

#include <string>
#include <vector>

namespace amigobot_tracking {
namespace core {

// The arguments CLI11 parses (in its reversed order), without the remappings roslaunch
// appends (__name:=emulator, __log:=...).
inline std::vector<std::string> ownArguments(int argc, char** argv) {
  std::vector<std::string> args;
  for (int i = argc - 1; i > 0; --i) {
    if (std::string(argv[i]).find(":=") == std::string::npos) args.emplace_back(argv[i]);
  }
  return args;
}

}  // namespace core
}  // namespace amigobot_tracking
