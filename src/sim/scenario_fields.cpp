#include "amigobot_tracking/sim/scenario_fields.h"

#include <set>

#include "amigobot_tracking/sim/scenario.h"

namespace amigobot_tracking {
namespace sim {
namespace {

using core::field;
using core::nonNegative;
using core::positive;
using Setup = sim::ClosedLoopSetup;

core::FieldTable<Setup> simulationFields() {
  core::FieldTable<Setup> t = {
      field("duration", &Setup::duration, "s", "simulated time", positive()),
      field("control_period", &Setup::control_period, "s", "controller step = the fine integration step",
            positive()),
      field("max_step", &Setup::max_step, "s", "variable step up to this; 0 = fixed step", nonNegative()),
  };
  core::include(&t, "", &Setup::step_policy,
                core::FieldTable<sim::StepPolicy>{
                    field("comfortable_ratio", &sim::StepPolicy::comfortable_ratio, "-",
                          "|e|/rho where the step starts shrinking (< tight_ratio)", nonNegative()),
                    field("tight_ratio", &sim::StepPolicy::tight_ratio, "-", "|e|/rho where only control_period is used",
                          nonNegative()),
                });
  return t;
}

core::FieldTable<Setup> targetFields() {
  core::FieldTable<Setup> t = {
      field("sample_period", &Setup::sample_period, "s", "target sampling; 0 = every control step", nonNegative()),
  };
  core::include(&t, "", &Setup::sensor,
                core::FieldTable<sim::TargetSensorConfig>{
                    field("noise_std", &sim::TargetSensorConfig::noise_std, "m", "Gaussian noise per axis",
                          nonNegative()),
                    field("delay", &sim::TargetSensorConfig::delay, "s", "transport delay", nonNegative()),
                });
  return t;
}

core::FieldTable<Setup> localizationFields() {
  core::FieldTable<Setup> t;
  core::include(&t, "", &Setup::pose_sensor,
                core::FieldTable<sim::PoseSensorConfig>{
                    field("sample_period", &sim::PoseSensorConfig::sample_period, "s",
                          "robot pose sampling; 0 = the true pose at every step", nonNegative()),
                    field("delay", &sim::PoseSensorConfig::delay, "s", "a pose taken at t arrives at t + delay",
                          nonNegative()),
                });
  return t;
}

// The baselines' own settings (read only by the proportional law and the two estimators).
core::FieldTable<Setup> baselineFields() {
  using B = sim::BaselineParams;
  core::FieldTable<Setup> t;
  core::include(&t, "", &Setup::baseline,
                core::FieldTable<B>{
                    field("k_p", &B::k_p, "1/s",
                          "gain of the proportional baseline (default: k_d / rho_inf, the paper law's "
                          "small-error stiffness)",
                          positive()),
                    field("lowpass_tau", &B::lowpass_tau, "s", "time constant of the finite-difference estimator",
                          positive()),
                    field("kalman_accel_std", &B::kalman_accel_std, "m/s^2", "process noise of the Kalman estimator",
                          positive()),
                    field("kalman_measurement_std", &B::kalman_measurement_std, "m",
                          "measurement noise of the Kalman estimator", positive()),
                });
  return t;
}

core::FieldTable<Scenario> makeTable() {
  core::FieldTable<Scenario> t;
  core::include(&t, "simulation/", &Scenario::setup, simulationFields());
  t.push_back(field("simulation/log_period", &Scenario::log_period, "s", "CSV row spacing; 0 = every step",
                    nonNegative()));
  t.push_back(field("simulation/name", &Scenario::name, "-", "run name (default: the file's stem)"));
  t.push_back(field("robot/dynamics", &Scenario::dynamics, "-",
                    "firmware: the command reaches the body through the robot's ramps, cycle, latency and wheel "
                    "limit (core/robot/actuator_model.h); ideal: at once (the paper's unicycle)",
                    core::oneOf({"firmware", "ideal"})));
  t.push_back(field("robot/description", &Scenario::robot_description, "-",
                    "robot YAML (config/robots/) whose dynamics keys the firmware base takes, relative to the "
                    "scenario file; empty = the AmigoBot's"));
  core::include(&t, "controller/", &Scenario::setup, baselineFields());
  core::include(&t, "target/", &Scenario::setup, targetFields());
  core::include(&t, "localization/", &Scenario::setup, localizationFields());
  return t;
}

}  // namespace

const core::FieldTable<Scenario>& scenarioFields() {
  static const core::FieldTable<Scenario> table = makeTable();
  return table;
}

std::string scenarioPath(const std::string& key) {
  if (key == "robot_radius") return "robot.radius";
  if (key == "offset" || key == "v_max" || key == "w_max") return "robot." + key;
  const std::string nested = "estimator/";
  return "controller." + (key.rfind(nested, 0) == 0 ? key.substr(nested.size()) : key);
}

void applyOverride(YAML::Node* tree, const std::string& file, const std::string& assignment) {
  YAML::Node& root = *tree;
  const size_t eq = assignment.find('=');
  const std::string path = assignment.substr(0, eq);
  const size_t dot = path.find('.');
  if (eq == std::string::npos || dot == std::string::npos || dot == 0 || dot + 1 == path.size())
    throw ScenarioError("--set " + assignment + ": expected section.key=value");
  const std::string section = path.substr(0, dot), key = path.substr(dot + 1);
  const std::string text = assignment.substr(eq + 1);
  // A plain value stays a scalar without a file position (messages then name no line).
  YAML::Node value(text);
  if (!text.empty() && (text[0] == '[' || text[0] == '{')) {
    try {
      value = YAML::Load(text);
    } catch (const YAML::Exception& e) {
      throw ScenarioError("--set " + path + ": not a YAML value: " + e.msg);
    }
  }
  if (root[section].IsDefined() && !root[section].IsNull() && !root[section].IsMap())
    throw ScenarioError(file + ": --set " + path + ": " + section + " is not a mapping");
  root[section][key] = value;
}

bool requiredScenarioKey(const std::string& path) {
  static const std::set<std::string> required = {
      "robot.radius",       "robot.offset",        "robot.v_max",        "robot.w_max",
      "controller.k_d",     "controller.k_o",      "controller.k_r",     "controller.lambda",
      "controller.rho_inf", "controller.rho_0",    "controller.delta",   "controller.a1",
      "controller.a2",      "controller.lambda_o", "controller.rho_o",   "controller.rho_o0",
      "controller.body_safe", "simulation.duration"};
  return required.count(path) > 0;
}

}  // namespace sim
}  // namespace amigobot_tracking
