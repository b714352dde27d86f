#include "amigobot_tracking/sim/robot_description.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "amigobot_tracking/core/input_file.h"
#include "amigobot_tracking/sim/scenario.h"

namespace amigobot_tracking {
namespace sim {
namespace {

// One key of the file: its name there, the field, the file's unit and the factor to SI.
struct DynamicsKey {
  const char* name;
  double core::ActuatorLimits::*field;
  const char* unit;
  const char* meaning;
};

const DynamicsKey kKeys[] = {
    {"max_velocity", &core::ActuatorLimits::max_velocity, "m/s", "body and wheel speed ceiling (MaxVelocity)"},
    {"max_rot_velocity", &core::ActuatorLimits::max_rot_velocity, "rad/s", "body rotation ceiling (MaxRVelocity)"},
    {"trans_accel", &core::ActuatorLimits::trans_accel, "m/s^2", "translational acceleration (TransAccel)"},
    {"trans_decel", &core::ActuatorLimits::trans_decel, "m/s^2", "translational deceleration (TransDecel)"},
    {"rot_accel", &core::ActuatorLimits::rot_accel, "rad/s^2", "rotational acceleration (RotAccel)"},
    {"rot_decel", &core::ActuatorLimits::rot_decel, "rad/s^2", "rotational deceleration (RotDecel)"},
    {"sip_cycle", &core::ActuatorLimits::cycle, "s", "firmware cycle: a command is sampled once per cycle"},
    {"latency", &core::ActuatorLimits::latency, "s", "from a command's arrival to its first effect on the wheels"},
};

double number(const YAML::Node& node, const std::string& file, const std::string& key) {
  try {
    const double v = node.as<double>();
    if (std::isnan(v)) throw YAML::Exception(node.Mark(), "NaN");
    return v;
  } catch (const YAML::Exception&) {
    throw ScenarioError(file + ":" + std::to_string(node.Mark().line + 1) + ": " + key + ": expected a number");
  }
}

}  // namespace

RobotDynamics parseRobotDynamics(const std::string& text, const std::string& file) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ScenarioError(file + ":" + std::to_string(e.mark.line + 1) + ": not valid YAML: " + e.msg);
  }
  if (!root.IsMap()) throw ScenarioError(file + ": a robot description is a mapping of keys");
  RobotDynamics d;
  d.ideal = false;
  for (const DynamicsKey& k : kKeys)
    if (root[k.name]) d.limits.*k.field = number(root[k.name], file, k.name);
  // ARIA's w = (R - L)/2 * DiffConvFactor [1/mm]: half the track is 1/DiffConvFactor mm.
  if (root["diff_conv_factor"]) d.half_track = 1e-3 / number(root["diff_conv_factor"], file, "diff_conv_factor");
  const std::string error = core::validateActuatorLimits(d.limits, d.half_track);
  if (!error.empty()) throw ScenarioError(file + ": " + error);
  return d;
}

RobotDynamics loadRobotDynamics(const std::string& path) {
  std::string text;
  try {
    text = core::readInputFile(path);
  } catch (const std::runtime_error& e) {
    throw ScenarioError(std::string(e.what()) + " (the robot description)");
  }
  return parseRobotDynamics(text, path);
}

std::string robotDynamicsYaml(const RobotDynamics& d, const std::string& origin) {
  std::ostringstream out;
  out << "# Robot dynamics " << origin << ".\n"
      << "# Only the base's dynamics; every other key of a robot description keeps the AmigoBot's value.\n"
      << "# Format per key: type, unit: meaning.\n\n" << std::setprecision(6);
  for (const DynamicsKey& k : kKeys)
    out << "# double, " << k.unit << ": " << k.meaning << ".\n" << k.name << ": " << d.limits.*k.field << "\n";
  out << "# double, 1/mm: w = (R - L)/2 * diff_conv_factor; half the wheel track is 1/diff_conv_factor mm.\n"
      << "diff_conv_factor: " << 1e-3 / d.half_track << "\n";
  return out.str();
}

}  // namespace sim
}  // namespace amigobot_tracking
