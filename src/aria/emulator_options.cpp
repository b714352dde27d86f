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
      field("ticks_mm", &E::ticks_mm, "ticks/mm", "FLASH TicksMM: the encoders' true ticks per mm", core::atLeast(1)),
      field("rev_count", &E::rev_count, "ticks/180deg", "FLASH RevCount: the encoders' ticks per half turn",
            core::atLeast(1)),
      field("left_open_at_baud", &E::left_open_at_baud, "baud",
            "> 0: start open at this baud, as a crashed session leaves it; 0: closed at 9600", core::atLeast(0)),
  };
  return table;
}

std::string EmulatorOptions::validate() const {
  const std::string bad = core::checkFields(emulatorFields(), *this);
  if (!bad.empty()) return bad;
  const std::string robot_error = robot.validate();
  if (!robot_error.empty()) return "robot." + robot_error;
  if (!initial_pose.isFinite()) return "initial_pose: must be finite";
  const std::string world_error = world::validateWorld(world);
  if (!world_error.empty()) return "world." + world_error;
  if (name.empty() || name.size() > 60) return "name: must be 1..60 characters";
  return {};
}

}  // namespace aria
}  // namespace amigobot_tracking
