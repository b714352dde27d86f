#include "amigobot_tracking/core/robot/robot_description.h"

namespace amigobot_tracking {
namespace core {
namespace {

FieldTable<ActuatorLimits> makeActuatorRows() {
  using A = ActuatorLimits;
  return {
      field("max_velocity", &A::max_velocity, "m/s", "the base's speed ceiling, body and each wheel (MaxVelocity)",
            positive()),
      field("max_rot_velocity", &A::max_rot_velocity, "rad/s", "the base's turn-rate ceiling (MaxRVelocity)",
            positive()),
      field("trans_accel", &A::trans_accel, "m/s^2", "firmware ramp while |v| grows (TransAccel)", positive()),
      field("trans_decel", &A::trans_decel, "m/s^2", "firmware ramp while |v| shrinks (TransDecel)", positive()),
      field("rot_accel", &A::rot_accel, "rad/s^2", "firmware ramp while |omega| grows (RotAccel)", positive()),
      field("rot_decel", &A::rot_decel, "rad/s^2", "firmware ramp while |omega| shrinks (RotDecel)", positive()),
      field("sip_cycle", &A::cycle, "s", "firmware cycle: one SIP, and one command sample, per cycle", duration()),
      field("latency", &A::latency, "s", "from a command's arrival to its first effect on the wheels",
            durationOrZero()),
  };
}

FieldTable<RobotDescription> makeRows() {
  using R = RobotDescription;
  FieldTable<R> t = {
      field("robot_radius", &R::robot_radius, "m", "body radius (RobotRadius)", boundedRadius()),
      field("robot_width", &R::robot_width, "m", "body width (RobotWidth)", boundedRadius()),
      field("robot_length", &R::robot_length, "m", "body length (RobotLength)", boundedRadius()),
  };
  include(&t, "", &R::dynamics, actuatorLimitsFields());
  t.push_back(field("v_max", &R::v_max, "m/s", "the driver's diamond half-width in v (<= max_velocity)", positive()));
  t.push_back(
      field("w_max", &R::w_max, "rad/s", "the driver's diamond half-width in omega (<= max_rot_velocity)", positive()));
  return t;
}

}  // namespace

const FieldTable<ActuatorLimits>& actuatorLimitsFields() {
  static const FieldTable<ActuatorLimits> table = makeActuatorRows();
  return table;
}

const FieldTable<RobotDescription>& robotDescriptionFields() {
  static const FieldTable<RobotDescription> table = makeRows();
  return table;
}

std::string diamondInsideError(const RobotDescription& robot, double v_max, double w_max, const std::string& v_key,
                               const std::string& w_key, const std::string& where) {
  const auto outside = [&](const std::string& key, double value, double limit, const char* name, const char* unit) {
    return key + ": must be <= the robot's " + name + " " + formatValue(limit) + " " + unit + " (" + where +
           "), got " + formatValue(value);
  };
  if (v_max > robot.v_max) return outside(v_key, v_max, robot.v_max, "v_max", "m/s");
  if (w_max > robot.w_max) return outside(w_key, w_max, robot.w_max, "w_max", "rad/s");
  return "";
}

std::string RobotDescription::validate() const {
  const std::string bad = checkFields(robotDescriptionFields(), *this);
  if (!bad.empty()) return bad;
  if (v_max > dynamics.max_velocity)
    return "v_max: must be <= max_velocity " + formatValue(dynamics.max_velocity) + " m/s, got " + formatValue(v_max);
  if (w_max > dynamics.max_rot_velocity)
    return "w_max: must be <= max_rot_velocity " + formatValue(dynamics.max_rot_velocity) + " rad/s, got " +
           formatValue(w_max);
  return "";
}

}  // namespace core
}  // namespace amigobot_tracking
