// The robot description: what every reader of the robot (driver, tracking, teleop, the
// emulator, the offline simulator) needs to know about the base, in SI, without ROS or MRPT.
// Its one home is the robot parameter file config/robots/<model>.yaml; the keys there are
// flat ("trans_accel", "v_max") and are the rows of robotDescriptionFields(), which drives the
// loader (aria/robot_params.h adds the ARIA conversion factors and the sonar table), the
// validation and the docs' row list. Defaults: the AmigoBot.
#pragma once

#include <string>

#include "amigobot_tracking/core/robot/actuator_limits.h"
#include "amigobot_tracking/core/support/field_table.h"

namespace amigobot_tracking {
namespace core {

struct RobotDescription {
  // Geometry.
  double robot_radius = 0.18;  // [m] body radius (ARIA RobotRadius)
  double robot_width = 0.279;  // [m] (RobotWidth)
  double robot_length = 0.33;  // [m] (RobotLength)
  // What the base does to a command: ramps, cycle, latency and its own speed ceiling.
  ActuatorLimits dynamics;
  // The operating diamond {|v|/v_max + |w|/w_max <= 1} the driver enforces on every command;
  // inside the ceiling. Tracking's and teleop's own limits may be smaller, never larger.
  double v_max = 0.3;  // [m/s]
  double w_max = 0.8;  // [rad/s]

  // "" or "key: reason" for the first bad row, then the diamond outside the ceiling.
  std::string validate() const;
};

// The base's rows (a robot file's keys: "sip_cycle" is ActuatorLimits::cycle): the one
// description of these keys, read by the driver's robot file and the simulator alike.
const FieldTable<ActuatorLimits>& actuatorLimitsFields();
// The rows, keys as in the robot file ("sip_cycle" is dynamics.cycle).
const FieldTable<RobotDescription>& robotDescriptionFields();

// "" when (v_max, w_max) lies inside the robot's diamond, else "<v_key>: must be <= the
// robot's v_max 0.3 m/s (<where>), got 0.5" (w likewise). `where` names the robot file.
// The one rule for every reader whose own limit may tighten the robot's, never widen it.
std::string diamondInsideError(const RobotDescription& robot, double v_max, double w_max, const std::string& v_key,
                               const std::string& w_key, const std::string& where);

}  // namespace core
}  // namespace amigobot_tracking
