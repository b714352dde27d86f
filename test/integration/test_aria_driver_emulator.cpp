// AriaClient against the amigobot_emulator executable over real TCP sockets and a real
// pseudo-terminal: handshake, motors, a driven square checked against ground truth, the
// firmware watchdog, the command timeout, reconnect after a crash, recovery of a robot left
// open, simulator quirks and a clean close. Timeouts are generous for a loaded machine.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "amigobot_tracking/aria/client.h"
#include "amigobot_tracking/core/robot/actuator_limits.h"
#include "emulator_process.h"

using namespace amigobot_test;
using namespace amigobot_tracking::aria;
using amigobot_tracking::core::Pose2;
using amigobot_tracking::core::wrapAngle;

namespace {

std::string ptyLink(const std::string& tag) {
  return "/tmp/amigobot_test_" + tag + "_" + std::to_string(::getpid());
}

ClientConfig clientConfig(const std::string& port) {
  ClientConfig c = emulatorClientConfig(port);
  c.robot.v_max = 0.5;  // a robot file with a wider diamond (the driver may only tighten it)
  c.robot.w_max = 2.0;
  return c;
}

std::unique_ptr<AriaClient> connectClient(const ClientConfig& config) {
  auto client = std::make_unique<AriaClient>(config, [](LogLevel, const std::string&) {});
  client->start();
  const bool up = waitFor([&] { return client->status().link == LinkState::kConnected && client->status().robot; }, 30.0);
  EXPECT_TRUE(up) << "not connected: " << client->status().last_error;
  return client;
}

Pose2 odom(const AriaClient& c) {
  const auto s = c.status();
  return s.robot ? s.robot->odometry.pose : Pose2{};
}

// The firmware acts on a command latency .. latency + cycle after it arrives (core/robot/actuator_model.h):
// the stop is sent that much early, on the mean, as a client of the real robot has to.
const double kFirmwareDelay =
    amigobot_tracking::core::ActuatorLimits{}.latency + 0.5 * amigobot_tracking::core::ActuatorLimits{}.cycle;  // [s]

// Drives straight by odometry for `distance`. The speed shrinks near the goal but stays
// above two VEL2 steps (20 mm/s per wheel each): below that VEL2 quantises it to zero and
// the robot stalls short of the goal (the same floor applies to the turns).
void driveStraight(AriaClient& c, double distance) {
  const Pose2 start = odom(c);
  waitFor([&] {
    const Pose2 p = odom(c);
    const double left = distance - std::hypot(p.x - start.x, p.y - start.y);
    const double v = std::clamp(1.5 * left, 0.045, 0.3);
    c.setVelocity({v, 0.0});
    return left < 0.003 + v * kFirmwareDelay;
  }, 30.0);
  c.setVelocity({0.0, 0.0});
}

// Turns left to the absolute heading `goal` (absolute, so overshoots do not accumulate).
void turnLeftTo(AriaClient& c, double goal) {
  waitFor([&] {
    const double left = wrapAngle(goal - odom(c).theta);
    const double w = std::clamp(2.0 * left, 0.5, 1.2);
    c.setVelocity({0.0, w});
    return left < 0.01 + w * kFirmwareDelay;
  }, 30.0);
  c.setVelocity({0.0, 0.0});
}

void waitStopped(EmulatorProcess& emu) {
  waitFor([&] {
    const Truth t = emu.truth();
    return std::abs(t.v) < 1e-6 && std::abs(t.w) < 1e-6;
  }, 10.0);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // one more SIP after the stop
}

}  // namespace

struct SquareCase {
  bool pty;
  CommandMode mode;
  const char* model;
};

class AriaSquare : public ::testing::TestWithParam<SquareCase> {};

TEST_P(AriaSquare, DrivesASquareWithOdometryMatchingGroundTruth) {
  const SquareCase param = GetParam();
  const std::string link = ptyLink("square");
  EmulatorProcess emu({"--model", param.model}, 0, param.pty ? link : "");
  ClientConfig config = clientConfig(param.pty ? link : emu.address());
  config.robot = builtinRobotParams(param.model);
  config.command_mode = param.mode;
  config.enable_motors = true;
  config.trans_accel = config.trans_decel = 1.0;  // SETA/SETRA: brisk, so the square is quick
  config.rot_accel = config.rot_decel = 4.0;
  auto client = connectClient(config);
  ASSERT_TRUE(client->status().identity);
  EXPECT_EQ(client->status().identity->subclass, param.model);
  ASSERT_TRUE(client->status().config) << "no CONFIGpac";
  EXPECT_EQ(client->status().config->sip_cycle_ms, 100);
  ASSERT_TRUE(waitFor([&] { return emu.truth().motors; }, 10.0)) << "motors not enabled";

  const double side = 0.4;
  for (int k = 0; k < 4; ++k) {
    driveStraight(*client, side);
    waitStopped(emu);
    const Truth corner = emu.truth();
    // The k-th corner of the square (counter-clockwise), judged by ground truth.
    const double cx[] = {side, side, 0.0, 0.0}, cy[] = {0.0, side, side, 0.0};
    EXPECT_NEAR(corner.pose.x, cx[k], 0.05) << "corner " << k;
    EXPECT_NEAR(corner.pose.y, cy[k], 0.05) << "corner " << k;
    turnLeftTo(*client, wrapAngle((k + 1) * M_PI / 2));
    waitStopped(emu);
  }
  const Truth truth = emu.truth();
  const Pose2 est = odom(*client);
  // Odometry agrees with ground truth up to the firmware's quantisation.
  EXPECT_NEAR(est.x, truth.pose.x, 0.01);
  EXPECT_NEAR(est.y, truth.pose.y, 0.01);
  EXPECT_NEAR(wrapAngle(est.theta - truth.pose.theta), 0.0, 0.01);
  EXPECT_NEAR(std::hypot(truth.pose.x, truth.pose.y), 0.0, 0.08) << "the square did not close";
  const ClientStatus s = client->status();
  EXPECT_EQ(s.parser.errors(), 0u);
  EXPECT_GT(s.sip_rate, 5.0);
  EXPECT_EQ(s.last_command->mode, param.mode);
  client->stop();
  // Clean shutdown: the robot is closed with its motors off.
  EXPECT_TRUE(waitFor([&] { const Truth t = emu.truth(); return !t.open && !t.motors; }, 5.0));
}

INSTANTIATE_TEST_SUITE_P(TransportsAndModes, AriaSquare,
                         ::testing::Values(SquareCase{false, CommandMode::kVelRvel, "amigo"},
                                           SquareCase{true, CommandMode::kVel2, "amigo-sh"}),
                         [](const auto& info) {
                           return std::string(info.param.pty ? "pty_" : "tcp_") + commandModeName(info.param.mode);
                         });

TEST(AriaDriverEmulator, FirmwareWatchdogStopsARobotWhoseClientFellSilent) {
  EmulatorProcess emu;
  RawClient raw = RawClient::tcp(emu.tcpPort());
  ASSERT_TRUE(raw.ok());
  ASSERT_TRUE(raw.handshakeAndOpen());
  raw.send(commandPacket(Command::kEnable, 1));
  raw.send(commandPacket(Command::kVel, 200));
  ASSERT_TRUE(waitFor([&] { return emu.truth().v > 0.15; }, 5.0)) << "robot never moved";
  // No more commands: within the 2 s watchdog plus deceleration the robot must stop.
  EXPECT_TRUE(waitFor([&] { const Truth t = emu.truth(); return t.watchdog && std::abs(t.v) < 1e-6; }, 6.0));
  // A command resumes the last setpoints (firmware behaviour).
  raw.send(commandPacket(Command::kPulse));
  EXPECT_TRUE(waitFor([&] { return emu.truth().v > 0.15; }, 5.0));
}

TEST(AriaDriverEmulator, SimulatorWatchdogOnlyWarns) {
  EmulatorProcess emu({"--simulator-mode"});
  RawClient raw = RawClient::tcp(emu.tcpPort());
  ASSERT_TRUE(raw.handshakeAndOpen());
  raw.send(commandPacket(Command::kVel, 200));  // motors start enabled in a simulator
  ASSERT_TRUE(waitFor([&] { return emu.truth().v > 0.15; }, 5.0));
  ASSERT_TRUE(waitFor([&] { return emu.truth().watchdog; }, 6.0));
  EXPECT_GT(emu.truth().v, 0.15) << "a simulator's watchdog must not stop the robot";
  // SYNC0 while open counts as a PULSE: SIPs keep coming.
  raw.send(syncPacket(0));
  const Packet p = raw.next(2.0);
  EXPECT_FALSE(raw.timedOut());
  EXPECT_EQ(p.type, kSipStopped) << "a simulator always sends 0x32";
}

TEST(AriaDriverEmulator, StaleCommandStopsTheRobotWhileTheLinkStaysFed) {
  EmulatorProcess emu;
  ClientConfig config = clientConfig(emu.address());
  config.enable_motors = true;
  config.command_timeout = 0.6;
  auto client = connectClient(config);
  client->setVelocity({0.2, 0.0});
  ASSERT_TRUE(waitFor([&] { return emu.truth().v > 0.1; }, 5.0));
  // No new request: after 0.6 s the client sends zero; the link (and watchdog) stay fed.
  EXPECT_TRUE(waitFor([&] { return std::abs(emu.truth().v) < 1e-6; }, 4.0));
  EXPECT_FALSE(emu.truth().watchdog);
  EXPECT_EQ(client->status().link, LinkState::kConnected);
}

TEST(AriaDriverEmulator, NaNRequestsAreRefusedAndStopTheRobot) {
  EmulatorProcess emu;
  ClientConfig config = clientConfig(emu.address());
  config.enable_motors = true;
  auto client = connectClient(config);
  client->setVelocity({0.2, 0.0});
  ASSERT_TRUE(waitFor([&] { return emu.truth().v > 0.1; }, 5.0));
  client->setVelocity({std::nan(""), 0.0});
  EXPECT_TRUE(waitFor([&] { return std::abs(emu.truth().v) < 1e-6; }, 4.0));
  EXPECT_EQ(client->status().non_finite_requests, 1u);
}

class AriaReconnect : public ::testing::TestWithParam<bool> {};

TEST_P(AriaReconnect, ReconnectsAfterTheEmulatorIsKilledAndRestarted) {
  const bool pty = GetParam();
  const std::string link = ptyLink("reconnect");
  const int port = freePort();
  auto emu = std::make_unique<EmulatorProcess>(std::vector<std::string>{}, port, pty ? link : "");
  ClientConfig config = clientConfig(pty ? link : emu->address());
  config.enable_motors = true;
  auto client = connectClient(config);
  ASSERT_EQ(client->status().connections, 1u);
  emu->kill(SIGKILL);  // a crash: no goodbye on either side
  EXPECT_TRUE(waitFor([&] { return client->status().link != LinkState::kConnected; }, 10.0))
      << "link loss not detected";
  emu = std::make_unique<EmulatorProcess>(std::vector<std::string>{}, port, pty ? link : "");
  EXPECT_TRUE(waitFor([&] { return client->status().connections >= 2 && client->status().link == LinkState::kConnected; },
                      30.0))
      << client->status().last_error;
  // The new robot session gets its motors enabled again and accepts motion.
  client->setVelocity({0.2, 0.0});
  EXPECT_TRUE(waitFor([&] { return emu->truth().v > 0.1; }, 10.0));
}

INSTANTIATE_TEST_SUITE_P(Transports, AriaReconnect, ::testing::Values(false, true),
                         [](const auto& info) { return std::string(info.param ? "pty" : "tcp"); });

class AriaStillOpen : public ::testing::TestWithParam<bool> {};

TEST_P(AriaStillOpen, RecoversARobotLeftOpenByAnEarlierClient) {
  const bool pty = GetParam();
  const std::string link = ptyLink("open");
  EmulatorProcess emu({}, 0, pty ? link : "");
  {
    RawClient earlier = pty ? RawClient::pty(link) : RawClient::tcp(emu.tcpPort());
    ASSERT_TRUE(earlier.ok());
    ASSERT_TRUE(earlier.handshakeAndOpen());
    ASSERT_TRUE(waitFor([&] { return emu.truth().open; }, 5.0));
  }  // gone without CLOSE: firmware keeps streaming SIPs
  ASSERT_TRUE(emu.truth().open);
  auto client = connectClient(clientConfig(pty ? link : emu.address()));
  EXPECT_GE(client->status().still_open_recoveries, 1u);
  EXPECT_EQ(client->status().connections, 1u);
}

INSTANTIATE_TEST_SUITE_P(Transports, AriaStillOpen, ::testing::Values(false, true),
                         [](const auto& info) { return std::string(info.param ? "pty" : "tcp"); });

TEST(AriaDriverEmulator, SimulatorMotorsFollowTheRequestAndCloseDropsTheSocket) {
  EmulatorProcess emu({"--simulator-mode"});
  auto client = connectClient(clientConfig(emu.address()));
  // Motors start enabled in a simulator; nobody asked for them, so the driver disables them.
  EXPECT_TRUE(waitFor([&] { return !emu.truth().motors; }, 5.0));
  client->requestMotors(true);
  EXPECT_TRUE(waitFor([&] { return emu.truth().motors; }, 5.0));
  EXPECT_TRUE(waitFor([&] { const auto s = client->status(); return s.robot && s.robot->motors_enabled; }, 5.0));
  client->stop();
  EXPECT_TRUE(waitFor([&] { return !emu.truth().open; }, 5.0));
}

// A noisy serial line (user problem #1: bad checksums): a fifth of the robot's packets are
// damaged. The parser resynchronises, the link stays up and odometry still matches the
// ground truth, because SIP positions are absolute (a lost SIP loses no motion).
TEST(AriaDriverEmulator, NoisyLineKeepsTheLinkAndTheOdometry) {
  const std::string link = ptyLink("noisy");
  EmulatorProcess emu({"--corrupt", "0.2"}, 0, link);
  ClientConfig config = clientConfig(link);
  config.enable_motors = true;
  auto client = connectClient(config);
  client->setVelocity({0.2, 0.3});
  std::this_thread::sleep_for(std::chrono::seconds(3));
  client->setVelocity({0.0, 0.0});
  waitStopped(emu);
  const ClientStatus s = client->status();
  EXPECT_GT(s.parser.errors() + s.parser.garbage_bytes, 0u) << "the line was not noisy";
  EXPECT_EQ(s.connections, 1u) << "the link dropped: " << s.last_error;
  const Truth truth = emu.truth();
  const Pose2 est = odom(*client);
  EXPECT_GT(std::hypot(truth.pose.x, truth.pose.y), 0.2);
  EXPECT_NEAR(est.x, truth.pose.x, 0.01);
  EXPECT_NEAR(est.y, truth.pose.y, 0.01);
  EXPECT_NEAR(wrapAngle(est.theta - truth.pose.theta), 0.0, 0.01);
}

// The emulator's --time-scale (for faster-than-real-time runs) keeps the protocol intact:
// SIPs arrive proportionally faster and the driver follows.
TEST(AriaDriverEmulator, TimeScaledEmulatorStillDrives) {
  EmulatorProcess emu({"--time-scale", "3"});
  ClientConfig config = clientConfig(emu.address());
  config.enable_motors = true;
  auto client = connectClient(config);
  EXPECT_TRUE(waitFor([&] { return client->status().sip_rate > 20.0; }, 5.0)) << client->status().sip_rate;
  client->setVelocity({0.2, 0.0});
  EXPECT_TRUE(waitFor([&] { return odom(*client).x > 0.2; }, 10.0));
  client->setVelocity({0.0, 0.0});
  waitStopped(emu);
  EXPECT_NEAR(odom(*client).x, emu.truth().pose.x, 0.01);
}

// OPEN is sent with ARIA's int argument by default; p2os sends it bare. Both must open.
TEST(AriaDriverEmulator, BareOpenAlsoOpensTheRobot) {
  EmulatorProcess emu;
  ClientConfig config = clientConfig(emu.address());
  config.open_with_argument = false;
  auto client = connectClient(config);
  EXPECT_TRUE(emu.truth().open);
  EXPECT_GT(client->status().sips, 0u);
}

// The error names the port and MRPT's message (not a backtrace frame), and reaches the log as
// an ERROR (before: a WARN ending in "[6 ]  0x7f53...").
TEST(AriaDriverEmulator, GivesUpOnASilentPortWithAReadableError) {
  const int port = freePort();  // nobody listens here
  ClientConfig config = clientConfig("127.0.0.1:" + std::to_string(port));
  std::mutex mutex;
  std::vector<std::string> errors;
  AriaClient client(config, [&](LogLevel level, const std::string& text) {
    std::lock_guard<std::mutex> lock(mutex);
    if (level == LogLevel::kError) errors.push_back(text);
  });
  client.start();
  EXPECT_TRUE(waitFor([&] { return !client.status().last_error.empty(); }, 10.0));
  EXPECT_NE(client.status().last_error.find(std::to_string(port)), std::string::npos) << client.status().last_error;
  EXPECT_NE(client.status().last_error.find("Connection refused"), std::string::npos) << client.status().last_error;
  EXPECT_EQ(client.status().last_error.find("0x"), std::string::npos) << client.status().last_error;
  EXPECT_TRUE(waitFor([&] {
    std::lock_guard<std::mutex> lock(mutex);
    return !errors.empty();
  }, 5.0)) << "no ERROR about the robot link";
  {
    std::lock_guard<std::mutex> lock(mutex);
    ASSERT_FALSE(errors.empty());
    EXPECT_NE(errors[0].find("robot link tcp 127.0.0.1:" + std::to_string(port) + " down: cannot connect: "), std::string::npos)
        << errors[0];
  }
  EXPECT_NE(client.status().link, LinkState::kConnected);
  client.stop();
  EXPECT_EQ(client.status().link, LinkState::kStopped);
}

// TicksMM from the client's parameters reaches the firmware, comes back in CONFIGpac and
// changes the odometry's scale: twice the encoders' ticks per mm halves every distance.
TEST(AriaDriverEmulator, TicksMmFromTheParametersChangesTheOdometryScale) {
  EmulatorProcess emu;
  ClientConfig config = clientConfig(emu.address());
  config.enable_motors = true;
  config.ticks_mm = 256;  // the emulator's encoders: 128 ticks/mm
  auto client = connectClient(config);
  ASSERT_TRUE(client->status().config);
  EXPECT_EQ(client->status().config->ticks_mm, 256);
  ASSERT_TRUE(waitFor([&] { return emu.truth().motors; }, 10.0));
  client->setVelocity({0.2, 0.0});
  EXPECT_TRUE(waitFor([&] { return emu.truth().pose.x > 0.3; }, 10.0));
  client->setVelocity({0.0, 0.0});
  waitStopped(emu);
  EXPECT_NEAR(odom(*client).x, 0.5 * emu.truth().pose.x, 0.01);
}
