// Test helpers for in-process protocol tests: bytes to one packet, the handshake run
// against a RobotEmulator.
#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/aria/emulator.h"
#include "amigobot_tracking/aria/packet.h"

namespace amigobot_test {

// The one packet `bytes` hold (a test failure when they hold none).
inline amigobot_tracking::aria::Packet packetOf(const std::vector<std::uint8_t>& bytes) {
  amigobot_tracking::aria::PacketParser parser;
  parser.feed(bytes);
  amigobot_tracking::aria::Packet p;
  EXPECT_TRUE(parser.next(p));
  return p;
}

// Runs the handshake and OPEN at time t; returns the SYNC reply types (-1: no reply).
inline std::vector<int> openRobot(amigobot_tracking::aria::RobotEmulator& robot, double t) {
  using namespace amigobot_tracking::aria;
  std::vector<int> types;
  for (int n = 0; n < 3; ++n) {
    const auto reply = robot.handle(packetOf(syncPacket(n)), t);
    types.push_back(reply.empty() ? -1 : packetOf(reply).type);
  }
  robot.handle(packetOf(commandPacket(Command::kOpen, 1)), t);
  return types;
}

}  // namespace amigobot_test
