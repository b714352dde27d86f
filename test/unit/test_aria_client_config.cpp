// Driver configuration: port parsing (serial vs host:port) and validation messages that
// name the bad field.
#include <gtest/gtest.h>

#include <cmath>

#include "amigobot_tracking/aria/client.h"
#include "amigobot_tracking/aria/transport.h"
#include "temp_dir.h"

using namespace amigobot_tracking::aria;

TEST(AriaTransport, HostPortIsTcpAndDevicesAreSerial) {
  // The address rule itself: test_link_address.
  EXPECT_FALSE(makeTransport("localhost:8101", 9600)->isSerial());
  EXPECT_TRUE(makeTransport("/tmp/odd:123", 9600)->isSerial());  // a path with a colon is still a device
  EXPECT_THROW(makeTransport("localhost:81a", 9600), std::invalid_argument);
  EXPECT_TRUE(makeTransport("localhost:8101", 9600)->describe().find("tcp localhost:8101") != std::string::npos);
  EXPECT_TRUE(makeTransport("/dev/ttyUSB0", 9600)->isSerial());
  EXPECT_THROW(makeTransport("localhost:99999", 9600), std::invalid_argument);
  EXPECT_THROW(makeTransport("", 9600), std::invalid_argument);
  EXPECT_THROW(makeTransport("/dev/ttyUSB0", 0), std::invalid_argument);
}

TEST(AriaTransport, OpeningAMissingDeviceSaysWhichOne) {
  auto t = makeTransport("/nonexistent/ttyAMIGO", 9600);
  try {
    t->open();
    FAIL() << "opened a missing device";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/ttyAMIGO"), std::string::npos) << e.what();
  }
}

TEST(AriaClientConfig, DefaultsAreValid) { EXPECT_EQ(ClientConfig().validate(), ""); }

TEST(AriaClientConfig, BadFieldsAreNamed) {
  auto error = [](auto mutate) {
    ClientConfig c;
    mutate(c);
    return c.validate();
  };
  EXPECT_NE(error([](ClientConfig& c) { c.v_max = std::nan(""); }).find("v_max"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.w_max = 10.0; }).find("w_max"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.command_timeout = -1; }).find("cmd_vel_timeout"), std::string::npos);
  // Upper bound (issue 25): 1e308 s was accepted, i.e. no watchdog at all.
  EXPECT_NE(error([](ClientConfig& c) { c.command_timeout = 1e308; }).find("cmd_vel_timeout"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.link_timeout = 61.0; }).find("link_timeout"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.command_refresh = 2.5; }).find("watchdog"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.port = ""; }).find("port"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.robot.vel2_divisor = 0; }).find("robot.vel2_divisor"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.max_packet_count = 300; }).find("max_packet_count"), std::string::npos);
  EXPECT_NE(error([](ClientConfig& c) { c.reconnect_delay_max = 0.1; }).find("reconnect_delay_max"), std::string::npos);
  ClientConfig bad;
  bad.v_max = -1;
  EXPECT_THROW(AriaClient client(bad), std::invalid_argument);
}

TEST(AriaClientConfig, RunTimeLimitsAreCheckedLikeTheConfigAndNameTheField) {
  AriaClient client(ClientConfig{}, [](LogLevel, const std::string&) {});
  ClientConfig limits = client.motionLimits();
  EXPECT_DOUBLE_EQ(limits.v_max, 0.0);  // the robot's diamond
  EXPECT_DOUBLE_EQ(limits.diamond().vMax(), 0.3);
  limits.v_max = 0.35;  // above the amigo file's diamond (0.3), below its ceiling
  EXPECT_NE(client.setMotionLimits(limits).find("v_max: must be <= the robot's v_max 0.3 m/s (built-in amigo set, "
                                                "config/robots/amigo.yaml)"),
            std::string::npos)
      << client.setMotionLimits(limits);
  limits.v_max = 0.2;
  limits.rot_accel = -1.0;
  EXPECT_NE(client.setMotionLimits(limits).find("rot_accel"), std::string::npos);
  limits.rot_accel = 2.0;
  limits.port = "elsewhere:1";  // not live: ignored
  limits.command_refresh = 0.1;
  EXPECT_EQ(client.setMotionLimits(limits), "");
  EXPECT_DOUBLE_EQ(client.motionLimits().v_max, 0.2);
  EXPECT_DOUBLE_EQ(client.motionLimits().rot_accel, 2.0);
  EXPECT_EQ(client.motionLimits().port, ClientConfig().port);
  EXPECT_DOUBLE_EQ(client.motionLimits().command_refresh, ClientConfig().command_refresh);
}

TEST(AriaClientConfig, CalibrationOutsideTheFirmwareRangeIsRefused) {
  ClientConfig c;
  c.ticks_mm = -1;
  EXPECT_NE(c.validate().find("ticks_mm"), std::string::npos);
  c.ticks_mm = 128;
  c.drift_factor = 40000;
  EXPECT_NE(c.validate().find("drift_factor"), std::string::npos);
  c.drift_factor = -40;
  c.rev_count = -1;
  EXPECT_NE(c.validate().find("rev_count"), std::string::npos);
  c.rev_count = 16384;
  EXPECT_EQ(c.validate(), "");
}

// The diamond lives in the robot file: a file with a smaller one is what every command is
// judged against, with no driver parameter set; a driver limit may tighten it, not widen it.
class AriaRobotFileDiamond : public TempDirTest {};

TEST_F(AriaRobotFileDiamond, IsWhatEveryCommandIsJudgedAgainst) {
  const std::string file = write("slow.yaml", "model: amigo\nv_max: 0.2\nw_max: 0.5\n");
  ClientConfig c;
  c.robot = loadRobotParams(file);
  ASSERT_EQ(c.validate(), "");
  EXPECT_DOUBLE_EQ(c.diamond().vMax(), 0.2);
  EXPECT_DOUBLE_EQ(c.diamond().wMax(), 0.5);
  const auto fast = quantizeCommand({0.3, 0.0}, c.command_mode, c.robot, c.diamond());
  ASSERT_TRUE(fast);
  EXPECT_LE(fast->first, 200) << "VEL in mm/s";
  const auto turn = quantizeCommand({0.0, 0.8}, c.command_mode, c.robot, c.diamond());
  ASSERT_TRUE(turn);
  EXPECT_LE(turn->twist.omega, 0.5 + 1e-9);
  c.v_max = 0.1;  // tightens
  EXPECT_EQ(c.validate(), "");
  EXPECT_DOUBLE_EQ(c.diamond().vMax(), 0.1);
  c.v_max = 0.3;  // the old default, now wider than this robot's diamond
  EXPECT_EQ(c.validate(), "v_max: must be <= the robot's v_max 0.2 m/s (" + file +
                              "), got 0.3: the robot's diamond is set in its robot file, a driver limit only tightens it");
}
