#include <cmath>

#include "amigobot_tracking/aria/emulator.h"

namespace amigobot_tracking {
namespace aria {

const core::FieldTable<EmulatorOptions>& emulatorFields() {
  using E = EmulatorOptions;
  using core::field;
  static const core::FieldTable<E> table = {
      field("name", &E::name, "-", "SYNC2 name (1..60 characters)"),
      field("simulator_mode", &E::simulator_mode, "-",
            "motors start enabled, SIPs always 0x32, watchdog only warns, disconnect closes"),
      field("odometry_noise", &E::odometry_noise, "-", "relative std-dev of the wheel speeds the firmware integrates",
            core::nonNegative()),
      field("battery_voltage", &E::battery_voltage, "V", "reported battery voltage", core::nonNegative()),
      field("sonar_max_range", &E::sonar_max_range, "m", "reported when nothing is in the cone", core::positive()),
      field("sonar_half_cone", &E::sonar_half_cone, "rad", "half opening angle of a transducer's cone",
            core::positive()),
      field("physics_step", &E::physics_step, "s", "kinematics step", core::interval(0.0, true, 0.05, false)),
  };
  return table;
}

std::string EmulatorOptions::validate() const {
  const std::string bad = core::checkFields(emulatorFields(), *this);
  if (!bad.empty()) return bad;
  const std::string robot_error = robot.validate();
  if (!robot_error.empty()) return "robot." + robot_error;
  if (!initial_pose.isFinite()) return "initial_pose: must be finite";
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    if (!(obstacles[i].radius > 0.0) || !obstacles[i].center.allFinite()) {
      return "obstacles[" + std::to_string(i) + "]: needs a finite centre and a positive radius";
    }
  }
  if (name.empty() || name.size() > 60) return "name: must be 1..60 characters";
  return {};
}

}  // namespace aria
}  // namespace amigobot_tracking
