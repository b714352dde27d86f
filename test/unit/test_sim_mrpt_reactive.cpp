// The MRPT peer (sim_mrpt/reactive_law.h) in the offline closed loop: real MRPT navigator, the
// simulator's unicycle and clock, disks seen as laser points.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <mrpt/core/Clock.h>

#include "amigobot_tracking/core/robot/offset_point.h"
#include "amigobot_tracking/sim/closed_loop.h"
#include "amigobot_tracking/sim/monte_carlo.h"
#include "amigobot_tracking/sim/scenario.h"
#include "amigobot_tracking/sim/simulator.h"
#include "amigobot_tracking/sim_mrpt/reactive_law.h"

using namespace amigobot_tracking;

namespace {

class StaticGoal : public core::Reference {
 public:
  explicit StaticGoal(const Eigen::Vector2d& goal) : goal_(goal) {}
  core::ReferenceState at(double) const override { return {goal_, Eigen::Vector2d::Zero()}; }

 private:
  Eigen::Vector2d goal_;
};

sim::ClosedLoopSetup staticSetup() {
  sim::ClosedLoopSetup setup;
  core::ControllerConfig& c = setup.controller;
  c.robot_radius = 0.18;
  c.offset = 0.3;
  c.v_max = 0.6;
  c.w_max = 1.6;
  c.body_safe = true;
  setup.initial_pose = {0.0, 0.0, 0.0};
  setup.obstacles = {core::Disk{{2.0, 0.05}, 0.3}};  // between the start and the goal
  setup.duration = 40.0;
  setup.control_period = 0.01;
  setup.law = "mrpt_reactive";
  sim_mrpt::provideReactiveLaw();  // the registry's mrpt_reactive
  return setup;
}

// The shipped dead end (the robot faces the pocket's end, the target walks away behind it),
// run by MRPT's navigator with these options.
sim::Scenario deadEnd(const sim_mrpt::ReactiveLawOptions& options) {
  sim::Scenario scenario = sim::loadScenario(std::string(AMIGOBOT_SOURCE_DIR) + "/config/scenarios/dead_end_away.yaml",
                                             {"controller.variant=mrpt_reactive"});
  sim_mrpt::provideReactiveLaw(options);
  return scenario;
}

}  // namespace

// Facing away from the target in a dead end, MRPT 2.5's navigator failed every step with
// ERR201 (its score formulas compiled from a PTG that cannot reach a target behind) and the
// robot never moved (true ASE 11.8 m2, a 25 s stall). Primed, it backs out, turns round and
// follows (it ends 3.8 m behind its start).
TEST(MrptReactive, LeavesADeadEndFacingAwayFromTheTarget) {
  const sim::Scenario scenario = deadEnd(sim_mrpt::ReactiveLawOptions());
  const auto reference = scenario.makeReference();
  core::Pose2 last = scenario.setup.initial_pose;
  const sim::ClosedLoopSummary s =
      sim::runClosedLoop(scenario.setup, *reference, [&](const sim::ClosedLoopStep& step) { last = step.pose; });
  EXPECT_LT(last.x, -1.0);  // out of the pocket (it opens at x = -0.3) and after the target
  EXPECT_LT(s.metrics.true_ase, 5.0);  // 2.56 m2 measured: it backs out and turns round in 14 s
  EXPECT_LT(s.metrics.longest_stall, 10.0);
  EXPECT_EQ(s.metrics.body_collisions, 0u);
}

// A navigator error ends the run naming MRPT's reason, here MRPT's own failure without the
// priming; a Monte Carlo batch with such a run fails too (on any thread) instead of scoring
// robots that never moved.
TEST(MrptReactive, ANavigatorErrorFailsTheRunNamingIt) {
  sim_mrpt::ReactiveLawOptions unprimed;
  unprimed.prime_scores = false;
  const sim::Scenario scenario = deadEnd(unprimed);
  const auto reference = scenario.makeReference();
  try {
    sim::runClosedLoop(scenario.setup, *reference);
    ADD_FAILURE() << "the run ended normally";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("mrpt_reactive: MRPT's navigator failed at t = 0 s"), std::string::npos) << what;
    EXPECT_NE(what.find("ERR201"), std::string::npos) << what;
  }
  sim::MonteCarloOptions batch;
  batch.runs = 3;
  batch.jobs = 2;
  EXPECT_THROW(sim::summarizeMonteCarlo(scenario, batch), std::runtime_error);
}

TEST(MrptReactive, ReachesAStaticGoalBehindADiskWithoutTouchingIt) {
  const sim::ClosedLoopSetup setup = staticSetup();
  ASSERT_EQ(sim::validateSetup(setup), "");
  const Eigen::Vector2d goal(4.0, 0.0);
  double worst_diamond = 0.0;
  core::Pose2 last;
  const sim::ClosedLoopSummary s = sim::runClosedLoop(setup, StaticGoal(goal), [&](const sim::ClosedLoopStep& step) {
    worst_diamond = std::max(worst_diamond, std::abs(step.output.u.v) / 0.6 + std::abs(step.output.u.omega) / 1.6);
    last = step.pose;
  });
  EXPECT_LT((last.position() - goal).norm(), setup.controller.offset + 0.1);  // ended within r (+ one period)
  EXPECT_GT(s.min_clearance_body, 0.0);                                       // never touched the disk
  EXPECT_EQ(s.metrics.body_collisions, 0u);
  EXPECT_EQ(s.diamond_violations, 0u);
  EXPECT_LE(worst_diamond, 1.0 + 1e-9);
  EXPECT_EQ(s.invalid_steps, 0u);
  // It went round the disk, not through it: the path left the x axis.
  EXPECT_GT(s.metrics.max_true_error, 0.0);
}

TEST(MrptReactive, MovingTargetGivesFiniteMetricsInsideTheDiamond) {
  sim::Scenario scenario =
      sim::loadScenario(std::string(AMIGOBOT_SOURCE_DIR) + "/config/scenarios/saddle_line.yaml",
                        {"controller.variant=mrpt_reactive"});
  sim_mrpt::provideReactiveLaw();
  const core::DiamondSet diamond(scenario.setup.controller.v_max, scenario.setup.controller.w_max);
  int outside = 0, moving = 0;
  const auto reference = scenario.makeReference();
  const sim::ClosedLoopSummary s = sim::runClosedLoop(scenario.setup, *reference, [&](const sim::ClosedLoopStep& step) {
    if (!diamond.contains(step.output.u, sim::kDiamondTolerance)) ++outside;
    if (step.output.u.v != 0.0 || step.output.u.omega != 0.0) ++moving;
  });
  const sim::RunMetrics& m = s.metrics;
  EXPECT_EQ(outside, 0);
  EXPECT_EQ(m.diamond_violations, 0u);
  EXPECT_EQ(m.nan_count, 0u);
  EXPECT_GT(moving, 100);
  for (double x : {m.ase, m.aae, m.tec, m.true_ase, m.max_true_error, m.longest_stall, m.min_clearance_body})
    EXPECT_TRUE(std::isfinite(x)) << x;
  EXPECT_GT(m.ase, 0.0);
  // The target runs 9 m in 30 s at half the robot's top speed: the peer follows it.
  EXPECT_LT(m.final_error, 3.0);
}

TEST(MrptReactive, RefusedWithoutTheLibraryAndRestoresMrptsClock) {
  sim::ClosedLoopSetup setup = staticSetup();
  const core::LawFactory registered = core::provideLaw("mrpt_reactive", nullptr);
  EXPECT_THROW(sim::runClosedLoop(setup, StaticGoal({1.0, 0.0})), std::invalid_argument);
  core::provideLaw("mrpt_reactive", registered);
  setup.duration = 0.2;
  sim::runClosedLoop(setup, StaticGoal({1.0, 0.0}));
  EXPECT_EQ(mrpt::Clock::getActiveClock(), mrpt::Clock::Realtime);
}

// MRPT's clock is one per process while a batch runs its laws on several threads: the
// figures must not depend on the number of jobs, and the clock is MRPT's own afterwards.
TEST(MrptReactive, ABatchGivesTheSameFiguresOnOneOrTwoJobsAndRestoresTheClock) {
  sim::Scenario scenario =
      sim::loadScenario(std::string(AMIGOBOT_SOURCE_DIR) + "/config/scenarios/pedestrians/crossing_ahead.yaml",
                        {"controller.variant=mrpt_reactive"});
  sim_mrpt::provideReactiveLaw();
  sim::MonteCarloOptions batch;
  batch.runs = 4;
  batch.jobs = 1;
  const sim::MonteCarloSummary one = sim::summarizeMonteCarlo(scenario, batch);
  EXPECT_EQ(mrpt::Clock::getActiveClock(), mrpt::Clock::Realtime);
  batch.jobs = 2;
  const sim::MonteCarloSummary two = sim::summarizeMonteCarlo(scenario, batch);
  EXPECT_EQ(mrpt::Clock::getActiveClock(), mrpt::Clock::Realtime);
  ASSERT_EQ(one.per_run.size(), two.per_run.size());
  for (std::size_t i = 0; i < one.per_run.size(); ++i) {
    EXPECT_EQ(one.per_run[i].metrics.true_ase, two.per_run[i].metrics.true_ase) << "run " << i;
    EXPECT_EQ(one.per_run[i].metrics.min_clearance_body, two.per_run[i].metrics.min_clearance_body) << "run " << i;
  }
}

TEST(MrptReactive, ConfigUsesTheDiamondCornersAndTheBody) {
  core::ControllerConfig c;
  c.v_max = 0.3;
  c.w_max = 0.8;
  c.robot_radius = 0.18;
  const std::string ini = sim_mrpt::reactiveConfigText(c, sim_mrpt::ReactiveLawOptions());
  EXPECT_NE(ini.find("robotMax_V_mps = 0.3\n"), std::string::npos);
  EXPECT_NE(ini.find("PTG0_Type = CPTG_DiffDrive_alpha"), std::string::npos);
  EXPECT_NE(ini.find("holonomic_method = CHolonomicND"), std::string::npos);
  EXPECT_NE(ini.find("RobotModel_shape2D_xs = 0.18"), std::string::npos);  // 16-gon vertex at R / cos(pi/16)
}
