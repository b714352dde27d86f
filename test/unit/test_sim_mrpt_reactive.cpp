// The MRPT peer (sim_mrpt/reactive_law.h) in the offline closed loop: real MRPT navigator, the
// simulator's unicycle and clock, disks seen as laser points.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <mrpt/core/Clock.h>

#include "amigobot_tracking/core/offset_point.h"
#include "amigobot_tracking/sim/closed_loop.h"
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

}  // namespace

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
