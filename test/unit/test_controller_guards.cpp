// Guards around the paper's laws: the envelope threshold against k_r, rho after setConfig and
// after a stall, and a detection band that a fixed-rate loop cannot jump over.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "amigobot_tracking/core/law/controller.h"
#include "amigobot_tracking/core/robot/unicycle.h"
#include "table1.h"

using namespace amigobot_tracking::core;

namespace {

// Table 1 as config/controller_sim.yaml gave it to the node (body_safe true).
ControllerConfig table1() {
  ControllerConfig c = table1Config();
  c.body_safe = true;
  return c;
}

// The offset point 5 cm outside contact with a disk, the target behind the disk: the
// barrier opposes the attraction (a large conflict in (13), ~1/margin).
struct NearContact {
  Pose2 pose{-0.03, 0.0, 0.0};  // p_r = (0.27, 0): 0.05 m outside contact at 0.68 from the centre
  std::vector<Disk> disks{{{1.0, 0.0}, 0.2}};
  TargetSample target{0.0, {0.77, 0.0}};
};

}  // namespace

TEST(EnvelopeThreshold, SustainedConflictRatioSolvesItsEquation) {
  const double xi = sustainedConflictRatio(0.5, 1.0);
  EXPECT_NEAR(xi * std::atanh(xi), 2.0, 1e-9);
  EXPECT_NEAR(xi, 0.968, 1e-3);
  EXPECT_GT(sustainedConflictRatio(0.25, 1.0), xi);  // weaker relaxation settles closer to 1
}

TEST(EnvelopeThreshold, ThresholdBelowTheSustainedRatioIsRefusedNamingBoth) {
  ControllerConfig c;
  c.max_error_ratio = 0.95;  // below 0.968 for k_r = 0.5: the rule would replace (13)
  const std::string err = c.validate();
  EXPECT_EQ(err.rfind("max_error_ratio", 0), 0u) << err;
  EXPECT_NE(err.find("k_r = 0.5"), std::string::npos) << err;
  EXPECT_NE(err.find("0.95"), std::string::npos) << err;
  c.max_error_ratio = 0.99;
  EXPECT_EQ(c.validate(), "");
  c.k_r = 0.2;  // xi* = 0.9999...: 0.99 is below it
  EXPECT_NE(c.validate().find("max_error_ratio"), std::string::npos);
}

TEST(SetConfig, RaisedRhoInfReclampsRho) {
  PerformanceController controller;
  const Pose2 pose{0.0, 0.0, 0.0};
  for (int k = 0; k <= 400; ++k) controller.step(0.05 * k, pose, {0.05 * k, {0.35, 0.0}}, {});
  ASSERT_LT(controller.rho(), 0.11);  // decayed to about rho_inf = 0.1
  ControllerConfig raised = controller.config();
  raised.rho_inf = 0.5;
  controller.setConfig(raised);
  EXPECT_GE(controller.rho(), 0.5);
  // And no push away from the target on the next step: lambda (rho - rho_inf) >= 0.
  const ControllerOutput out = controller.step(20.05, pose, {20.05, {0.35, 0.0}}, {});
  EXPECT_GE(out.rho, 0.5);
  EXPECT_GE(out.u.v, 0.0);
}

TEST(RhoLaw, AStallDoesNotMultiplyTheStaleConflict) {
  const NearContact scene;
  PerformanceController controller;
  const ControllerOutput first = controller.step(0.0, scene.pose, scene.target, scene.disks);
  ASSERT_TRUE(first.active.conflict);
  const double bounded = controller.config().max_relaxation_interval;
  PerformanceController on_time = controller, stalled = controller;
  const double rho_on_time = on_time.step(bounded, scene.pose, scene.target, scene.disks).rho;
  const double rho_stalled = stalled.step(1.0, scene.pose, scene.target, scene.disks).rho;  // 1 s stall
  EXPECT_GT(rho_on_time, first.rho);  // the conflict relaxes rho
  // The stall adds no more relaxation than max_relaxation_interval, and decays longer.
  EXPECT_LE(rho_stalled, rho_on_time + 1e-12) << "on time " << rho_on_time << ", stalled " << rho_stalled;
}

TEST(BandReach, Table1At20HzIsRefusedNamingTheNumbers) {
  const ControllerConfig c = table1();
  const std::string err = bandReachError(c, 0.05);
  EXPECT_NE(err.find("delta = 0.016"), std::string::npos) << err;
  EXPECT_NE(err.find("0.375 m"), std::string::npos) << err;  // 5 m/s * 1.5 * 0.05 s
  EXPECT_NE(err.find("v_max = 5"), std::string::npos) << err;
  ControllerConfig wide = c;
  wide.delta = 0.4;  // above 5 m/s * 0.075 s, the worst period
  EXPECT_EQ(bandReachError(wide, 0.05), "");
  EXPECT_EQ(bandReachError(c, 0.002), "");  // 1 cm per period at 500 Hz
  EXPECT_EQ(bandReachError(ControllerConfig(), 0.05), "");  // the experiment's 0.3 m/s: 1.5 cm
}

// Section 5.3's diamond (0.3 m/s, 0.8 rad/s, r = 0.3: 0.3 m/s at the offset point) with
// delta = 0.016 at 20 Hz: 0.015 m per nominal period passed, but a period stretched by timer
// jitter crosses the band (the band was entered or left on 1309 of 1801 steps). An obstacle
// approaching at 0.5 m/s makes the experiment's delta = 0.25 too thin at 5 Hz.
TEST(BandReach, TimerJitterAndObstacleSpeedCount) {
  ControllerConfig c;  // the experiment's diamond
  c.delta = 0.016;
  const std::string err = bandReachError(c, 0.05);
  EXPECT_NE(err.find("delta = 0.016"), std::string::npos) << err;
  EXPECT_NE(err.find("timer jitter"), std::string::npos) << err;
  c.delta = 0.25;
  EXPECT_EQ(bandReachError(c, 0.2), "");  // 0.3 m/s * 0.3 s = 0.09 m
  const std::string moving = bandReachError(c, 0.2, 0.5);  // 0.8 m/s * 0.3 s = 0.24 m: still inside
  EXPECT_EQ(moving, "");
  const std::string fast = bandReachError(c, 0.2, 0.6);  // 0.9 m/s * 0.3 s = 0.27 m
  EXPECT_NE(fast.find("obstacle speed 0.6"), std::string::npos) << fast;
}

// The relaxation rate cap: deep in the band (the conflict ~1/margin) (13) alone raises rho by
// k_r T |e_hat^T u_c| h, metres per step; with max_rho_rate it rises at most that fast.
TEST(RhoLaw, RateCapBoundsTheRelaxationOfANearContactConflict) {
  NearContact scene;
  scene.pose = Pose2{0.0295, 0.0, 0.0};  // p_r 0.5 mm outside contact: a band entered deep in one step
  ControllerConfig capped;
  capped.max_rho_rate = 1.0;
  PerformanceController paper, bounded(capped);
  double paper_jump = 0.0, bounded_jump = 0.0;
  double rho_paper = paper.step(0.0, scene.pose, scene.target, scene.disks).rho;
  double rho_bounded = bounded.step(0.0, scene.pose, scene.target, scene.disks).rho;
  for (int k = 1; k <= 4; ++k) {
    const double t = 0.05 * k;
    const double p = paper.step(t, scene.pose, scene.target, scene.disks).rho;
    const double b = bounded.step(t, scene.pose, scene.target, scene.disks).rho;
    paper_jump = std::max(paper_jump, p - rho_paper);
    bounded_jump = std::max(bounded_jump, b - rho_bounded);
    rho_paper = p;
    rho_bounded = b;
  }
  EXPECT_GT(paper_jump, 1.0);                       // the paper's (13): metres in one 50 ms step
  EXPECT_LE(bounded_jump, capped.max_rho_rate * 0.05 + 1e-12);
  EXPECT_GT(bounded_jump, 0.0);                     // still relaxed, only slower
}

// Why: with Table 1 at 20 Hz the explicit (10) is first evaluated inside the disk.
TEST(BandReach, Table1At20HzWithTheExplicitBandEntersTheDisk) {
  const ControllerConfig c = table1();
  PerformanceController controller(c);
  const Disk disk{{2.5, 0.0}, 0.2};
  Pose2 pose{0.0, 0.05, 0.0};
  double min_clearance = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 100; ++k) {
    const double t = 0.05 * k;
    const ControllerOutput out = controller.step(t, pose, {t, {4.0, 0.0}}, {disk});
    ASSERT_TRUE(out.valid) << out.error;
    for (int i = 0; i < 10; ++i) {  // the command held for the period, checked on the way
      pose = integrateUnicycle(pose, out.u, 0.005);
      const Eigen::Vector2d p_r = pose.position() + c.offset * Eigen::Vector2d(std::cos(pose.theta), std::sin(pose.theta));
      min_clearance = std::min(min_clearance, (p_r - disk.center).norm() - disk.radius - c.effectiveRadius());
    }
  }
  EXPECT_LT(min_clearance, 0.0);
}
