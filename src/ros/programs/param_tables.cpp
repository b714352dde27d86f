// param_tables: prints the field tables of the nodes' parameter sets as JSON, the one input of
// scripts/tools/param_docs.py, which writes the YAML comments of config/, the parameter tables
// of docs/ and the .cfg files from them (`make docs`; `make test` fails when one is stale). Each
// set is named as the generated files name it: tracking (the nodelet's own rows, the
// controller's, scan/ and obstacle_tracker/), driver, laser, localization, keyboard_teleop,
// joystick_teleop and robot (a robot file).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "amigobot_tracking/aria/robot_params.h"
#include "amigobot_tracking/core/law/controller_config.h"
#include "amigobot_tracking/core/perception/obstacle_tracker.h"
#include "amigobot_tracking/core/perception/scan_obstacles.h"
#include "amigobot_tracking/localization/localization_config.h"
#include "amigobot_tracking/ros/driver.h"
#include "amigobot_tracking/ros/laser_scan.h"
#include "amigobot_tracking/ros/robot_source.h"
#include "amigobot_tracking/ros/tracking_params.h"
#include "amigobot_tracking/teleop/joystick.h"
#include "amigobot_tracking/teleop/keyboard.h"

using namespace amigobot_tracking;
using nlohmann::json;

namespace {

const char* typeWord(core::FieldType type) {
  switch (type) {
    case core::FieldType::kReal: return "double";
    case core::FieldType::kInteger: return "int";
    case core::FieldType::kBoolean: return "bool";
    case core::FieldType::kText: return "string";
  }
  return "?";
}

// The default as a reader of the YAML writes it: a text quoted ("map", ""), a number as short
// as it is exact.
std::string defaultWord(const core::FieldValue& value) {
  if (const auto* text = std::get_if<std::string>(&value)) return "\"" + *text + "\"";
  if (const auto* real = std::get_if<double>(&value)) {
    if (!std::isfinite(*real)) return core::formatValue(value);
    // The fewest significant digits that read back exactly, without an exponent where a
    // reader would not write one (20, not 2e+01).
    char buffer[64];
    for (int digits = 1; digits <= 17; ++digits) {
      std::snprintf(buffer, sizeof buffer, "%.*g", digits, *real);
      if (std::strtod(buffer, nullptr) != *real) continue;
      const double magnitude = std::fabs(*real);
      if (std::strchr(buffer, 'e') && magnitude >= 1e-4 && magnitude < 1e15) {
        const int decimals = std::max(0, digits - 1 - static_cast<int>(std::floor(std::log10(magnitude))));
        std::snprintf(buffer, sizeof buffer, "%.*f", decimals, *real);
      }
      break;
    }
    return buffer;
  }
  return core::formatValue(value);
}

// `home`: the YAML file of config/ where a row that no file of its set names gets its line.
template <class C>
void addRows(json* rows, const std::string& prefix, const core::FieldTable<C>& table, const std::string& home) {
  for (const core::Field<C>& f : table) {
    json row = {{"key", prefix + f.key},
                {"home", home},
                {"type", typeWord(f.type)},
                {"unit", f.unit},
                {"default", f.default_text.empty() ? defaultWord(core::defaultValue(f)) : f.default_text},
                {"described", !f.default_text.empty()},  // the default in words: no value to write
                {"meaning", f.meaning},
                {"bounds", core::describeBounds(f.type, f.bounds)},
                {"live", f.live}};
    if (f.live) row["range"] = {f.reconfigure_min, f.reconfigure_max};
    if (f.live && f.type == core::FieldType::kReal) row["default_value"] = std::get<double>(core::defaultValue(f));
    rows->push_back(std::move(row));
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) {
    std::cerr << "usage: param_tables (prints every parameter set's field table as JSON; no options)\n";
    return std::string(argv[1]) == "--help" ? 0 : 2;
  }
  json sets = json::object();
  json& tracking = sets["tracking"] = json::array();
  addRows(&tracking, "", ros_layer::trackingNodeFields(), "config/tracking.yaml");
  addRows(&tracking, "", core::controllerFields(), "config/controller_experiment.yaml");  // the built-in defaults
  addRows(&tracking, "scan/", core::scanObstacleFields(), "config/tracking.yaml");
  addRows(&tracking, "obstacle_tracker/", core::obstacleTrackerFields(), "config/tracking.yaml");
  addRows(&(sets["driver"] = json::array()), "", ros_layer::driverFields(), "config/driver.yaml");
  addRows(&(sets["laser"] = json::array()), "", ros_layer::laserFields(), "config/laser.yaml");
  addRows(&(sets["localization"] = json::array()), "", localization::localizationFields(), "config/localization.yaml");
  json& keyboard = sets["keyboard_teleop"] = json::array();
  addRows(&keyboard, "", teleop::keyboardFields(), "config/teleop.yaml");
  addRows(&keyboard, "", ros_layer::robotSourceFields(), "config/teleop.yaml");  // read by the program beside its table
  addRows(&(sets["joystick_teleop"] = json::array()), "", teleop::joystickFields(), "config/teleop.yaml");
  addRows(&(sets["robot"] = json::array()), "", aria::robotParamsFields(), "");  // robot files: not generated
  std::cout << sets.dump(1) << "\n";
  return 0;
}
