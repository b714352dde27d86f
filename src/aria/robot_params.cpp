#include "amigobot_tracking/aria/robot_params.h"

#include <cmath>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/core/input_file.h"

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr double kDeg = M_PI / 180.0;

SonarPose sonarDeg(double x_mm, double y_mm, double heading_deg) {
  return {x_mm * 1e-3, y_mm * 1e-3, heading_deg * kDeg};
}

bool positiveFinite(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

std::string RobotParams::validate() const {
  const std::pair<const char*, double> positive[] = {
      {"robot_radius", robot_radius},     {"robot_width", robot_width},
      {"robot_length", robot_length},     {"angle_conv_factor", angle_conv_factor},
      {"dist_conv_factor", dist_conv_factor}, {"vel_conv_factor", vel_conv_factor},
      {"range_conv_factor", range_conv_factor}, {"diff_conv_factor", diff_conv_factor},
      {"vel2_divisor", vel2_divisor},     {"max_velocity", max_velocity},
      {"max_rot_velocity", max_rot_velocity}, {"trans_accel", trans_accel},
      {"trans_decel", trans_decel},       {"rot_accel", rot_accel},
      {"rot_decel", rot_decel},           {"sip_cycle", sip_cycle},
      {"watchdog", watchdog},             {"sonar_max_range", sonar_max_range}};
  for (const auto& [name, value] : positive) {
    if (!positiveFinite(value)) return std::string(name) + ": must be positive and finite, got " + std::to_string(value);
  }
  if (model.empty()) return "model: must not be empty";
  if (angle_units_per_turn < 8) return "angle_units_per_turn: must be at least 8, got " + std::to_string(angle_units_per_turn);
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
  auto get = [&](const char* key, auto& field) {
    const YAML::Node node = root[key];
    if (!node) return;
    try {
      field = node.as<std::decay_t<decltype(field)>>();
    } catch (const YAML::Exception& e) {
      throw std::runtime_error(path + ":" + std::to_string(node.Mark().line + 1) + ": " + key + ": bad value (" +
                               e.msg + ")");
    }
  };
  get("model", p.model);
  get("robot_radius", p.robot_radius);
  get("robot_width", p.robot_width);
  get("robot_length", p.robot_length);
  get("angle_conv_factor", p.angle_conv_factor);
  get("angle_units_per_turn", p.angle_units_per_turn);
  get("dist_conv_factor", p.dist_conv_factor);
  get("vel_conv_factor", p.vel_conv_factor);
  get("range_conv_factor", p.range_conv_factor);
  get("diff_conv_factor", p.diff_conv_factor);
  get("vel2_divisor", p.vel2_divisor);
  get("max_velocity", p.max_velocity);
  get("max_rot_velocity", p.max_rot_velocity);
  get("trans_accel", p.trans_accel);
  get("trans_decel", p.trans_decel);
  get("rot_accel", p.rot_accel);
  get("rot_decel", p.rot_decel);
  get("sip_cycle", p.sip_cycle);
  get("watchdog", p.watchdog);
  get("switch_to_baud", p.switch_to_baud);
  get("sonar_max_range", p.sonar_max_range);
  get("sonar_polling", p.sonar_polling);
  if (const YAML::Node sonars = root["sonars"]) {
    if (!sonars.IsSequence()) throw std::runtime_error(path + ": sonars: expected a list of {x, y, heading_deg}");
    p.sonars.clear();
    for (std::size_t i = 0; i < sonars.size(); ++i) {
      const YAML::Node s = sonars[i];
      try {
        p.sonars.push_back({s["x"].as<double>(), s["y"].as<double>(), s["heading_deg"].as<double>() * kDeg});
      } catch (const YAML::Exception& e) {
        throw std::runtime_error(path + ":" + std::to_string(s.Mark().line + 1) + ": sonars[" + std::to_string(i) +
                                 "]: expected x, y [m] and heading_deg (" + e.msg + ")");
      }
    }
  }
  for (auto it = root.begin(); it != root.end(); ++it) {
    static const char* known[] = {"model", "robot_radius", "robot_width", "robot_length", "angle_conv_factor",
                                  "angle_units_per_turn", "dist_conv_factor", "vel_conv_factor",
                                  "range_conv_factor", "diff_conv_factor", "vel2_divisor", "max_velocity",
                                  "max_rot_velocity", "trans_accel", "trans_decel", "rot_accel", "rot_decel",
                                  "sip_cycle", "watchdog", "switch_to_baud", "sonars", "sonar_max_range",
                                  "sonar_polling"};
    if (!it->first.IsScalar())
      throw std::runtime_error(path + ":" + std::to_string(it->first.Mark().line + 1) + ": a key must be a word, not a list or mapping");
    const std::string key = it->first.Scalar();
    bool found = false;
    for (const char* k : known) found = found || key == k;
    if (!found) throw std::runtime_error(path + ":" + std::to_string(it->first.Mark().line + 1) + ": unknown key '" + key + "'");
  }
  const std::string error = p.validate();
  if (!error.empty()) throw std::runtime_error(path + ": " + error);
  return p;
}

}  // namespace aria
}  // namespace amigobot_tracking
