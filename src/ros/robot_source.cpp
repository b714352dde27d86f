#include "amigobot_tracking/ros/robot_source.h"

#include <stdexcept>

namespace amigobot_tracking {
namespace ros_layer {

const core::FieldTable<RobotSource>& robotSourceFields() {
  using S = RobotSource;
  using core::field;
  static const core::FieldTable<S> table = {
      field("robot_model", &S::robot_model, "-",
            "built-in robot description, amigo (AmigOS) or amigo-sh (AmigoSH), used when robot_params is empty",
            core::oneOf({"amigo", "amigo-sh"})),
      field("robot_params", &S::robot_params, "-",
            "robot file (config/robots/<model>.yaml), the robot description: diamond, speed ceiling, ramps, "
            "geometry, conversion factors, sonar poses; overrides robot_model when set. The driver, tracking and "
            "keyboard_teleop read the same two parameters, and the launch files give them the same file"),
  };
  return table;
}

aria::RobotParams loadRobot(const RobotSource& source) {
  try {
    return source.robot_params.empty() ? aria::builtinRobotParams(source.robot_model)
                                       : aria::loadRobotParams(source.robot_params);
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("~robot_model/~robot_params: ") + e.what());
  }
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
