// The emulator's UART model (garbage at a mismatched baud, pacing at the robot's baud) and
// the firmware's baud state (HOSTBAUD, CLOSE back to 9600, left open by a crashed session).
#include <gtest/gtest.h>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/aria/emulator.h"
#include "amigobot_tracking/aria/emulator_line.h"
#include "aria_packets.h"

using namespace amigobot_tracking::aria;
using amigobot_test::openRobot;
using amigobot_test::packetOf;

namespace {
// The CONFIGpac of an opened robot, after HOSTBAUD 2 (38400) was sent to it.
std::optional<ConfigPac> configThenHostBaud(RobotEmulator& robot) {
  openRobot(robot, 0.0);
  const auto config = decodeConfigPac(packetOf(robot.handle(packetOf(commandPacket(Command::kConfig, 1)), 0.1)));
  robot.handle(packetOf(commandPacket(Command::kHostBaud, 2)), 0.2);
  return config;
}
}  // namespace

TEST(SerialLineModel, GarbageNeverHoldsAHeaderSoItNeverFramesAPacket) {
  for (int b = 0; b < 256; ++b) EXPECT_NE(garble(static_cast<std::uint8_t>(b)), kHeader0) << b;
  const std::vector<std::uint8_t> vel = commandPacket(Command::kVel, 300);
  PacketParser parser;
  parser.feed(SerialLineModel::receive(vel.data(), vel.size(), 9600, 38400));
  Packet p;
  EXPECT_FALSE(parser.next(p));
  EXPECT_EQ(parser.stats().garbage_bytes, vel.size());
}

TEST(SerialLineModel, MatchingBaudsPassBytesUnchanged) {
  const std::vector<std::uint8_t> vel = commandPacket(Command::kVel, 300);
  EXPECT_EQ(SerialLineModel::receive(vel.data(), vel.size(), 38400, 38400), vel);
}

TEST(SerialLineModel, PacesTheRobotsBytesAtItsBaud) {
  SerialLineModel line;
  const std::vector<std::uint8_t> sip(96, 0x11);
  line.transmit(sip, 9600, 10.0);  // 96 bytes x 10 bits at 9600: 100 ms
  EXPECT_TRUE(line.due(10.099, 9600).empty());
  EXPECT_EQ(line.due(10.101, 9600), sip);
  line.transmit(sip, 38400, 20.0);  // 25 ms
  EXPECT_EQ(line.due(20.026, 38400).size(), sip.size());
  line.transmit(sip, 38400, 30.0);
  const std::vector<std::uint8_t> heard = line.due(31.0, 9600);  // host at the wrong baud
  ASSERT_EQ(heard.size(), sip.size());
  EXPECT_NE(heard, sip);
}

TEST(SerialLineModel, DropsOutputBeyondASecondOfBacklog) {
  SerialLineModel line;
  const std::vector<std::uint8_t> chunk(960, 0x22);  // one second at 9600
  line.transmit(chunk, 9600, 0.0);
  line.transmit(chunk, 9600, 0.0);
  line.transmit(chunk, 9600, 0.0);
  EXPECT_EQ(line.bytesDropped(), chunk.size());
}

TEST(EmulatorBaud, HostBaudSwitchesTheRobotAndCloseRestoresTheFlashBaud) {
  RobotEmulator robot({});
  EXPECT_EQ(robot.baud(), 9600);
  const auto config = configThenHostBaud(robot);
  ASSERT_TRUE(config);
  EXPECT_EQ(config->auto_baud.value_or(0), 2);
  EXPECT_EQ(robot.baud(), 38400);
  robot.handle(packetOf(commandPacket(Command::kHostBaud, 7)), 0.3);  // no such rate: ignored
  EXPECT_EQ(robot.baud(), 38400);
  robot.handle(packetOf(commandPacket(Command::kClose, 1)), 0.4);
  EXPECT_EQ(robot.baud(), 9600);
}

TEST(EmulatorBaud, LeftOpenByACrashedSessionItSendsSipsAtThatBaud) {
  EmulatorOptions options;
  options.left_open_at_baud = 115200;
  RobotEmulator robot(options);
  EXPECT_TRUE(robot.isOpen());
  EXPECT_EQ(robot.baud(), 115200);
  EXPECT_FALSE(robot.advance(0.0).empty());
  options.left_open_at_baud = -1;
  EXPECT_THROW(RobotEmulator{options}, std::invalid_argument);
}

TEST(EmulatorBaud, SimulatorModeDoesNotOfferTheSwitch) {
  EmulatorOptions options;
  options.simulator_mode = true;
  RobotEmulator robot(options);
  const auto config = configThenHostBaud(robot);
  ASSERT_TRUE(config);
  EXPECT_EQ(config->auto_baud.value_or(0), 0);
  EXPECT_EQ(robot.baud(), 9600);
}
