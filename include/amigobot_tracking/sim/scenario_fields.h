// Where the field tables' rows live in a scenario file: the controller's rows in robot and
// controller, the scenario's own rows (simulation, target, localization) in the table below.
// The reference, obstacles, jumps, seed and the enumerations are read by scenario.cpp.
#pragma once

#include <string>

#include <yaml-cpp/yaml.h>

#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/sim/scenario.h"

namespace amigobot_tracking {
namespace sim {

// "simulation/duration", "target/delay", "localization/sample_period", ...
const core::FieldTable<Scenario>& scenarioFields();

// The scenario path of a controller row: "robot.radius" for robot_radius, "robot.v_max",
// "controller.a1" for estimator/a1 (the estimator's rows sit flat in controller, whose key
// `estimator` names the target velocity source), "controller.k_d".
std::string scenarioPath(const std::string& controller_key);

// `section.key=value` (amigobot_sim --set) on a scenario's YAML tree: the value is read as
// YAML (a number, a word, a list); the parser then checks it like a value in the file.
// Throws ScenarioError on a malformed assignment.
void applyOverride(YAML::Node* root, const std::string& file, const std::string& assignment);

// Keys every scenario must give ("controller.k_d"): the paper's Table 1 and the duration.
bool requiredScenarioKey(const std::string& path);

}  // namespace sim
}  // namespace amigobot_tracking
