// The emulator's firmware logic in-process (no I/O): handshake stages, OPEN/CLOSE, VEL2
// decoding, the watchdog in both modes, sonar from disks, walls and polygons, SIP tails per model.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/aria/emulator.h"
#include "amigobot_tracking/aria/odometry.h"
#include "aria_packets.h"

using namespace amigobot_tracking::aria;
using amigobot_test::openRobot;
using amigobot_test::packetOf;

namespace {
std::optional<Sip> sipAt(RobotEmulator& robot, double t) {
  const auto bytes = robot.advance(t);
  if (bytes.empty()) return std::nullopt;
  return decodeSip(packetOf(bytes));
}
}  // namespace

TEST(AriaEmulator, HandshakeTellsSync1FromOpenByItsStage) {
  RobotEmulator robot({});
  // OPEN before any SYNC is a stray SYNC1: ignored, the robot stays closed.
  robot.handle(packetOf(commandPacket(Command::kOpen, 1)), 0.0);
  EXPECT_FALSE(robot.isOpen());
  EXPECT_TRUE(robot.advance(0.5).empty()) << "nothing is sent before OPEN";
  EXPECT_EQ(openRobot(robot, 1.0), (std::vector<int>{0, 1, 2}));
  EXPECT_TRUE(robot.isOpen());
  EXPECT_FALSE(robot.motorsEnabled()) << "firmware: motors off until ENABLE";
  const auto sync2 = robot.handle(packetOf(syncPacket(2)), 1.0);  // = CLOSE while open
  EXPECT_TRUE(sync2.empty());
  EXPECT_FALSE(robot.isOpen());
}

TEST(AriaEmulator, SipsEveryCycleWithTheModelsTail) {
  for (const char* model : {"amigo", "amigo-sh"}) {
    EmulatorOptions o;
    o.robot = builtinRobotParams(model);
    RobotEmulator robot(o);
    openRobot(robot, 0.0);
    int sips = 0;
    std::optional<Sip> last;
    for (double t = 0.0; t < 1.0 - 1e-9; t += 0.01) {
      if (auto s = sipAt(robot, t)) {
        ++sips;
        last = s;
      }
    }
    EXPECT_EQ(sips, 10) << model;
    ASSERT_TRUE(last);
    EXPECT_TRUE(last->digout) << model;
    EXPECT_EQ(last->battery_x10.has_value(), std::string(model) == "amigo-sh") << model;
    EXPECT_FALSE(last->rot_vel) << model;
  }
}

// A command arriving when a SIP is due must not swallow it: the server hands every packet
// to handle() and then calls advance(), and the SIP was made inside handle() and dropped
// with the (empty) reply, so odom lost a SIP whenever a command woke the server late (the
// e2e rates test saw 7.5 Hz on a loaded machine). Here every SIP falls due just before a
// VEL + RVEL pair, as when the driver sends its setpoints at 20 Hz.
TEST(AriaEmulator, ACommandWhenASipIsDueDoesNotSwallowIt) {
  RobotEmulator robot({});
  openRobot(robot, 0.0);
  ASSERT_TRUE(sipAt(robot, 0.0)) << "first SIP at OPEN";
  robot.handle(packetOf(commandPacket(Command::kEnable, 1)), 0.0);
  int sips = 0;
  for (int k = 1; k <= 100; ++k) {
    const double t = 0.1 * k + 0.003;  // 3 ms after the SIP fell due
    EXPECT_TRUE(robot.handle(packetOf(commandPacket(Command::kVel, 100)), t).empty()) << "VEL has no reply";
    EXPECT_TRUE(robot.handle(packetOf(commandPacket(Command::kRVel, 10)), t).empty()) << "RVEL has no reply";
    if (sipAt(robot, t)) {
      ++sips;
    } else {
      ADD_FAILURE() << "SIP due at " << 0.1 * k << " s not sent by advance(" << t << ")";
    }
  }
  EXPECT_EQ(sips, 100);
  EXPECT_EQ(robot.counters().sips_sent, 101u) << "every SIP counted as sent was returned";
}

TEST(AriaEmulator, Vel2DrivesTheWheelsItEncodes) {
  RobotEmulator robot({});
  openRobot(robot, 0.0);
  robot.handle(packetOf(commandPacket(Command::kEnable, 1)), 0.0);
  robot.handle(packetOf(vel2Packet(-5, 10)), 0.0);  // left -100 mm/s, right +200 mm/s
  robot.advance(1.9);
  const double b = robot.options().robot.halfTrack();
  EXPECT_NEAR(robot.trueTwist().v, 0.05, 1e-9);
  EXPECT_NEAR(robot.trueTwist().omega, 0.15 / b, 1e-9);
}

TEST(AriaEmulator, FirmwareWatchdogStopsAndResumesSimulatorOnlyWarns) {
  for (bool simulator : {false, true}) {
    EmulatorOptions o;
    o.simulator_mode = simulator;
    RobotEmulator robot(o);
    openRobot(robot, 0.0);
    robot.handle(packetOf(commandPacket(Command::kEnable, 1)), 0.0);
    robot.handle(packetOf(commandPacket(Command::kVel, 200)), 0.0);
    robot.advance(1.5);
    EXPECT_NEAR(robot.trueTwist().v, 0.2, 1e-9);
    robot.advance(3.0);  // 3 s without a command
    EXPECT_TRUE(robot.watchdogTripped());
    EXPECT_NEAR(robot.trueTwist().v, simulator ? 0.2 : 0.0, 1e-9) << "simulator " << simulator;
    robot.handle(packetOf(commandPacket(Command::kPulse)), 3.0);
    robot.advance(4.0);
    EXPECT_NEAR(robot.trueTwist().v, 0.2, 1e-9) << "resumes the last setpoint";
  }
}

TEST(AriaEmulator, SimulatorStartsWithMotorsOnAndAlwaysSends0x32) {
  EmulatorOptions o;
  o.simulator_mode = true;
  RobotEmulator robot(o);
  openRobot(robot, 0.0);
  EXPECT_TRUE(robot.motorsEnabled());
  robot.handle(packetOf(commandPacket(Command::kVel, 300)), 0.0);
  robot.advance(1.5);
  const auto sip = sipAt(robot, 1.6);
  ASSERT_TRUE(sip);
  EXPECT_EQ(sip->type, kSipStopped);
  EXPECT_TRUE(sip->rot_vel);
  EXPECT_EQ(sip->sonars.size(), 8u);
  robot.clientDisconnected();
  EXPECT_FALSE(robot.isOpen()) << "a simulator closes the robot when its client goes";
}

TEST(AriaEmulator, SonarSeesADiskInFrontAndNothingBehind) {
  EmulatorOptions o;
  o.world.obstacles.push_back({{1.0, 0.0}, 0.2});
  RobotEmulator robot(o);
  const auto ranges = robot.sonarRanges();
  ASSERT_EQ(ranges.size(), 8u);
  // Transducers 2 and 3 face forward from x = 0.150 m: surface at 0.8 m, seen a bit obliquely.
  EXPECT_NEAR(ranges[2], std::hypot(1.0 - 0.15, 0.03) - 0.2, 1e-9);
  EXPECT_NEAR(ranges[3], ranges[2], 1e-9);
  EXPECT_DOUBLE_EQ(ranges[6], o.sonar_max_range);
  EXPECT_DOUBLE_EQ(ranges[0], o.sonar_max_range);
}

TEST(AriaEmulator, SonarSeesAWallAndATable) {
  EmulatorOptions o;
  o.world.walls.push_back({{-3.0, 1.0}, {3.0, 1.0}});  // a wall 1 m to the left
  RobotEmulator robot(o);
  std::vector<double> ranges = robot.sonarRanges();
  // Transducer 0 looks straight left (90 deg) from (0.076, 0.100): the wall is 0.9 m away.
  EXPECT_NEAR(ranges[0], 1.0 - o.robot.sonars[0].y, 1e-9);
  EXPECT_DOUBLE_EQ(ranges[5], o.sonar_max_range) << "the right side sees nothing";
  // A table ahead instead: its near edge at x = 1.2. Transducer 2 (15 deg) sees it first
  // along the edge of its cone nearest to the table's normal (15 deg - half cone).
  o.world.walls.clear();
  o.world.polygons.push_back({{{1.2, -0.5}, {2.0, -0.5}, {2.0, 0.5}, {1.2, 0.5}}});
  ranges = RobotEmulator(o).sonarRanges();
  const auto& front = o.robot.sonars[2];
  EXPECT_NEAR(ranges[2], (1.2 - front.x) / std::cos(front.yaw - o.sonar_half_cone), 1e-9);
  EXPECT_DOUBLE_EQ(ranges[0], o.sonar_max_range);
}

TEST(AriaEmulator, ConfigPacReportsTheLimitsAndSetaChangesThem) {
  RobotEmulator robot({});
  openRobot(robot, 0.0);
  robot.handle(packetOf(commandPacket(Command::kSetA, 1000)), 0.0);
  robot.handle(packetOf(commandPacket(Command::kSetA, -1200)), 0.0);
  const auto reply = robot.handle(packetOf(commandPacket(Command::kConfig, 1)), 0.0);
  const auto config = decodeConfigPac(packetOf(reply));
  ASSERT_TRUE(config);
  EXPECT_EQ(config->subtype, "amigo");
  EXPECT_EQ(config->trans_acc, 1000);
  EXPECT_EQ(config->trans_decel, 1200);
  EXPECT_EQ(config->watchdog, 2000);
}

TEST(AriaEmulator, InvalidOptionsAreRejectedByName) {
  EmulatorOptions o;
  o.world.obstacles.push_back({{0.0, 0.0}, -1.0});
  EXPECT_NE(o.validate().find("world.obstacles[0].radius"), std::string::npos) << o.validate();
  EXPECT_THROW(RobotEmulator robot(o), std::invalid_argument);
}

// The sonar scale is uncertain (ARIA/p2os: 1 mm per unit; AmigOS v1.3 manual: 0.555 mm per
// unit). Either reading round-trips when robot and driver agree, and a mismatch shows as a
// 0.555 scale error, which is what a real-robot check against a tape measure would reveal.
TEST(AriaEmulator, SonarScaleReadingsRoundTripAndAMismatchIsVisible) {
  for (double scale : {1.0, 0.555}) {
    EmulatorOptions o;
    o.simulator_mode = true;  // all eight transducers in every SIP
    o.robot.range_conv_factor = scale;
    o.world.obstacles.push_back({{1.0, 0.0}, 0.2});
    RobotEmulator robot(o);
    openRobot(robot, 0.0);
    const auto sip = sipAt(robot, 0.0);
    ASSERT_TRUE(sip);
    const SonarReading& front = sip->sonars.at(2);
    EXPECT_NEAR(sonarRange(front, o.robot), robot.sonarRanges()[2], 1e-3 * scale) << scale;
    RobotParams other = o.robot;
    other.range_conv_factor = scale == 1.0 ? 0.555 : 1.0;
    EXPECT_NEAR(sonarRange(front, other) / sonarRange(front, o.robot), other.range_conv_factor / scale, 1e-9);
  }
}

TEST(AriaEmulator, CommandLogJournalsEverySetpointPairAsDecoded) {
  RobotEmulator robot({});
  std::ostringstream log;
  robot.setCommandLog(&log);
  openRobot(robot, 0.0);
  robot.handle(packetOf(commandPacket(Command::kEnable, 1)), 0.0);
  robot.handle(packetOf(commandPacket(Command::kVel, 200)), 0.5);   // 0.2 m/s
  robot.handle(packetOf(commandPacket(Command::kRVel, -30)), 0.5);  // -30 deg/s
  robot.handle(packetOf(vel2Packet(-5, 10)), 1.0);
  robot.handle(packetOf(commandPacket(Command::kStop)), 1.5);
  std::istringstream lines(log.str());
  struct Row {
    double t;
    std::string command;
    double v, w;
  };
  std::vector<Row> rows;
  Row r;
  while (lines >> r.t >> r.command >> r.v >> r.w) rows.push_back(r);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].command, "VEL");
  EXPECT_NEAR(rows[0].v, 0.2, 1e-9);
  EXPECT_NEAR(rows[0].w, 0.0, 1e-9);
  EXPECT_EQ(rows[1].command, "RVEL");  // the pair the robot holds after the second packet
  EXPECT_NEAR(rows[1].v, 0.2, 1e-9);
  EXPECT_NEAR(rows[1].w, -30.0 * M_PI / 180.0, 1e-6);
  const double b = robot.options().robot.halfTrack();
  EXPECT_EQ(rows[2].command, "VEL2");
  EXPECT_NEAR(rows[2].v, 0.05, 1e-9);
  EXPECT_NEAR(rows[2].w, 0.15 / b, 1e-6);
  EXPECT_EQ(rows[3].command, "STOP");
  EXPECT_EQ(rows[3].v, 0.0);
  EXPECT_DOUBLE_EQ(rows[3].t, 1.5);
}

// A kidnap (aria/emulator_status.h's control socket, posted through the mailbox): the true
// pose jumps, the firmware's odometry must not. A twin driven alike but never moved sends the
// same odometry in every SIP, while the teleported one's truth carries on from the new pose.
TEST(AriaEmulator, ATeleportMovesTheTruthButNotTheOdometry) {
  RobotEmulator kidnapped({}), twin({});
  TeleportMailbox mailbox;
  kidnapped.setTeleportMailbox(&mailbox);
  for (RobotEmulator* robot : {&kidnapped, &twin}) {
    openRobot(*robot, 0.0);
    robot->handle(packetOf(commandPacket(Command::kEnable, 1)), 0.0);
    robot->handle(packetOf(commandPacket(Command::kVel, 200)), 0.0);
  }
  const amigobot_tracking::core::Pose2 there{2.0, 1.0, 3.0 * M_PI / 2.0};
  int compared = 0;
  double twin_x_at_teleport = 0.0;
  for (int k = 1; k <= 300; ++k) {
    const double t = 0.01 * k;
    if (k == 100) {
      mailbox.post(there);
      twin_x_at_teleport = twin.truePose().x;
    }
    const auto a = sipAt(kidnapped, t), b = sipAt(twin, t);
    ASSERT_EQ(a.has_value(), b.has_value()) << "t = " << t;
    if (!a) continue;
    ++compared;
    EXPECT_EQ(a->x, b->x) << "odometry jumped at t = " << t;
    EXPECT_EQ(a->y, b->y) << "odometry jumped at t = " << t;
    EXPECT_EQ(a->theta, b->theta) << "odometry jumped at t = " << t;
    EXPECT_EQ(a->left_vel, b->left_vel) << "the wheels changed at t = " << t;
  }
  EXPECT_GE(compared, 29);
  // From `there` (heading -pi/2 after the wrap) it drove on as far as the twin did meanwhile
  // along its x: the wheels carried on through the teleport.
  const double driven = twin.truePose().x - twin_x_at_teleport;
  EXPECT_GT(driven, 0.1) << "the twin never drove";
  const auto truth = kidnapped.truePose();
  EXPECT_NEAR(truth.x, 2.0, 1e-6);
  EXPECT_NEAR(truth.y, 1.0 - driven, 1e-6);
  EXPECT_NEAR(truth.theta, -M_PI / 2.0, 1e-9) << "heading not wrapped into (-pi, pi]";
  EXPECT_FALSE(mailbox.take()) << "the teleport was not taken";
  EXPECT_THROW(kidnapped.teleport({std::nan(""), 0.0, 0.0}), std::invalid_argument);
}

TEST(AriaEmulator, EncoderRequestIsAnsweredUnlessDeaf) {
  RobotEmulator robot({});
  TeleportMailbox control;
  robot.setTeleportMailbox(&control);
  openRobot(robot, 0.0);
  robot.handle(packetOf(commandPacket(Command::kEnable, 1)), 0.1);
  robot.handle(packetOf(commandPacket(Command::kVel, 200)), 0.1);
  for (double t = 0.1; t < 1.0; t += 0.01) robot.advance(t);
  const auto answer = robot.handle(packetOf(commandPacket(Command::kEncoder, 1)), 1.0);
  ASSERT_FALSE(answer.empty());
  const Packet p = packetOf(answer);
  EXPECT_EQ(p.type, kEncoderPacType);
  ASSERT_EQ(p.payload.size(), 8u);
  const auto left = static_cast<std::int32_t>(p.payload[0] | p.payload[1] << 8 | p.payload[2] << 16 | p.payload[3] << 24);
  EXPECT_GT(left, 0) << "the wheels turned forward";
  // Deaf: the packet is lost (no answer, no effect), SIPs still flow, the watchdog trips.
  control.setDeaf(true);
  EXPECT_TRUE(robot.handle(packetOf(commandPacket(Command::kEncoder, 1)), 1.05).empty());
  robot.handle(packetOf(commandPacket(Command::kVel, 0)), 1.05);
  int sips = 0;
  for (double t = 1.06; t < 3.5; t += 0.01) sips += !robot.advance(t).empty();
  EXPECT_GT(sips, 20);
  EXPECT_TRUE(robot.watchdogTripped());
  EXPECT_EQ(robot.counters().unheard_packets, 2u);
  EXPECT_NEAR(robot.trueTwist().v, 0.0, 1e-9) << "stopped by the watchdog, not by the unheard VEL 0";
  control.setDeaf(false);
  EXPECT_FALSE(robot.handle(packetOf(commandPacket(Command::kEncoder, 1)), 3.6).empty());
}

TEST(AriaEmulator, DeafControlLinesAreParsed) {
  bool deaf = false;
  EXPECT_EQ(parseDeafLine("deaf on", &deaf), "");
  EXPECT_TRUE(deaf);
  EXPECT_EQ(parseDeafLine("deaf off", &deaf), "");
  EXPECT_FALSE(deaf);
  EXPECT_NE(parseDeafLine("deaf", &deaf), "");
  EXPECT_NE(parseDeafLine("deaf maybe", &deaf), "");
  EXPECT_NE(parseDeafLine("deaf on now", &deaf), "");
}
