// The tracking loop (core/supervision/tracking_loop.h): one call per cycle from plain inputs to the
// command. A stale pose stops at once, a pending config is used from the next step on, laser
// disks on the target are dropped (virtual ones never), the resume ramps up from zero, and
// the simulator's unramped start sends the controller's own command.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "amigobot_tracking/core/supervision/tracking_loop.h"

using namespace amigobot_tracking::core;

namespace {

const double kLoopPeriod = 0.05;  // [s]

TrackingLoopConfig loopConfig() {
  TrackingLoopConfig c;
  c.supervisor.control_period = kLoopPeriod;
  c.supervisor.require_scan = false;
  c.target_exclusion_radius = 0.3;
  return c;
}

// Robot at the origin facing +x, target 1 m ahead and to the left, both fresh at t.
TrackingLoopInputs inputsAt(double t) {
  TrackingLoopInputs in;
  in.t = t;
  in.supervisor.have_pose = in.supervisor.have_target = true;
  in.supervisor.pose_age = in.supervisor.target_age = 0.01;
  in.pose = {t, Pose2{0.0, 0.0, 0.0}};
  in.target.stamp = t;
  in.target.position = {1.0, 0.5};
  return in;
}

}  // namespace

TEST(TrackingLoop, StalePoseStopsAtOnceAndResumesOnTheRamp) {
  TrackingLoop loop(loopConfig());
  ASSERT_TRUE(loop.enable());
  double t = 0.0;
  TrackingLoopResult r;
  for (int i = 0; i < 100; ++i, t += kLoopPeriod) r = loop.step(inputsAt(t));
  ASSERT_TRUE(r.tracking);
  ASSERT_GT(std::abs(r.u.v) + std::abs(r.u.omega), 0.05);
  const Twist2 cruising = r.u;

  TrackingLoopInputs stale = inputsAt(t);
  stale.supervisor.pose_age = 0.6;  // > pose_timeout 0.5
  r = loop.step(stale);
  EXPECT_TRUE(r.publish);
  EXPECT_FALSE(r.stepped);
  EXPECT_EQ(r.u.v, 0.0);
  EXPECT_EQ(r.u.omega, 0.0);
  EXPECT_EQ(loop.supervisor().state(), TrackingSupervisor::State::kInputsStale);
  EXPECT_NE(loop.supervisor().status().find("robot pose is stale"), std::string::npos);

  // Fresh again: the controller restarts and the command leaves zero by at most one
  // period of the ramp's acceleration.
  t += kLoopPeriod;
  r = loop.step(inputsAt(t));
  ASSERT_TRUE(r.tracking);
  const RampLimits ramp = loopConfig().supervisor.ramp;
  EXPECT_LE(std::abs(r.u.v), ramp.v_accel * kLoopPeriod + 1e-12);
  EXPECT_LE(std::abs(r.u.omega), ramp.w_accel * kLoopPeriod + 1e-12);
  EXPECT_TRUE(loop.supervisor().ramping());
  EXPECT_LT(std::abs(r.u.v) + std::abs(r.u.omega), std::abs(cruising.v) + std::abs(cruising.omega));
}

TEST(TrackingLoop, PendingConfigIsUsedFromTheNextStep) {
  TrackingLoop loop(loopConfig());
  loop.enable();
  loop.step(inputsAt(0.0));
  ControllerConfig slower = loop.controller().config();
  slower.v_max = 0.1;
  slower.w_max = 0.3;
  ASSERT_EQ(slower.validate(), "");
  loop.setPendingConfig(slower);
  EXPECT_TRUE(loop.configPending());
  EXPECT_EQ(loop.nextConfig().v_max, 0.1);
  EXPECT_EQ(loop.controller().config().v_max, 0.3);  // not before the step
  double t = kLoopPeriod;
  TrackingLoopResult r;
  for (int i = 0; i < 60; ++i, t += kLoopPeriod) {
    r = loop.step(inputsAt(t));
    ASSERT_TRUE(r.tracking);
    EXPECT_TRUE(DiamondSet(0.1, 0.3).contains(r.u, 1e-9)) << "step " << i;
  }
  EXPECT_FALSE(loop.configPending());
  EXPECT_EQ(loop.controller().config().v_max, 0.1);
}

TEST(TrackingLoop, LaserDisksOnTheTargetAreDroppedVirtualOnesKept) {
  TrackingLoop loop(loopConfig());
  loop.enable();
  const std::vector<Disk> laser = {Disk{{1.1, 0.5}, 0.1}, Disk{{-1.0, 0.0}, 0.1}};
  const std::vector<Disk> virtuals = {Disk{{1.0, 0.6}, 0.1}};
  TrackingLoopInputs in = inputsAt(0.0);
  in.supervisor.scan_age = 0.05;
  in.scan_disks = &laser;
  in.virtual_disks = &virtuals;
  TrackingLoopResult r = loop.step(in);
  ASSERT_EQ(r.laser_disks, 1u);  // the disk 0.1 m from the target is the target
  ASSERT_EQ(r.virtual_disks, 1u);
  ASSERT_EQ(loop.obstacles().size(), 2u);
  EXPECT_EQ(loop.obstacles()[0].center.x(), -1.0);
  EXPECT_EQ(loop.obstacles()[1].center.y(), 0.6);

  in.t = in.pose.stamp = in.target.stamp = kLoopPeriod;
  in.supervisor.scan_age = 0.6;  // stale scan: no laser disks (require_scan off: still tracking)
  r = loop.step(in);
  EXPECT_TRUE(r.tracking);
  EXPECT_EQ(r.laser_disks, 0u);
  EXPECT_EQ(loop.obstacles().size(), 1u);
}

// enable(false), the simulator's start: the bare controller's command, step by step.
TEST(TrackingLoop, StartWithoutResumeSendsTheControllersCommand) {
  TrackingLoop ramped(loopConfig()), direct(loopConfig());
  ramped.enable();
  direct.enable(false);
  PerformanceController reference(loopConfig().controller);
  TrackingLoopInputs in = inputsAt(0.0);
  in.target.position = {3.0, 1.0};  // far: the start rule, not the restart's, sets rho
  const ControllerOutput expected = reference.stepStamped(in.t, in.pose, in.target, {});
  const TrackingLoopResult a = ramped.step(in), b = direct.step(in);
  EXPECT_EQ(b.u.v, expected.u.v);
  EXPECT_EQ(b.u.omega, expected.u.omega);
  EXPECT_EQ(direct.controller().rho(), reference.rho());
  EXPECT_LT(std::abs(a.u.v), std::abs(expected.u.v));
  for (int i = 1; i < 50; ++i) {
    in.t = in.pose.stamp = in.target.stamp = i * kLoopPeriod;
    const ControllerOutput e = reference.stepStamped(in.t, in.pose, in.target, {});
    const TrackingLoopResult r = direct.step(in);
    ASSERT_EQ(r.u.v, e.u.v) << "step " << i;
    ASSERT_EQ(r.u.omega, e.u.omega) << "step " << i;
  }
}

// The robot's rule: a localisation jump beyond the tracking bound stops, and the bound is the
// rho_inf in use, so a reconfigured rho_inf moves it (a jump of 0.3 m beyond what max_speed
// explains stops at rho_inf 0.1 m, not at 0.5 m).
TEST(TrackingLoop, PoseJumpLimitFollowsTheReconfiguredRhoInf) {
  TrackingLoopConfig config = loopConfig();
  config.pose_jump_limit_is_rho_inf = true;
  config.supervisor.max_speed = 1.0;  // explains 0.05 m per period
  const double jump = 0.35;
  auto jumpAfter = [&](TrackingLoop& loop, const ControllerConfig* pending) {
    loop.enable();
    double t = 0.0;
    for (int i = 0; i < 5; ++i, t += kLoopPeriod) EXPECT_TRUE(loop.step(inputsAt(t)).tracking) << loop.supervisor().status();
    if (pending) loop.setPendingConfig(*pending);
    EXPECT_TRUE(loop.step(inputsAt(t)).tracking);
    TrackingLoopInputs jumped = inputsAt(t + kLoopPeriod);
    jumped.pose.pose.x += jump;
    return loop.step(jumped);
  };
  TrackingLoop fixed(config);
  EXPECT_EQ(fixed.supervisor().config().pose_jump_limit, config.controller.rho_inf);
  TrackingLoopResult r = jumpAfter(fixed, nullptr);
  EXPECT_FALSE(r.tracking);
  EXPECT_EQ(fixed.supervisor().status().rfind("localisation: pose jumped", 0), 0u) << fixed.supervisor().status();

  ControllerConfig wider = config.controller;
  wider.rho_inf = 0.5;
  ASSERT_EQ(wider.validate(), "");
  TrackingLoop reconfigured(config);
  r = jumpAfter(reconfigured, &wider);
  EXPECT_EQ(reconfigured.supervisor().config().pose_jump_limit, 0.5);
  EXPECT_TRUE(r.tracking) << reconfigured.supervisor().status();

  config.pose_jump_limit_is_rho_inf = false;  // the simulator: no jump rule
  TrackingLoop off(config);
  EXPECT_EQ(off.supervisor().config().pose_jump_limit, 0.0);
  EXPECT_TRUE(jumpAfter(off, nullptr).tracking);
}

TEST(TrackingLoop, DisabledSendsNothingAndDisableOneZero) {
  TrackingLoop loop(loopConfig());
  EXPECT_FALSE(loop.step(inputsAt(0.0)).publish);
  loop.enable();
  EXPECT_TRUE(loop.step(inputsAt(kLoopPeriod)).publish);
  const Twist2 zero = loop.disable(2 * kLoopPeriod);
  EXPECT_EQ(zero.v, 0.0);
  EXPECT_FALSE(loop.step(inputsAt(3 * kLoopPeriod)).publish);
}
