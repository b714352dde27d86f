#include "amigobot_tracking/core/robot/robot_description.h"

namespace amigobot_tracking {
namespace core {
namespace {

FieldTable<ActuatorLimits> makeActuatorRows() {
  using A = ActuatorLimits;
  return {
      field("max_velocity", &A::max_velocity, "m/s",
            "the base's speed ceiling, for the body and each wheel (MaxVelocity)", positive()),
      field("max_rot_velocity", &A::max_rot_velocity, "rad/s",
            "the base's turn-rate ceiling (MaxRVelocity; the default is 300 deg/s)", positive()),
      field("trans_accel", &A::trans_accel, "m/s^2",
            "firmware ramp while the speed grows (TransAccel; the default is MobileSim's amigo model)", positive()),
      field("trans_decel", &A::trans_decel, "m/s^2",
            "firmware ramp while the speed shrinks (TransDecel; the default is MobileSim's amigo model)", positive()),
      field("rot_accel", &A::rot_accel, "rad/s^2",
            "firmware ramp while the turn rate grows in magnitude (RotAccel; the default is ARIA's 100 deg/s^2 "
            "without a CONFIGpac)",
            positive()),
      field("rot_decel", &A::rot_decel, "rad/s^2",
            "firmware ramp while the turn rate shrinks in magnitude (RotDecel)", positive()),
      field("sip_cycle", &A::cycle, "s",
            "firmware cycle: one SIP, and one command sample, per cycle (the driver's diagnostics warn below half "
            "this SIP rate)",
            duration()),
      field("latency", &A::latency, "s",
            "from a command's arrival to its first effect on the wheels (a command takes effect a cycle later)",
            durationOrZero()),
  };
}

FieldTable<RobotDescription> makeRows() {
  using R = RobotDescription;
  FieldTable<R> t = {
      field("robot_radius", &R::robot_radius, "m", "body radius (ARIA RobotRadius)", boundedRadius()),
      field("robot_width", &R::robot_width, "m", "body width (RobotWidth)", boundedRadius()),
      field("robot_length", &R::robot_length, "m", "body length (RobotLength: front 160 + rear 170 mm)",
            boundedRadius()),
  };
  include(&t, "", &R::dynamics, actuatorLimitsFields());
  t.push_back(field("v_max", &R::v_max, "m/s",
                    "half-width in v of the diamond abs(v)/v_max + abs(omega)/w_max <= 1 the driver holds every "
                    "command to, <= max_velocity; tracking's and teleop's limits default to it and may only be "
                    "smaller, a driver's ~v_max may tighten it. The robot file is its one home",
                    positive()));
  t.push_back(field("w_max", &R::w_max, "rad/s",
                    "half-width in omega of the diamond the driver holds every command to, <= max_rot_velocity; "
                    "tracking's and teleop's limits default to it and may only be smaller, a driver's ~w_max may "
                    "tighten it",
                    positive()));
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
