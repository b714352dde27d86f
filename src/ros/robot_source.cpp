#include "amigobot_tracking/ros/robot_source.h"

#include <stdexcept>

namespace amigobot_tracking {
namespace ros_layer {

const core::FieldTable<RobotSource>& robotSourceFields() {
  using S = RobotSource;
  using core::field;
  static const core::FieldTable<S> table = {
      field("robot_model", &S::robot_model, "-", "built-in robot description", core::oneOf({"amigo", "amigo-sh"})),
      field("robot_params", &S::robot_params, "-", "robot file (config/robots/): its diamond, ceiling, ramps; overrides robot_model"),
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
