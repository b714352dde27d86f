// The field tables are the one description of the nodelets' parameters; this test fails
// when the files that document them drift: every tracking field in config/tracking.yaml or
// config/controller_experiment.yaml (with a comment on its line; "(reconfigurable)" exactly
// for the live ones), every driver field in config/driver.yaml, each in the docs'
// parameter tables (the laser's in config/laser.yaml too), and in cfg/Tracking.cfg (cfg/Driver.cfg: with
// the same default) exactly when live -- and the other way, no cfg
// entry or docs row of the two nodelets' tables naming no field.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "amigobot_tracking/aria/client.h"
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

namespace {

struct Row {
  bool live;
};

template <class C>
void add(std::map<std::string, Row>* rows, const std::string& prefix, const core::FieldTable<C>& table) {
  for (const auto& f : table) (*rows)[prefix + f.key] = {f.live};
}

// Every parameter of the tracking nodelet that a table describes, with its live flag.
std::map<std::string, Row> nodeletFields() {
  std::map<std::string, Row> rows;
  add(&rows, "", ros_layer::trackingNodeFields());
  add(&rows, "", core::controllerFields());
  add(&rows, "scan/", core::scanObstacleFields());
  add(&rows, "obstacle_tracker/", core::obstacleTrackerFields());
  return rows;
}

std::map<std::string, Row> driverRows() {
  std::map<std::string, Row> rows;
  add(&rows, "", ros_layer::driverFields());
  return rows;
}

std::map<std::string, Row> laserRows() {
  std::map<std::string, Row> rows;
  add(&rows, "", ros_layer::laserFields());
  return rows;
}

std::map<std::string, Row> localizationRows() {
  std::map<std::string, Row> rows;
  add(&rows, "", localization::localizationFields());
  return rows;
}

const char kLocalizationHeader[] = "| Localization parameter |";
const char kTrackingHeader[] = "| Parameter | Type | Unit | Default | Meaning |";
const char kDriverHeader[] = "| Driver parameter | Type | Unit | Default | Meaning |";

std::vector<std::string> lines(const std::string& relative) {
  std::ifstream in(std::string(AMIGOBOT_SOURCE_DIR) + "/" + relative);
  EXPECT_TRUE(in) << "cannot read " << relative;
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// YAML keys (nested with '/') -> the comment on their line; "# key: value  # ..." lines
// (documented but commented out) count too.
std::map<std::string, std::string> yamlKeys(const std::string& file) {
  static const std::regex entry(R"(^(\s*)(?:# )?([A-Za-z_][A-Za-z0-9_]*):(.*)$)");
  std::map<std::string, std::string> keys;
  std::vector<std::pair<size_t, std::string>> parents;  // indentation, key
  for (const std::string& line : lines(file)) {
    std::smatch m;
    if (!std::regex_match(line, m, entry)) continue;
    const size_t indent = m[1].length();
    while (!parents.empty() && parents.back().first >= indent) parents.pop_back();
    std::string key;
    for (const auto& p : parents) key += p.second + "/";
    key += m[2].str();
    const std::string rest = m[3].str();
    const size_t hash = rest.find('#');
    keys[key] = hash == std::string::npos ? "" : rest.substr(hash + 1);
    if (rest.find_first_not_of(' ') == hash || rest.find_first_not_of(' ') == std::string::npos)
      parents.emplace_back(indent, m[2].str());
  }
  return keys;
}

// `a/{b,c}` -> a/b, a/c.
std::vector<std::string> expand(const std::string& name) {
  const size_t open = name.find('{'), close = name.find('}');
  if (open == std::string::npos || close == std::string::npos) return {name};
  std::vector<std::string> out;
  std::stringstream inner(name.substr(open + 1, close - open - 1));
  for (std::string part; std::getline(inner, part, ',');)
    out.push_back(name.substr(0, open) + part + name.substr(close + 1));
  return out;
}

// The parameter tables live in docs/ros_api.md (nodes and nodelets), docs/robot_file.md and docs/teleop.md.
std::vector<std::string> tableLines() {
  std::vector<std::string> all;
  for (const char* file : {"docs/ros_api.md", "docs/robot_file.md", "docs/teleop.md"})
    for (std::string& line : lines(file)) all.push_back(std::move(line));
  return all;
}

// Names in backticks in the first cell of the docs' table rows; with a `header`, the rows
// of the table under that header alone.
std::set<std::string> readmeNames(const std::string& header = "") {
  static const std::regex code("`([^`]+)`");
  std::set<std::string> names;
  bool in_nodelet = false;
  for (const std::string& line : tableLines()) {
    if (!header.empty() && line.rfind(header, 0) == 0) in_nodelet = true;
    else if (line.rfind("|", 0) != 0) in_nodelet = false;
    if (line.rfind("|", 0) != 0 || (!header.empty() && !in_nodelet)) continue;
    const std::string cell = line.substr(1, line.find('|', 1) - 1);
    for (std::sregex_iterator it(cell.begin(), cell.end(), code), end; it != end; ++it)
      for (const std::string& n : expand((*it)[1].str())) names.insert(n);
  }
  return names;
}

}  // namespace

TEST(ParamCoverage, EveryFieldIsInTheYamlWithAComment) {
  std::map<std::string, std::string> keys = yamlKeys("config/tracking.yaml");
  for (const auto& [k, comment] : yamlKeys("config/controller_experiment.yaml")) keys[k] = comment;
  for (const auto& [key, row] : nodeletFields()) {
    const auto it = keys.find(key);
    if (it == keys.end()) {
      ADD_FAILURE() << key << " is in no config/tracking.yaml or config/controller_experiment.yaml line";
      continue;
    }
    EXPECT_GT(it->second.size(), 10u) << key << ": the YAML line needs a comment (type, unit, default, meaning)";
    EXPECT_EQ(it->second.find("(reconfigurable)") != std::string::npos, row.live)
        << key << ": '(reconfigurable)' in its comment exactly when live";
  }
}

TEST(ParamCoverage, EveryDriverFieldIsInItsYamlWithAComment) {
  const std::map<std::string, std::string> keys = yamlKeys("config/driver.yaml");
  for (const auto& [key, row] : driverRows()) {
    const auto it = keys.find(key);
    ASSERT_NE(it, keys.end()) << key << " is not in config/driver.yaml";
    EXPECT_GT(it->second.size(), 10u) << key << ": the YAML line needs a comment (type, unit, default, meaning)";
  }
  for (const auto& [key, comment] : keys) EXPECT_TRUE(driverRows().count(key)) << "config/driver.yaml: " << key;
}

TEST(ParamCoverage, EveryLaserFieldIsInItsYamlAndTheReadme) {
  const std::map<std::string, std::string> keys = yamlKeys("config/laser.yaml");
  const std::set<std::string> readme = readmeNames();
  for (const auto& [key, row] : laserRows()) {
    const auto it = keys.find(key);
    ASSERT_NE(it, keys.end()) << key << " is not in config/laser.yaml";
    EXPECT_GT(it->second.size(), 10u) << key << ": the YAML line needs a comment (type, unit, default, meaning)";
    EXPECT_TRUE(readme.count(key)) << key << " is in no parameter table of docs/ros_api.md or docs/teleop.md";
  }
  for (const auto& [key, comment] : keys) EXPECT_TRUE(laserRows().count(key)) << "config/laser.yaml: " << key;
}

TEST(ParamCoverage, EveryLocalizationFieldIsInItsYamlAndTheReadme) {
  const std::map<std::string, std::string> keys = yamlKeys("config/localization.yaml");
  const std::set<std::string> readme = readmeNames(kLocalizationHeader);
  const std::map<std::string, Row> fields = localizationRows();
  for (const auto& [key, row] : fields) {
    const auto it = keys.find(key);
    ASSERT_NE(it, keys.end()) << key << " is not in config/localization.yaml";
    EXPECT_GT(it->second.size(), 10u) << key << ": the YAML line needs a comment (type, unit, default, meaning)";
    EXPECT_TRUE(readme.count(key)) << key << " is in no row of the Localization parameter table (docs/ros_api.md)";
  }
  for (const auto& [key, comment] : keys)
    EXPECT_TRUE(fields.count(key) || key == "initial_pose" || key == "icp" || key == "global" || key == "graph") << "config/localization.yaml: " << key;
  for (const std::string& name : readme) EXPECT_TRUE(fields.count(name)) << "docs localization row `" << name << "` names no field";
}

// The teleop nodes: config/teleop.yaml has one block per node, each field with its comment,
// nothing else; every field is in docs/teleop.md's tables.
TEST(ParamCoverage, EveryTeleopFieldIsInItsYamlAndTheReadme) {
  const std::map<std::string, std::string> keys = yamlKeys("config/teleop.yaml");
  const std::set<std::string> readme = readmeNames();
  std::map<std::string, Row> rows;
  add(&rows, "keyboard_teleop/", teleop::keyboardFields());
  add(&rows, "keyboard_teleop/", ros_layer::robotSourceFields());  // read by the program beside its table
  add(&rows, "joystick_teleop/", teleop::joystickFields());
  for (const auto& [key, row] : rows) {
    const auto it = keys.find(key);
    ASSERT_NE(it, keys.end()) << key << " is not in config/teleop.yaml";
    EXPECT_GT(it->second.size(), 10u) << key << ": the YAML line needs a comment (type, unit, default, meaning)";
    EXPECT_TRUE(readme.count(key.substr(key.find('/') + 1))) << key << " is in no parameter table of docs/ros_api.md or docs/teleop.md";
  }
  for (const auto& [key, comment] : keys)
    EXPECT_TRUE(rows.count(key) || key == "keyboard_teleop" || key == "joystick_teleop") << "config/teleop.yaml: " << key;
}

TEST(ParamCoverage, EveryFieldIsInTheReadmeAndEveryRowNamesOne) {
  const std::set<std::string> all = readmeNames();
  const std::map<std::string, Row> fields = nodeletFields(), driver = driverRows();
  for (const auto& [key, row] : fields) EXPECT_TRUE(all.count(key)) << key << " is in no parameter table of docs/ros_api.md or docs/teleop.md";
  for (const auto& [key, row] : driver) EXPECT_TRUE(all.count(key)) << key << " is in no parameter table of docs/ros_api.md or docs/teleop.md";
  const std::set<std::string> not_in_tables = {"virtual_obstacles"};  // a list (tracking_params.h)
  for (const std::string& name : readmeNames(kTrackingHeader))
    EXPECT_TRUE(fields.count(name) || not_in_tables.count(name)) << "docs row `" << name << "` names no field";
  for (const std::string& name : readmeNames(kDriverHeader))
    EXPECT_TRUE(driver.count(name)) << "docs driver row `" << name << "` names no field";
}

// gen.add("name", type, level, "description", default, ...) of a .cfg: name -> default text.
std::map<std::string, std::string> cfgEntries(const std::string& path) {
  static const std::regex add(R"re(gen\.add\(\s*"([A-Za-z0-9_]+)"\s*,\s*\w+\s*,\s*[^,]+,\s*"[^"]*"\s*,\s*([^,\)]+))re");
  std::map<std::string, std::string> entries;
  for (const std::string& line : lines(path)) {
    std::smatch m;
    if (std::regex_search(line, m, add)) entries[m[1].str()] = m[2].str();
  }
  return entries;
}

// Every live row of `table` is an entry of the .cfg with the row's default, and no other row is.
template <class C>
void expectCfgIsTheLiveRows(const std::string& path, const core::FieldTable<C>& table) {
  const std::map<std::string, std::string> cfg = cfgEntries(path);
  EXPECT_FALSE(cfg.empty()) << path;
  for (const core::Field<C>& f : table) {
    const auto it = cfg.find(f.key);
    EXPECT_EQ(it != cfg.end(), f.live) << f.key << ": in " << path << " exactly when live";
    if (it == cfg.end() || !f.live) continue;
    const core::FieldValue def = core::defaultValue(f);
    if (const double* d = std::get_if<double>(&def)) {
      EXPECT_DOUBLE_EQ(std::stod(it->second), *d) << path << ": " << f.key << " default";
    } else if (const int* i = std::get_if<int>(&def)) {
      EXPECT_EQ(std::stoi(it->second), *i) << path << ": " << f.key << " default";
    } else if (const bool* b = std::get_if<bool>(&def)) {
      EXPECT_EQ(it->second == "True", *b) << path << ": " << f.key << " default";
    }
  }
}

TEST(ParamCoverage, TheCfgHasExactlyTheLiveFields) {
  const std::map<std::string, std::string> cfg = cfgEntries("cfg/Tracking.cfg");
  EXPECT_FALSE(cfg.empty());
  for (const auto& [key, row] : nodeletFields())
    EXPECT_EQ(cfg.count(key) > 0, row.live) << key << ": in cfg/Tracking.cfg exactly when live";
  for (const auto& [name, def] : cfg) EXPECT_TRUE(nodeletFields().count(name)) << "cfg entry " << name << " names no field";
  expectCfgIsTheLiveRows("cfg/Tracking.cfg", core::controllerFields());
}

// The driver's dynamic_reconfigure is the live rows of its table (the client's and stamp_offset):
// Driver.cfg lists exactly those, with their defaults, and no entry names anything else.
TEST(ParamCoverage, DriverCfgIsTheClientsLiveRowsWithTheirDefaults) {
  expectCfgIsTheLiveRows("cfg/Driver.cfg", ros_layer::driverFields());
  for (const auto& [name, def] : cfgEntries("cfg/Driver.cfg"))
    EXPECT_TRUE(driverRows().count(name)) << "cfg/Driver.cfg entry " << name << " names no driver field";
}
