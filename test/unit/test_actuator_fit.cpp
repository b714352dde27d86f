// amigobot_sim --identify's fitter on emulator runs with non-default firmware values: the
// client changes the ramps with SETA / SETRA, the robot's ceiling is 0.6 m/s, and the fit of
// the commands and the SIP velocities recovers ramps, latency and wheel limit within 10 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "amigobot_tracking/aria/commands.h"
#include "amigobot_tracking/aria/emulator.h"
#include "amigobot_tracking/aria/sip.h"
#include "amigobot_tracking/sim/actuator_fit.h"
#include "amigobot_tracking/sim/robot_description.h"
#include "aria_packets.h"

using namespace amigobot_tracking;
using amigobot_test::openRobot;
using amigobot_test::packetOf;

namespace {

constexpr double kDegToRad = M_PI / 180.0;

struct Segment {
  double until;  // [s]
  int vel_mm_s, rvel_deg_s;
};
// Starts, stops and reversals on each axis, then a turn the wheel limit cuts.
const std::vector<Segment> kSequence = {{2.5, 400, 0},  {5.0, 0, 0},  {7.5, -300, 0}, {10.0, 0, 0},
                                        {12.5, 0, 90},  {15.0, 0, 0}, {17.5, 0, -90}, {20.0, 0, 0},
                                        {23.0, 500, 120}, {26.0, 0, 0}};

// An emulator run: commands about every 0.1 s at drifting phases against the firmware's cycle
// (as a 10 Hz cmd_vel does), the SIP wheel velocities as the odometry.
sim::ActuatorRecording emulatorRun(const aria::RobotParams& params) {
  aria::EmulatorOptions options;
  options.robot = params;
  aria::RobotEmulator robot(options);
  openRobot(robot, 0.0);
  robot.handle(packetOf(aria::commandPacket(aria::Command::kEnable, 1)), 0.0);
  robot.handle(packetOf(aria::commandPacket(aria::Command::kSetA, 500)), 0.0);    // accel 0.5 m/s^2
  robot.handle(packetOf(aria::commandPacket(aria::Command::kSetA, -1000)), 0.0);  // decel 1.0 m/s^2
  robot.handle(packetOf(aria::commandPacket(aria::Command::kSetRA, 150)), 0.0);   // 150 deg/s^2
  robot.handle(packetOf(aria::commandPacket(aria::Command::kSetRA, -200)), 0.0);  // 200 deg/s^2
  sim::ActuatorRecording r;
  r.half_track = params.halfTrack();
  double next_command = 0.05;
  int k = 0;
  for (double t = 0.0; t < kSequence.back().until; t += 0.001) {
    if (const auto bytes = robot.advance(t); !bytes.empty()) {
      const aria::Sip sip = aria::decodeSip(packetOf(bytes)).value();
      const double left = sip.left_vel * params.vel_conv_factor * 1e-3, right = sip.right_vel * params.vel_conv_factor * 1e-3;
      r.odometry.push_back({t, {0.5 * (left + right), 0.5 * (right - left) / params.halfTrack()}});
    }
    if (t >= next_command) {
      int vel = 0, rvel = 0;
      for (const Segment& s : kSequence)
        if (t < s.until) {
          vel = s.vel_mm_s, rvel = s.rvel_deg_s;
          break;
        }
      robot.handle(packetOf(aria::commandPacket(aria::Command::kVel, vel)), t);
      robot.handle(packetOf(aria::commandPacket(aria::Command::kRVel, rvel)), t);
      r.commands.push_back({t, {vel * 1e-3, rvel * kDegToRad}});
      next_command += 0.1 + 0.013 * ((++k * 7) % 5);  // 100-152 ms apart
    }
  }
  return r;
}

void expectWithin10(double fitted, double truth, const char* name) {
  EXPECT_NEAR(fitted, truth, 0.1 * truth) << name;
}

}  // namespace

TEST(ActuatorFit, RecoversTheFirmwaresValuesFromAnEmulatorRun) {
  aria::RobotParams params = aria::builtinRobotParams("amigo");
  params.dynamics.max_velocity = 0.6;  // the wheel ceiling, below the 0.68 m/s the last turn asks
  const sim::ActuatorRecording run = emulatorRun(params);
  ASSERT_GT(run.odometry.size(), 200u);
  const sim::ActuatorFit fit = sim::fitActuator(run);
  const core::ActuatorLimits& l = fit.dynamics.limits;
  std::printf("fit: accel %.3f decel %.3f rot %.3f / %.3f latency %.3f cycle %.3f max_velocity %.3f rms %.4f\n",
              l.trans_accel, l.trans_decel, l.rot_accel, l.rot_decel, l.latency, l.cycle, l.max_velocity, fit.rms_error);
  expectWithin10(l.trans_accel, 0.5, "trans_accel");
  expectWithin10(l.trans_decel, 1.0, "trans_decel");
  expectWithin10(l.rot_accel, 150 * kDegToRad, "rot_accel");
  expectWithin10(l.rot_decel, 200 * kDegToRad, "rot_decel");
  expectWithin10(l.latency, core::ActuatorLimits{}.latency, "latency");
  expectWithin10(l.cycle, params.dynamics.cycle, "cycle");
  EXPECT_TRUE(fit.wheel_limit_seen);
  expectWithin10(l.max_velocity, 0.6, "max_velocity");
  // The YAML it writes is what the simulator reads.
  const sim::RobotDynamics back = sim::parseRobotDynamics(sim::robotDynamicsYaml(fit.dynamics, "fitted"), "fitted");
  EXPECT_NEAR(back.limits.trans_accel, l.trans_accel, 1e-5 * l.trans_accel);
}

TEST(ActuatorFit, TooLittleOrBrokenDataIsNamed) {
  sim::ActuatorRecording r;
  r.commands = {{0.0, {0.1, 0.0}}, {1.0, {0.0, 0.0}}};
  EXPECT_THROW(sim::fitActuator(r), std::invalid_argument);  // no odometry
  for (int i = 0; i < 30; ++i) r.odometry.push_back({0.1 * i, {0.0, 0.0}});
  r.odometry[5].t = -1.0;
  try {
    sim::fitActuator(r);
    FAIL() << "accepted time going back";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("odometry"), std::string::npos) << e.what();
  }
  const std::string csv = ::testing::TempDir() + "bad_run.csv";
  std::ofstream(csv) << "cmd,0,0.1,0\nodom,zero,0,0\n";
  EXPECT_THROW(sim::readActuatorCsv(csv), std::runtime_error);
}
