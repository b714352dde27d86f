// The controller (9)-(13) closing the loop on an ideal unicycle.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "amigobot_tracking/sim/closed_loop.h"
#include "amigobot_tracking/core/robot/unicycle.h"
#include "table1.h"

using namespace amigobot_tracking::core;
using namespace amigobot_tracking::sim;

namespace {

ControllerConfig table1() { return table1Config(); }

ClosedLoopSetup unconstrained() {
  ClosedLoopSetup s;
  s.controller = table1();
  s.controller.v_max = s.controller.w_max = 1e3;  // never saturates
  s.initial_pose = {2.0, -0.5, M_PI / 2};
  s.duration = 20.0;
  return s;
}

}  // namespace

TEST(ClosedLoop, UnconstrainedCircleStaysInsideRhoAndConverges) {
  const ClosedLoopSetup setup = unconstrained();
  const CircleReference circle({0.0, 0.0}, 2.0, 20.0);
  const ClosedLoopSummary s = runClosedLoop(setup, circle);
  EXPECT_LT(s.max_error_ratio, 1.0);
  EXPECT_EQ(s.envelope_widenings, 0u);  // the guarantee held on its own
  EXPECT_EQ(s.saturated_steps, 0u);
  EXPECT_EQ(s.invalid_steps, 0u);
  EXPECT_LT(s.final_error, setup.controller.rho_inf);
}

TEST(ClosedLoop, UnconstrainedRoseStaysInsideRhoAndConverges) {
  ClosedLoopSetup setup = unconstrained();
  setup.duration = 2 * M_PI;
  const RoseReference rose(3.0, 3.0, 1.0);
  const ClosedLoopSummary s = runClosedLoop(setup, rose);
  EXPECT_LT(s.max_error_ratio, 1.0);
  EXPECT_EQ(s.envelope_widenings, 0u);
  EXPECT_LT(s.final_error, setup.controller.rho_inf);
}

TEST(ClosedLoop, SampledTargetAt20HzStillConverges) {
  ClosedLoopSetup setup = unconstrained();
  setup.sample_period = 0.05;
  const CircleReference circle({0.0, 0.0}, 2.0, 20.0);
  const ClosedLoopSummary s = runClosedLoop(setup, circle);
  EXPECT_LT(s.max_error_ratio, 1.0);
  EXPECT_EQ(s.envelope_widenings, 0u);
  EXPECT_LT(s.final_error, setup.controller.rho_inf);
}

TEST(ClosedLoop, RhoWidensWhileSaturatedAndThenDecaysAsPrescribed) {
  // Tight diamond: the start saturates; once the target is caught, nothing conflicts.
  ClosedLoopSetup setup;
  setup.controller = table1();
  setup.controller.v_max = 0.6;
  setup.controller.w_max = 1.5;
  setup.initial_pose = {2.0, -1.0, M_PI};
  setup.duration = 30.0;
  const CircleReference circle({0.0, 0.0}, 2.0, 60.0);  // 0.21 m/s
  const double lambda = setup.controller.lambda, rho_inf = setup.controller.rho_inf;
  std::vector<ClosedLoopStep> steps;
  const ClosedLoopSummary s = runClosedLoop(setup, circle, [&](const ClosedLoopStep& step) { steps.push_back(step); });
  ASSERT_GT(s.saturated_steps, 10u);
  EXPECT_EQ(s.diamond_violations, 0u);
  EXPECT_LT(s.max_error_ratio, 1.0);
  EXPECT_EQ(s.envelope_widenings, 0u);  // (13), not the rule, widened rho
  const double h = setup.control_period;
  size_t last_saturated = 0;
  int widened = 0;
  for (size_t k = 1; k < steps.size(); ++k) {
    const ControllerOutput& prev = steps[k - 1].output;
    const double prescribed = rho_inf + (prev.rho - rho_inf) * std::exp(-lambda * h);
    if (prev.active.saturated) {
      last_saturated = k;
      if (steps[k].output.rho > prescribed + 1e-12) ++widened;
      EXPECT_GE(steps[k].output.rho, prescribed - 1e-12);
    }
    EXPECT_TRUE(DiamondSet(0.6, 1.5).contains(steps[k].output.u));
  }
  EXPECT_GT(widened, 10);
  ASSERT_LT(last_saturated + 100, steps.size()) << "saturation never ended";
  // After the last saturated step rho follows rho_inf + (rho_s - rho_inf) e^(-lambda t) exactly.
  const double rho_s = steps[last_saturated].output.rho, t_s = steps[last_saturated].t;
  for (size_t k = last_saturated; k < steps.size(); ++k) {
    const double expected = rho_inf + (rho_s - rho_inf) * std::exp(-lambda * (steps[k].t - t_s));
    ASSERT_NEAR(steps[k].output.rho, expected, 1e-9) << "at t=" << steps[k].t;
  }
  EXPECT_LT(s.final_error, rho_inf);
}

TEST(ClosedLoop, PaperRoseWithTable1LimitsNeverLeavesTheDiamond) {
  ClosedLoopSetup setup;
  setup.controller = table1();
  setup.initial_pose = {2.0, -0.5, M_PI / 2};
  setup.duration = 2 * M_PI;
  const ClosedLoopSummary s = runClosedLoop(setup, RoseReference(3.0, 3.0, 1.0));
  EXPECT_GT(s.saturated_steps, 0u);
  EXPECT_EQ(s.diamond_violations, 0u);
  EXPECT_EQ(s.invalid_steps, 0u);
  EXPECT_LT(s.max_error_ratio, 1.0);
  EXPECT_EQ(s.envelope_widenings, 0u);
}

TEST(ClosedLoop, DisksOnThePathAreNeverTouchedByTheOffsetPoint) {
  ClosedLoopSetup setup;
  setup.controller = table1();
  setup.initial_pose = {2.0, -0.5, M_PI / 2};
  setup.duration = 25.0;
  // The reference circle runs straight through three disks.
  setup.obstacles = {{{0.0, 2.0}, 0.2}, {{-2.0, 0.0}, 0.15}, {{1.414, -1.414}, 0.25}};
  const CircleReference circle({0.0, 0.0}, 2.0, 20.0);
  const ClosedLoopSummary s = runClosedLoop(setup, circle);
  EXPECT_GT(s.min_clearance_offset, 0.0);
  EXPECT_EQ(s.diamond_violations, 0u);
  EXPECT_LT(s.max_error_ratio, 1.0);
  EXPECT_EQ(s.envelope_widenings, 0u);
}

TEST(ClosedLoop, BodySafeRadiusKeepsTheBodyClear) {
  ClosedLoopSetup setup;
  setup.controller = table1();
  setup.controller.body_safe = true;
  setup.initial_pose = {2.0, -0.5, M_PI / 2};
  setup.duration = 25.0;
  setup.obstacles = {{{0.0, 2.0}, 0.2}, {{-2.0, 0.0}, 0.15}, {{1.414, -1.414}, 0.25}};
  const ClosedLoopSummary s = runClosedLoop(setup, CircleReference({0.0, 0.0}, 2.0, 20.0));
  EXPECT_GT(s.min_clearance_offset, 0.0);  // effective disk of radius R + r around p_r
  EXPECT_GT(s.min_clearance_body, 0.0);    // so the body disk around p is clear too
  EXPECT_EQ(s.diamond_violations, 0u);
  EXPECT_EQ(s.envelope_widenings, 0u);
}

TEST(ClosedLoop, TargetFartherThanRho0StillGoes) {
  ClosedLoopSetup setup = unconstrained();
  setup.initial_pose = {-5.0, -5.0, 0.0};  // |e(0)| ~ 8.6 m > rho_0 = 1.84 m
  const ClosedLoopSummary s = runClosedLoop(setup, CircleReference({0.0, 0.0}, 2.0, 20.0));
  EXPECT_GE(s.envelope_widenings, 1u);
  EXPECT_EQ(s.envelope_widenings, 1u);  // the start only
  EXPECT_LT(s.max_error_ratio, 1.0);
  EXPECT_LT(s.final_error, setup.controller.rho_inf);
}

TEST(ClosedLoop, NonFiniteInputsGiveAZeroCommand) {
  PerformanceController controller(table1());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ControllerOutput out = controller.step(0.0, {nan, 0.0, 0.0}, {0.0, {1.0, 0.0}}, {});
  EXPECT_FALSE(out.valid);
  EXPECT_EQ(out.u.v, 0.0);
  EXPECT_EQ(out.u.omega, 0.0);
  EXPECT_NE(out.error.find("pose"), std::string::npos);
  out = controller.step(0.0, {0.0, 0.0, 0.0}, {0.0, {nan, 0.0}}, {});
  EXPECT_FALSE(out.valid);
  EXPECT_NE(out.error.find("target"), std::string::npos);
  out = controller.step(0.1, {0.0, 0.0, 0.0}, {0.1, {1.0, 0.0}}, {});
  EXPECT_TRUE(out.valid);
  out = controller.step(0.05, {0.0, 0.0, 0.0}, {0.1, {1.0, 0.0}}, {});
  EXPECT_FALSE(out.valid);
  EXPECT_NE(out.error.find("backwards"), std::string::npos);
}

TEST(ClosedLoop, SetConfigBetweenStepsKeepsTheStateAndAppliesNewLimits) {
  ControllerConfig config = table1();
  PerformanceController controller(config);
  const CircleReference circle({0.0, 0.0}, 2.0, 20.0);
  Pose2 pose{2.0, -0.5, M_PI / 2};
  ControllerOutput out;
  for (int k = 0; k < 2000; ++k) {
    const double t = 1e-3 * k;
    out = controller.step(t, pose, {t, circle.at(t).position}, {});
    pose = integrateUnicycle(pose, out.u, 1e-3);
  }
  const double rho_before = controller.rho();
  const Eigen::Vector2d velocity_before = controller.estimator().velocity();
  config.v_max = 0.2;
  config.w_max = 0.5;
  config.k_d = 1.0;
  controller.setConfig(config);
  EXPECT_EQ(controller.rho(), rho_before);
  EXPECT_EQ(controller.estimator().velocity(), velocity_before);
  out = controller.step(2.0, pose, {2.0, circle.at(2.0).position}, {});
  EXPECT_TRUE(DiamondSet(0.2, 0.5).contains(out.u));
  EXPECT_GT(out.rho, 0.0);
}
