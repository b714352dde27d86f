// The emulator's firmware settings: POLLING changes the firing order, TICKSMM / REVCOUNT /
// DRIFTFACTOR scale the firmware's odometry and come back in CONFIGpac, CLOSE restores them.
#include <gtest/gtest.h>

#include <cmath>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/aria/emulator.h"
#include "amigobot_tracking/aria/odometry.h"
#include "aria_packets.h"

using namespace amigobot_tracking::aria;
using amigobot_test::openRobot;
using amigobot_test::packetOf;

namespace {

std::vector<int> firedIndices(RobotEmulator& robot, double t) {
  std::vector<int> fired;
  const std::optional<Sip> sip = decodeSip(packetOf(robot.advance(t)));
  EXPECT_TRUE(sip);
  if (sip) {
    for (const auto& s : sip->sonars) fired.push_back(s.index);
  }
  return fired;
}

// Drives straight at 0.2 m/s for 2 s; returns the distance the firmware's odometry says.
double odometryDistance(RobotEmulator& robot, const std::vector<std::vector<std::uint8_t>>& settings) {
  openRobot(robot, 0.0);
  for (const auto& packet : settings) robot.handle(packetOf(packet), 0.0);
  robot.handle(packetOf(commandPacket(Command::kEnable, 1)), 0.0);
  robot.handle(packetOf(commandPacket(Command::kVel, 200)), 0.0);
  for (double t = 0.1; t < 2.0; t += 0.1) robot.handle(packetOf(commandPacket(Command::kPulse)), t);
  const std::optional<Sip> sip = decodeSip(packetOf(robot.advance(2.0)));
  EXPECT_TRUE(sip);
  return sip ? sip->x * robot.options().robot.dist_conv_factor * 1e-3 : 0.0;
}

}  // namespace

TEST(EmulatorFirmware, PollingSetsTheFiringOrder) {
  RobotEmulator robot({});
  openRobot(robot, 0.0);
  EXPECT_EQ(firedIndices(robot, 0.0), (std::vector<int>{0, 1, 2, 3}));  // the firmware's own order
  robot.handle(packetOf(commandPacket(Command::kPolling, std::string{8, 1, 5})), 0.05);  // numbers from 1
  EXPECT_EQ(firedIndices(robot, 0.1), (std::vector<int>{7, 0, 4}));
  robot.handle(packetOf(commandPacket(Command::kPolling, std::string{9})), 0.15);  // no transducer 9: ignored
  EXPECT_EQ(firedIndices(robot, 0.2), (std::vector<int>{7, 0, 4}));
  EXPECT_EQ(robot.counters().unknown_commands, 1u);
}

TEST(EmulatorFirmware, TicksMmScalesTheOdometryAndComesBackInConfigPac) {
  RobotEmulator plain({});
  const double reference = odometryDistance(plain, {});
  EXPECT_NEAR(reference, plain.truePose().x, 0.002);
  RobotEmulator calibrated({});
  const double doubled_ticks = odometryDistance(calibrated, {commandPacket(Command::kTicksMM, 256)});
  EXPECT_NEAR(doubled_ticks, 0.5 * reference, 0.002);  // TicksMM 256 against the encoders' 128
  EXPECT_NEAR(calibrated.truePose().x, plain.truePose().x, 1e-9);  // the robot moved the same
  calibrated.handle(packetOf(commandPacket(Command::kRevCount, 8192)), 2.0);
  calibrated.handle(packetOf(commandPacket(Command::kDriftFactor, -40)), 2.0);
  const auto config = decodeConfigPac(packetOf(calibrated.handle(packetOf(commandPacket(Command::kConfig, 1)), 2.0)));
  ASSERT_TRUE(config);
  EXPECT_EQ(config->ticks_mm, 256);
  EXPECT_EQ(config->rev_count, 8192);
  EXPECT_EQ(config->drift_factor, -40);
  calibrated.handle(packetOf(commandPacket(Command::kClose, 1)), 2.1);
  openRobot(calibrated, 2.2);
  const auto flash = decodeConfigPac(packetOf(calibrated.handle(packetOf(commandPacket(Command::kConfig, 1)), 2.2)));
  ASSERT_TRUE(flash);
  EXPECT_EQ(flash->ticks_mm, 128);  // CLOSE: back to FLASH
}
