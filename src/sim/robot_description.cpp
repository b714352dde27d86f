#include "amigobot_tracking/sim/robot_description.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "amigobot_tracking/core/support/input_file.h"
#include "amigobot_tracking/core/robot/robot_description.h"
#include "amigobot_tracking/sim/scenario.h"
#include "amigobot_tracking/sim/yaml_section.h"

namespace amigobot_tracking {
namespace sim {
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
  for (const core::Field<core::ActuatorLimits>& f : core::actuatorLimitsFields())
    if (root[f.key]) f.set(d.limits, readNumber(file, root[f.key], f.key, true));
  // ARIA's w = (R - L)/2 * DiffConvFactor [1/mm]: half the track is 1/DiffConvFactor mm.
  if (root["diff_conv_factor"]) d.half_track = 1e-3 / readNumber(file, root["diff_conv_factor"], "diff_conv_factor", true);
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
  for (const core::Field<core::ActuatorLimits>& f : core::actuatorLimitsFields())
    out << "# double, " << f.unit << ": " << f.meaning << ".\n" << f.key << ": " << core::formatValue(f.get(d.limits))
        << "\n";
  out << "# double, 1/mm: w = (R - L)/2 * diff_conv_factor; half the wheel track is 1/diff_conv_factor mm.\n"
      << "diff_conv_factor: " << 1e-3 / d.half_track << "\n";
  return out.str();
}

}  // namespace sim
}  // namespace amigobot_tracking
