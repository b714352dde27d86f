// The simulator's body behind the robot's actuator model: scenario files default to the
// firmware's dynamics, the paper's Section 5 scenarios say `ideal`, a robot description's
// dynamics keys are read, and a firmware run's body ramps where the command jumps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

#include "amigobot_tracking/sim/robot_description.h"
#include "amigobot_tracking/sim/scenario.h"

using namespace amigobot_tracking;

namespace {

const std::string kScenarios = std::string(AMIGOBOT_SOURCE_DIR) + "/config/scenarios/";

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(SimDynamics, ScenariosDefaultToTheAmigoBotsFirmware) {
  const sim::Scenario s = sim::loadScenario(kScenarios + "clutter/doorway.yaml");
  EXPECT_FALSE(s.setup.dynamics.ideal);
  const core::ActuatorLimits amigo;
  EXPECT_EQ(s.setup.dynamics.limits.trans_accel, amigo.trans_accel);
  EXPECT_EQ(s.setup.dynamics.limits.latency, amigo.latency);
  EXPECT_TRUE(sim::loadScenario(kScenarios + "clutter/doorway.yaml", {"robot.dynamics=ideal"}).setup.dynamics.ideal);
  for (const char* paper : {"paper_5_1.yaml", "paper_5_2_rose.yaml", "experiment_5_3.yaml"})
    EXPECT_TRUE(sim::loadScenario(kScenarios + paper).setup.dynamics.ideal) << paper << " must stay the paper's unicycle";
}

TEST(SimDynamics, AnUnknownDynamicsIsNamed) {
  try {
    sim::loadScenario(kScenarios + "clutter/doorway.yaml", {"robot.dynamics=magic"});
    FAIL() << "accepted robot.dynamics=magic";
  } catch (const sim::ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("robot.dynamics"), std::string::npos) << e.what();
  }
}

TEST(SimDynamics, TheRobotDescriptionGivesTheDynamics) {
  // The shipped AmigoBot file holds the model's defaults.
  const sim::RobotDynamics amigo = sim::loadRobotDynamics(std::string(AMIGOBOT_SOURCE_DIR) + "/config/robots/amigo.yaml");
  const core::ActuatorLimits defaults;
  EXPECT_EQ(amigo.limits.trans_decel, defaults.trans_decel);
  EXPECT_EQ(amigo.limits.rot_accel, defaults.rot_accel);
  EXPECT_EQ(amigo.limits.max_velocity, defaults.max_velocity);
  EXPECT_EQ(amigo.limits.cycle, defaults.cycle);
  EXPECT_NEAR(amigo.half_track, core::kAmigoHalfTrack, 1e-12);
  // A lab's file, named relative to the scenario.
  const std::string robot = writeTemp("lab_robot.yaml", "model: amigo\ntrans_accel: 0.5\nlatency: 0.2\ndiff_conv_factor: 0.01\n");
  const sim::Scenario s = sim::loadScenario(kScenarios + "clutter/doorway.yaml", {"robot.description=" + robot});
  EXPECT_EQ(s.setup.dynamics.limits.trans_accel, 0.5);
  EXPECT_EQ(s.setup.dynamics.limits.latency, 0.2);
  EXPECT_NEAR(s.setup.dynamics.half_track, 0.1, 1e-12);
  // What --identify writes reads back the same.
  const sim::RobotDynamics back = sim::parseRobotDynamics(sim::robotDynamicsYaml(s.setup.dynamics, "test"), "round trip");
  EXPECT_NEAR(back.limits.trans_accel, 0.5, 1e-6);
  EXPECT_NEAR(back.limits.latency, 0.2, 1e-6);
  EXPECT_NEAR(back.half_track, 0.1, 1e-6);
  // A bad value is named with the file.
  const std::string bad = writeTemp("bad_robot.yaml", "trans_decel: -1\n");
  try {
    sim::loadRobotDynamics(bad);
    FAIL() << "accepted trans_decel -1";
  } catch (const sim::ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("trans_decel"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad_robot.yaml"), std::string::npos) << e.what();
  }
  EXPECT_THROW(sim::loadRobotDynamics(writeTemp("word.yaml", "latency: soon\n")), sim::ScenarioError);
  // A ramp may be .inf (no limit); NaN is refused by name.
  EXPECT_EQ(sim::parseRobotDynamics("trans_accel: .inf\n", "inf.yaml").limits.trans_accel,
            std::numeric_limits<double>::infinity());
  try {
    sim::parseRobotDynamics("latency: .nan\n", "nan.yaml");
    FAIL() << "accepted latency NaN";
  } catch (const sim::ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("nan.yaml:1: latency"), std::string::npos) << e.what();
  }
  EXPECT_THROW(sim::loadScenario(kScenarios + "clutter/doorway.yaml", {"robot.description=/no/such/robot.yaml"}),
               sim::ScenarioError);
}

TEST(SimDynamics, TheFirmwareBodyRampsWhereTheCommandJumps) {
  sim::Scenario s = sim::loadScenario(kScenarios + "clutter/doorway.yaml");
  s.setup.duration = 6.0;
  const auto reference = s.makeReference();
  const core::ActuatorLimits& l = s.setup.dynamics.limits;
  double largest_dv = 0.0, largest_dw = 0.0, largest_command_dv = 0.0, moved_before = 0.0, worst_wheel = 0.0;
  core::Twist2 last_body, last_command;
  double first_command = -1.0;
  sim::runClosedLoop(s.setup, *reference, [&](const sim::ClosedLoopStep& step) {
    const core::Twist2 body = step.body_velocity;
    largest_dv = std::max(largest_dv, std::abs(body.v - last_body.v) / std::max(step.h, s.setup.control_period));
    largest_dw = std::max(largest_dw, std::abs(body.omega - last_body.omega) / std::max(step.h, s.setup.control_period));
    largest_command_dv = std::max(largest_command_dv, std::abs(step.output.u.v - last_command.v));
    worst_wheel = std::max(worst_wheel, std::abs(body.v) + s.setup.dynamics.half_track * std::abs(body.omega));
    if (first_command < 0.0 && std::abs(step.output.u.v) > 1e-3) first_command = step.t;
    if (first_command >= 0.0 && step.t < first_command + l.latency - 1e-9)
      moved_before = std::max(moved_before, std::abs(body.v));
    last_body = body;
    last_command = step.output.u;
  });
  ASSERT_GE(first_command, 0.0);
  EXPECT_GT(largest_command_dv, 0.05) << "the command should jump for this test to mean anything";
  // The body never changes faster than the firmware's largest rates (one step's rounding).
  EXPECT_LE(largest_dv, std::max(l.trans_accel, l.trans_decel) + 1e-6);
  EXPECT_LE(largest_dw, std::max(l.rot_accel, l.rot_decel) + 1e-6);
  EXPECT_LE(worst_wheel, l.max_velocity + 1e-9);
  EXPECT_EQ(moved_before, 0.0) << "the body moved within the latency of the first command";
  // The ideal body follows the command at once: the same run lands elsewhere.
  sim::Scenario ideal = sim::loadScenario(kScenarios + "clutter/doorway.yaml", {"robot.dynamics=ideal"});
  ideal.setup.duration = s.setup.duration;
  core::Pose2 end_firmware, end_ideal;
  sim::runClosedLoop(s.setup, *reference, [&](const sim::ClosedLoopStep& step) { end_firmware = step.pose; });
  sim::runClosedLoop(ideal.setup, *reference, [&](const sim::ClosedLoopStep& step) {
    end_ideal = step.pose;
    EXPECT_EQ(step.body_velocity.v, step.output.u.v);
  });
  EXPECT_GT(std::hypot(end_firmware.x - end_ideal.x, end_firmware.y - end_ideal.y), 0.01);
}
