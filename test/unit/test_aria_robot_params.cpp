// Robot parameter files: the shipped YAML agrees with the built-in sets, and bad files are
// rejected with the file, line and key named.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>

#include "amigobot_tracking/aria/robot_params.h"

using namespace amigobot_tracking::aria;

namespace {
std::string robotFile(const std::string& model) {
  return std::string(AMIGOBOT_SOURCE_DIR) + "/config/robots/" + model + ".yaml";
}

void expectSame(const RobotParams& a, const RobotParams& b) {
  for (const auto& row : robotParamsFields()) EXPECT_EQ(row.get(a), row.get(b)) << row.key;
  EXPECT_EQ(a.sonar_polling, b.sonar_polling);
  ASSERT_EQ(a.sonars.size(), b.sonars.size());
  for (std::size_t i = 0; i < a.sonars.size(); ++i) {
    EXPECT_NEAR(a.sonars[i].x, b.sonars[i].x, 1e-12) << i;
    EXPECT_NEAR(a.sonars[i].y, b.sonars[i].y, 1e-12) << i;
    EXPECT_NEAR(a.sonars[i].yaw, b.sonars[i].yaw, 1e-12) << i;
  }
}

std::string writeTemp(const std::string& text) {
  char name[] = "/tmp/amigobot_params_XXXXXX";
  const int fd = mkstemp(name);
  EXPECT_GE(fd, 0);
  std::FILE* f = fdopen(fd, "w");
  std::fputs(text.c_str(), f);
  std::fclose(f);
  return name;
}

std::string loadError(const std::string& text) {
  const std::string path = writeTemp(text);
  std::string message;
  try {
    loadRobotParams(path);
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  std::remove(path.c_str());
  return message;
}
}  // namespace

TEST(AriaRobotParams, ShippedFilesMatchTheBuiltInSets) {
  expectSame(loadRobotParams(robotFile("amigo")), RobotParams::amigo());
  expectSame(loadRobotParams(robotFile("amigo-sh")), RobotParams::amigoSh());
}

TEST(AriaRobotParams, BuiltInsFollowAriaAndAreValid) {
  const RobotParams a = builtinRobotParams("amigo");
  const RobotParams sh = builtinRobotParams("amigo-sh");
  EXPECT_EQ(a.validate(), "");
  EXPECT_EQ(sh.validate(), "");
  EXPECT_DOUBLE_EQ(a.dist_conv_factor, 0.5083);
  EXPECT_DOUBLE_EQ(sh.dist_conv_factor, 1.0);
  EXPECT_NEAR(a.halfTrack(), 0.0909, 1e-4);  // 2/DiffConv = 182 mm track
  EXPECT_NEAR(a.sonars[0].yaw, M_PI / 2, 1e-12);
  EXPECT_NEAR(sh.sonars[2].x, 0.144, 1e-12);
  EXPECT_THROW(builtinRobotParams("pioneer"), std::invalid_argument);
}

TEST(AriaRobotParams, BadValuesNameTheKeyAndLine) {
  const std::string bad_type = loadError("model: amigo\nvel2_divisor: fast\n");
  EXPECT_NE(bad_type.find(":2:"), std::string::npos) << bad_type;
  EXPECT_NE(bad_type.find("vel2_divisor"), std::string::npos) << bad_type;
  const std::string negative = loadError("dist_conv_factor: -1\n");
  EXPECT_NE(negative.find("dist_conv_factor"), std::string::npos) << negative;
  const std::string unknown = loadError("dist_conv: 1\n");
  EXPECT_NE(unknown.find("unknown key 'dist_conv'"), std::string::npos) << unknown;
  const std::string sonar = loadError("sonars:\n  - {x: 0.1, y: 0.2}\n");
  EXPECT_NE(sonar.find("sonars[0]"), std::string::npos) << sonar;
  const std::string missing = loadError("");
  EXPECT_FALSE(missing.empty());
  EXPECT_THROW(loadRobotParams("/nonexistent/robot.yaml"), std::runtime_error);
}

TEST(AriaRobotParams, ValidateNamesTheField) {
  RobotParams p = RobotParams::amigo();
  p.dynamics.cycle = std::nan("");
  EXPECT_NE(p.validate().find("sip_cycle"), std::string::npos);
  p = RobotParams::amigo();
  p.angle_units_per_turn = 0;
  EXPECT_NE(p.validate().find("angle_units_per_turn"), std::string::npos);
}

TEST(AriaRobotParams, SonarAndBaudKeysAreCheckedByName) {
  const std::string polling = loadError("sonar_polling: [0, 3, 8]\n");
  EXPECT_NE(polling.find("sonar_polling[2]: transducer 8 does not exist"), std::string::npos) << polling;
  const std::string range = loadError("sonar_max_range: 0\n");
  EXPECT_NE(range.find("sonar_max_range"), std::string::npos) << range;
  const std::string baud = loadError("switch_to_baud: 14400\n");
  EXPECT_NE(baud.find("switch_to_baud: must be a HOSTBAUD rate"), std::string::npos) << baud;
  EXPECT_DOUBLE_EQ(RobotParams::amigo().sonar_max_range, 4.335);
}

// One table drives the loader: every row (and nothing else) is a key of the shipped files,
// a bad key is named with its file:line and the nearest row, bounds are the table's.
TEST(AriaRobotParams, TheFieldTableIsTheFilesKeys) {
  for (const char* model : {"amigo", "amigo-sh"}) {
    std::ifstream in(robotFile(model));
    std::set<std::string> keys;
    for (std::string line; std::getline(in, line);) {
      const std::size_t colon = line.find(':');
      if (line.empty() || line[0] == '#' || line[0] == ' ' || colon == std::string::npos) continue;
      keys.insert(line.substr(0, colon));
    }
    std::set<std::string> rows(robotParamsListKeys().begin(), robotParamsListKeys().end());
    for (const auto& row : robotParamsFields()) rows.insert(row.key);
    EXPECT_EQ(keys, rows) << model;
  }
}

TEST(AriaRobotParams, TheLoaderNamesFileLineKeyAndBound) {
  const std::string path = writeTemp("model: amigo\ntrans_accel: 0.3\nlatncy: 0.2\n");
  try {
    loadRobotParams(path);
    ADD_FAILURE() << "a misspelt key was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), path + ":3: unknown key 'latncy' (nearest: latency)");
  }
  std::remove(path.c_str());
  EXPECT_NE(loadError("\nlatency: -0.1\n").find(":2: latency: must be a finite number in [0, 86400], got -0.1"), std::string::npos)
      << loadError("\nlatency: -0.1\n");
  EXPECT_NE(loadError("v_max: [1]\n").find(":1: v_max: expected a number, got a list or mapping"), std::string::npos);
  EXPECT_NE(loadError("robot_radius: 1e308\n").find("robot_radius: must be a finite number in (0, 100]"), std::string::npos)
      << loadError("robot_radius: 1e308\n");
  // The diamond lies inside the ceiling.
  EXPECT_NE(loadError("v_max: 1.5\n").find(": v_max: must be <= max_velocity 1 m/s, got 1.5"), std::string::npos)
      << loadError("v_max: 1.5\n");
}

TEST(AriaRobotParams, TheDescriptionHoldsDynamicsLatencyAndDiamond) {
  const std::string path = writeTemp("trans_accel: 0.5\nsip_cycle: 0.05\nlatency: 0.2\nv_max: 0.25\nw_max: 0.6\n");
  const RobotParams p = loadRobotParams(path);
  std::remove(path.c_str());
  EXPECT_DOUBLE_EQ(p.dynamics.trans_accel, 0.5);
  EXPECT_DOUBLE_EQ(p.dynamics.cycle, 0.05);
  EXPECT_DOUBLE_EQ(p.dynamics.latency, 0.2);
  EXPECT_DOUBLE_EQ(p.v_max, 0.25);
  EXPECT_DOUBLE_EQ(p.w_max, 0.6);
  EXPECT_EQ(p.file, path);
  EXPECT_DOUBLE_EQ(RobotParams::amigo().dynamics.latency, 0.1);
  EXPECT_DOUBLE_EQ(RobotParams::amigo().v_max, 0.3);
}
