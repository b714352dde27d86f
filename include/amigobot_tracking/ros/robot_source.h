// How a node gets the robot description: the same two private parameters on every node that
// needs it (driver, tracking, keyboard_teleop): ~robot_params, the robot file
// (config/robots/<model>.yaml), or else ~robot_model, a built-in set. The launch files give
// every node the same file; the numbers live in that file only.
#pragma once

#include <string>

#include "amigobot_tracking/aria/robot_params.h"
#include "amigobot_tracking/core/support/field_table.h"

namespace amigobot_tracking {
namespace ros_layer {

struct RobotSource {
  std::string robot_model = "amigo";  // built-in robot description: amigo | amigo-sh
  std::string robot_params;           // robot file (config/robots/); overrides robot_model
};

const core::FieldTable<RobotSource>& robotSourceFields();

// The description the source names; throws std::runtime_error("~robot_model/~robot_params: ...").
aria::RobotParams loadRobot(const RobotSource& source);

}  // namespace ros_layer
}  // namespace amigobot_tracking
