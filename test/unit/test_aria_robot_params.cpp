// Robot parameter files: the shipped YAML agrees with the built-in sets, and bad files are
// rejected with the file, line and key named.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "amigobot_tracking/aria/robot_params.h"

using namespace amigobot_tracking::aria;

namespace {
std::string robotFile(const std::string& model) {
  return std::string(AMIGOBOT_SOURCE_DIR) + "/config/robots/" + model + ".yaml";
}

void expectSame(const RobotParams& a, const RobotParams& b) {
  EXPECT_EQ(a.model, b.model);
  EXPECT_DOUBLE_EQ(a.dist_conv_factor, b.dist_conv_factor);
  EXPECT_DOUBLE_EQ(a.vel_conv_factor, b.vel_conv_factor);
  EXPECT_DOUBLE_EQ(a.angle_conv_factor, b.angle_conv_factor);
  EXPECT_EQ(a.angle_units_per_turn, b.angle_units_per_turn);
  EXPECT_DOUBLE_EQ(a.range_conv_factor, b.range_conv_factor);
  EXPECT_DOUBLE_EQ(a.diff_conv_factor, b.diff_conv_factor);
  EXPECT_DOUBLE_EQ(a.vel2_divisor, b.vel2_divisor);
  EXPECT_DOUBLE_EQ(a.robot_radius, b.robot_radius);
  EXPECT_DOUBLE_EQ(a.max_velocity, b.max_velocity);
  EXPECT_DOUBLE_EQ(a.watchdog, b.watchdog);
  EXPECT_DOUBLE_EQ(a.sonar_max_range, b.sonar_max_range);
  EXPECT_EQ(a.sonar_polling, b.sonar_polling);
  EXPECT_EQ(a.switch_to_baud, b.switch_to_baud);
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
  p.sip_cycle = std::nan("");
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
