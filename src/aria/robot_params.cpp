#include "amigobot_tracking/aria/robot_params.h"

#include <cmath>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/core/support/input_file.h"

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr double kDeg = M_PI / 180.0;

SonarPose sonarDeg(double x_mm, double y_mm, double heading_deg) {
  return {x_mm * 1e-3, y_mm * 1e-3, heading_deg * kDeg};
}

[[noreturn]] void fail(const std::string& path, const YAML::Node& at, const std::string& what) {
  throw std::runtime_error(path + ":" + std::to_string(at.Mark().line + 1) + ": " + what);
}

core::FieldTable<RobotParams> makeRows() {
  using P = RobotParams;
  using core::field;
  using core::positive;
  core::FieldTable<P> t = {field("model", &P::model, "-",
                                 "SYNC2 subclass this set belongs to (ARIA lower-cases it); a robot that reports "
                                 "another subclass is named in a WARN at connection")};
  core::includeBase(&t, core::robotDescriptionFields());
  const core::FieldTable<P> aria = {
      field("angle_conv_factor", &P::angle_conv_factor, "rad/unit",
            "THPOS scale, 2*pi/4096 (AngleConvFactor); the .p files round it to 0.00153, the AmigoSH manual's table "
            "says degrees (0.0174533 with angle_units_per_turn 360), unverified",
            positive()),
      field("angle_units_per_turn", &P::angle_units_per_turn, "units",
            "THPOS wraps modulo this many units per turn (360 for the AmigoSH manual's degree reading)",
            core::atLeast(8)),
      field("dist_conv_factor", &P::dist_conv_factor, "mm/unit", "XPOS/YPOS scale (DistConvFactor)", positive()),
      field("vel_conv_factor", &P::vel_conv_factor, "(mm/s)/unit",
            "L/R VEL scale (VelConvFactor); p2os lists 1.3746 for amigo-sh", positive()),
      field("range_conv_factor", &P::range_conv_factor, "mm/unit",
            "sonar range scale (RangeConvFactor); the AmigOS v1.3 manual says 0.555", positive()),
      field("diff_conv_factor", &P::diff_conv_factor, "1/mm",
            "omega = (R - L)/2 * DiffConvFactor: the wheel track is 2/diff_conv_factor mm (182 mm for 0.011)",
            positive()),
      field("vel2_divisor", &P::vel2_divisor, "(mm/s)/unit", "VEL2's wheel-speed unit (Vel2Divisor)", positive()),
      field("watchdog", &P::watchdog, "s",
            "firmware watchdog: the robot stops after this long without a command; the driver's command_refresh "
            "must stay below it",
            core::duration()),
      field("switch_to_baud", &P::switch_to_baud, "baud",
            "SwitchToBaudRate, a HOSTBAUD rate (9600, 19200, 38400, 57600, 115200): after CONFIG the driver moves a "
            "serial link to it when it is above the connect baud and the robot allows it (ARIA's serial default is "
            "9600)",
            core::atLeast(1)),
      field("sonar_max_range", &P::sonar_max_range, "m",
            "farthest echo a transducer reports (amigo.p: 4335 mm); the max_range of sonar_range, where an echo this "
            "far or none is +inf",
            core::boundedRadius()),
  };
  t.insert(t.end(), aria.begin(), aria.end());
  return t;
}

std::vector<SonarPose> readSonars(const std::string& path, const YAML::Node& list) {
  if (!list.IsSequence()) fail(path, list, "sonars: expected a list of {x, y, heading_deg}");
  std::vector<SonarPose> sonars;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YAML::Node s = list[i];
    try {
      sonars.push_back({s["x"].as<double>(), s["y"].as<double>(), s["heading_deg"].as<double>() * kDeg});
    } catch (const YAML::Exception& e) {
      fail(path, s, "sonars[" + std::to_string(i) + "]: expected x, y [m] and heading_deg (" + e.msg + ")");
    }
  }
  return sonars;
}

// One scalar row: the text parsed as the row's type, then its bounds.
void readRow(const std::string& path, const core::Field<RobotParams>& row, const YAML::Node& node, RobotParams* p) {
  core::FieldValue value;
  if (!node.IsScalar() || !core::parseValue(row.type, node.Scalar(), &value))
    fail(path, node, row.key + ": expected " + core::typeName(row.type) +
                         (node.IsScalar()  ? ", got '" + node.Scalar() + "'"
                          : node.IsNull() ? ", got nothing"
                                          : ", got a list or mapping"));
  const std::string why = core::checkValue(row.type, row.bounds, value);
  if (!why.empty()) fail(path, node, row.key + ": " + why);
  row.set(*p, value);
}

}  // namespace

const core::FieldTable<RobotParams>& robotParamsFields() {
  static const core::FieldTable<RobotParams> table = makeRows();
  return table;
}

const std::vector<std::string>& robotParamsListKeys() {
  static const std::vector<std::string> keys = {"sonars", "sonar_polling"};
  return keys;
}

std::string RobotParams::validate() const {
  const std::string bad = core::checkFields(robotParamsFields(), *this);
  if (!bad.empty()) return bad;
  const std::string description = RobotDescription::validate();
  if (!description.empty()) return description;
  if (model.empty()) return "model: must not be empty";
  if (hostBaudIndex(switch_to_baud) < 0) {
    return "switch_to_baud: must be a HOSTBAUD rate (9600, 19200, 38400, 57600, 115200), got " +
           std::to_string(switch_to_baud);
  }
  for (std::size_t i = 0; i < sonars.size(); ++i) {
    const auto& s = sonars[i];
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.yaw)) {
      return "sonars[" + std::to_string(i) + "]: non-finite pose";
    }
  }
  for (std::size_t i = 0; i < sonar_polling.size(); ++i) {
    if (sonar_polling[i] < 0 || static_cast<std::size_t>(sonar_polling[i]) >= sonars.size()) {
      return "sonar_polling[" + std::to_string(i) + "]: transducer " + std::to_string(sonar_polling[i]) +
             " does not exist (0.." + std::to_string(static_cast<int>(sonars.size()) - 1) + ")";
    }
  }
  return {};
}

std::string RobotParams::origin() const {
  return file.empty() ? "built-in " + model + " set, config/robots/" + model + ".yaml" : file;
}

RobotParams RobotParams::amigo() {
  RobotParams p;
  p.sonars = {sonarDeg(76, 100, 90),    sonarDeg(125, 75, 41),    sonarDeg(150, 30, 15),
              sonarDeg(150, -30, -15),  sonarDeg(125, -75, -41),  sonarDeg(76, -100, -90),
              sonarDeg(-140, -58, -145), sonarDeg(-140, 58, 145)};
  return p;
}

RobotParams RobotParams::amigoSh() {
  RobotParams p = amigo();
  p.model = "amigo-sh";
  p.dist_conv_factor = 1.0;
  p.vel_conv_factor = 1.0;
  p.sonars = {sonarDeg(70, 100, 90),    sonarDeg(125, 75, 41),    sonarDeg(144, 30, 15),
              sonarDeg(144, -30, -15),  sonarDeg(120, -75, -41),  sonarDeg(70, -100, -90),
              sonarDeg(-146, -58, -145), sonarDeg(-146, 58, 145)};
  return p;
}

RobotParams builtinRobotParams(const std::string& model) {
  if (model == "amigo") return RobotParams::amigo();
  if (model == "amigo-sh") return RobotParams::amigoSh();
  throw std::invalid_argument("robot model '" + model + "': unknown (expected amigo or amigo-sh)");
}

RobotParams loadRobotParams(const std::string& path) {
  YAML::Node root;
  const std::string text = core::readInputFile(path);
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(path + ":" + std::to_string(e.mark.line + 1) + ": cannot read robot parameters: " + e.msg);
  }
  if (const auto big = core::yamlSizeProblem(root))
    throw std::runtime_error(path + ":" + std::to_string(big->node.Mark().line + 1) + ": " + big->reason);
  if (!root.IsMap()) throw std::runtime_error(path + ": expected a map of robot parameters");
  RobotParams p = RobotParams::amigo();
  std::vector<std::string> known = robotParamsListKeys();
  for (const auto& row : robotParamsFields()) known.push_back(row.key);
  for (auto it = root.begin(); it != root.end(); ++it) {
    if (!it->first.IsScalar()) fail(path, it->first, "a key must be a word, not a list or mapping");
    const std::string key = it->first.Scalar();
    const YAML::Node value = it->second;
    if (const core::Field<RobotParams>* row = core::findField(robotParamsFields(), key)) {
      readRow(path, *row, value, &p);
    } else if (key == "sonars") {
      p.sonars = readSonars(path, value);
    } else if (key == "sonar_polling") {
      try {
        p.sonar_polling = value.as<std::vector<int>>();
      } catch (const YAML::Exception& e) {
        fail(path, value, "sonar_polling: expected a list of transducer numbers (" + e.msg + ")");
      }
    } else {
      const std::string nearest = core::unknownKeys({key}, known).front().nearest;
      fail(path, it->first, "unknown key '" + key + "'" + (nearest.empty() ? "" : " (nearest: " + nearest + ")"));
    }
  }
  p.file = path;
  const std::string error = p.validate();
  if (!error.empty()) throw std::runtime_error(path + ": " + error);
  return p;
}

}  // namespace aria
}  // namespace amigobot_tracking
