// The tracking supervisor (core/supervision/tracking_supervisor.h) on pure inputs: stale inputs stop at
// once with a reason, fresh inputs restart the controller, the ramp leaves zero after the
// supervisor's own stops, braking passes, NaN never does.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "amigobot_tracking/core/law/controller.h"
#include "amigobot_tracking/core/supervision/tracking_loop.h"
#include "amigobot_tracking/core/supervision/tracking_supervisor.h"

using namespace amigobot_tracking::core;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kPeriod = 0.05;  // [s] 20 Hz
const DiamondSet kSupervisorDiamond(0.3, 0.8);

SupervisorInputs freshInputs() {
  SupervisorInputs in;
  in.have_pose = in.have_target = true;
  in.pose_age = in.target_age = 0.01;
  in.scan_age = 0.05;
  return in;
}

ControllerOutput output(double v, double omega) {
  ControllerOutput out;
  out.valid = true;
  out.u = {v, omega};
  return out;
}

// Enabled, one fresh step, the ramp run out at (v, omega): tracking, nothing held back.
TrackingSupervisor trackingAt(double v, double omega, double* t) {
  TrackingSupervisor s;
  s.enable();
  for (int i = 0; i < 200 && (i == 0 || s.ramping()); ++i, *t += kPeriod) {
    EXPECT_TRUE(s.begin(*t, freshInputs()).step);
    s.finish(*t, output(v, omega), kSupervisorDiamond);
  }
  EXPECT_FALSE(s.ramping());
  return s;
}

}  // namespace

TEST(TrackingSupervisor, DisabledSendsNothing) {
  TrackingSupervisor s;
  const auto d = s.begin(0.0, freshInputs());
  EXPECT_FALSE(d.step);
  EXPECT_FALSE(d.publish);
  EXPECT_EQ(s.state(), TrackingSupervisor::State::kDisabled);
  EXPECT_EQ(s.status(), "disabled");
}

TEST(TrackingSupervisor, EnableOnceThenDisableSendsOneZero) {
  double t = 0.0;
  TrackingSupervisor s = trackingAt(0.2, 0.1, &t);
  EXPECT_FALSE(s.enable()) << "already enabled: no second restart";
  const Twist2 zero = s.disable(t);
  EXPECT_EQ(zero.v, 0.0);
  EXPECT_EQ(zero.omega, 0.0);
  EXPECT_FALSE(s.enabled());
  EXPECT_EQ(s.status(), "disabled");
  EXPECT_FALSE(s.begin(t + kPeriod, freshInputs()).publish);
  EXPECT_TRUE(s.enable());
  EXPECT_TRUE(s.ramping()) << "re-enabled: the robot is taken as standing";
}

TEST(TrackingSupervisor, StaleOrMissingInputsStopWithTheReason) {
  SupervisorConfig config;
  config.pose_link = "map -> base_link";
  config.target_link = "map -> target";
  struct Case {
    SupervisorInputs in;
    const char* reason;
  };
  SupervisorInputs no_pose = freshInputs(), old_pose = freshInputs(), no_target = freshInputs(),
                   old_target = freshInputs(), no_scan = freshInputs(), old_scan = freshInputs();
  no_pose.have_pose = false;
  old_pose.pose_age = 0.6;
  no_target.have_target = false;
  old_target.target_age = 0.51;
  no_scan.scan_age = -1.0;
  old_scan.scan_age = 0.7;
  // Untrusted stamps (issue 25) and something inside the body.
  SupervisorInputs future_target = freshInputs(), zero_scan = freshInputs(), zero_pose = freshInputs(),
                   intrusion = freshInputs();
  future_target.target_problem = "stamped 30.000 s in the future (tolerance 0.100 s)";
  zero_scan.scan_problem = "stamp is 0";
  zero_pose.pose_problem = "stamp is 0";
  intrusion.body_intrusion = "scan point 0.06 m from the centre";
  for (const Case& c : {Case{future_target, "target map -> target: stamped 30.000 s in the future"},
                        Case{zero_scan, "scan: stamp is 0"}, Case{zero_pose, "robot pose map -> base_link: stamp is 0"},
                        Case{intrusion, "body intrusion: scan point 0.06 m"},Case{no_pose, "no robot pose map -> base_link"}, Case{old_pose, "robot pose is stale (0.6"},
                        Case{no_target, "no target map -> target"}, Case{old_target, "target is stale (0.51"},
                        Case{no_scan, "no scan yet"}, Case{old_scan, "scan is stale (0.7"}}) {
    const double t = 0.0;
    TrackingSupervisor s(config);
    s.enable();
    s.begin(t, freshInputs());
    s.finish(t, output(0.01, 0.0), kSupervisorDiamond);
    const auto d = s.begin(t + kPeriod, c.in);
    EXPECT_FALSE(d.step) << c.reason;
    EXPECT_TRUE(d.publish) << c.reason;
    EXPECT_EQ(d.u.v, 0.0);
    EXPECT_EQ(d.u.omega, 0.0);
    EXPECT_EQ(s.state(), TrackingSupervisor::State::kInputsStale);
    EXPECT_EQ(s.status().rfind(c.reason, 0), 0u) << s.status();
  }
}

TEST(TrackingSupervisor, WithoutRequireScanTheLaserMayBeSilent) {
  SupervisorConfig config;
  config.require_scan = false;
  TrackingSupervisor s(config);
  s.enable();
  SupervisorInputs in = freshInputs();
  in.scan_age = -1.0;
  EXPECT_TRUE(s.begin(0.0, in).step);
  EXPECT_FALSE(s.scanFresh(-1.0));
  EXPECT_TRUE(s.scanFresh(0.5));
  EXPECT_FALSE(s.scanFresh(0.51));
}

TEST(TrackingSupervisor, FreshAgainRestartsOnceThenSteps) {
  TrackingSupervisor s;
  EXPECT_TRUE(s.enable());
  EXPECT_FALSE(s.begin(0.0, freshInputs()).restart) << "enable() already asked for the restart";
  SupervisorInputs stale = freshInputs();
  stale.target_age = 2.0;
  s.begin(0.05, stale);
  s.begin(0.10, stale);
  const auto resumed = s.begin(0.15, freshInputs());
  EXPECT_TRUE(resumed.step);
  EXPECT_TRUE(resumed.restart);
  s.finish(0.15, output(0.1, 0.0), kSupervisorDiamond);
  EXPECT_FALSE(s.begin(0.20, freshInputs()).restart);
}

// The rule the restart applies: rho = max(rho_0, |e| / 0.5), so |e|/rho <= 1/2.
TEST(TrackingSupervisor, RestartRhoRule) {
  ControllerConfig config;  // rho_0 = 1, offset 0.3
  PerformanceController far(config), near(config);
  far.restart(TrackingLoop::kRestartErrorRatio);
  const ControllerOutput a = far.step(0.0, Pose2{0.0, 0.0, 0.0}, TargetSample{0.0, {3.3, 0.0}}, {});
  ASSERT_TRUE(a.valid);
  EXPECT_NEAR(a.rho, 6.0, 1e-12);  // |e| = 3
  EXPECT_FALSE(a.active.envelope_widened);
  near.restart(TrackingLoop::kRestartErrorRatio);
  const ControllerOutput b = near.step(0.0, Pose2{0.0, 0.0, 0.0}, TargetSample{0.0, {0.5, 0.0}}, {});
  EXPECT_NEAR(b.rho, config.rho_0, 1e-12);  // |e| = 0.2: rho_0 is wider
  // reset() drops the rule: the plain start rule widens rho to |e| / max_error_ratio.
  far.restart(TrackingLoop::kRestartErrorRatio);
  far.reset();
  EXPECT_NEAR(far.step(0.0, Pose2{0.0, 0.0, 0.0}, TargetSample{0.0, {3.3, 0.0}}, {}).rho,
              3.0 / config.max_error_ratio, 1e-12);
}

TEST(TrackingSupervisor, RampsAfterItsOwnStopAndCapsTheTimeStep) {
  double t = 0.0;
  TrackingSupervisor s = trackingAt(0.3, 0.0, &t);
  SupervisorInputs stale = freshInputs();
  stale.pose_age = 1.0;
  s.begin(t, stale);
  EXPECT_TRUE(s.ramping());
  t += 10.0;  // a long gap earns no more than one period of acceleration
  ASSERT_TRUE(s.begin(t, freshInputs()).step);
  const Twist2 first = s.finish(t, output(0.3, 0.0), kSupervisorDiamond);
  EXPECT_NEAR(first.v, s.config().ramp.v_accel * kPeriod, 1e-12);
  int periods = 1;
  for (Twist2 sent = first; s.ramping(); ++periods) {
    ASSERT_LT(periods, 100);
    t += kPeriod;
    s.begin(t, freshInputs());
    const Twist2 next = s.finish(t, output(0.3, 0.0), kSupervisorDiamond);
    EXPECT_LE(next.v - sent.v, s.config().ramp.v_accel * kPeriod + 1e-9);
    sent = next;
  }
  EXPECT_EQ(periods, 20);  // 0.3 m/s at 0.3 m/s^2: 1 s
  t += kPeriod;
  s.begin(t, freshInputs());
  EXPECT_EQ(s.finish(t, output(0.3, 0.0), kSupervisorDiamond).v, 0.3) << "ramp over: passes unchanged";
}

TEST(TrackingSupervisor, BrakingIsNeverHeldBack) {
  double t = 0.0;
  TrackingSupervisor s = trackingAt(0.3, 0.0, &t);
  s.begin(t, freshInputs());
  EXPECT_EQ(s.finish(t, output(0.05, 0.0), kSupervisorDiamond).v, 0.05) << "not ramping: 0.25 m/s less in one period";
  // While ramping: the command falls back toward zero at once.
  SupervisorInputs stale = freshInputs();
  stale.target_age = 1.0;
  s.begin(t += kPeriod, stale);
  s.begin(t += kPeriod, freshInputs());
  const Twist2 up = s.finish(t, output(0.3, 0.0), kSupervisorDiamond);
  ASSERT_GT(up.v, 0.0);
  ASSERT_TRUE(s.ramping());
  s.begin(t += kPeriod, freshInputs());
  EXPECT_EQ(s.finish(t, output(0.001, 0.0), kSupervisorDiamond).v, 0.001);
}

TEST(TrackingSupervisor, RefusedStepsStopAndInvalidOnesRestart) {
  double t = 0.0;
  TrackingSupervisor s = trackingAt(0.2, 0.0, &t);
  ControllerOutput invalid;
  invalid.error = "time went backwards";
  s.begin(t, freshInputs());
  EXPECT_EQ(s.finish(t, invalid, kSupervisorDiamond).v, 0.0);
  EXPECT_EQ(s.state(), TrackingSupervisor::State::kStepInvalid);
  EXPECT_EQ(s.status(), "controller: time went backwards");
  EXPECT_TRUE(s.begin(t += kPeriod, freshInputs()).restart);
  EXPECT_EQ(s.finish(t, output(0.31, 0.0), kSupervisorDiamond).v, 0.0) << "outside the diamond";
  EXPECT_EQ(s.state(), TrackingSupervisor::State::kCommandRefused);
  EXPECT_TRUE(s.ramping());
}

TEST(TrackingSupervisor, NaNInputsNeverPass) {
  for (int field = 0; field < 4; ++field) {
    double t = 0.0;
    TrackingSupervisor s = trackingAt(0.2, 0.1, &t);
    SupervisorInputs in = freshInputs();
    double when = t;
    if (field == 0) in.pose_age = kNaN;
    if (field == 1) in.target_age = kNaN;
    if (field == 2) in.scan_age = kNaN;
    if (field == 3) when = kNaN;
    const auto d = s.begin(when, in);
    EXPECT_FALSE(d.step) << field;
    EXPECT_EQ(d.u.v, 0.0) << field;
    EXPECT_EQ(s.state(), TrackingSupervisor::State::kInputsStale) << field;
  }
  for (const Twist2 bad : {Twist2{kNaN, 0.0}, Twist2{0.0, kNaN}, Twist2{std::numeric_limits<double>::infinity(), 0.0}}) {
    double t = 0.0;
    TrackingSupervisor s = trackingAt(0.2, 0.1, &t);
    s.begin(t, freshInputs());
    const Twist2 sent = s.finish(t, output(bad.v, bad.omega), kSupervisorDiamond);
    EXPECT_EQ(sent.v, 0.0);
    EXPECT_EQ(sent.omega, 0.0);
    EXPECT_EQ(s.state(), TrackingSupervisor::State::kCommandRefused);
  }
  double t = 0.0;
  TrackingSupervisor s = trackingAt(0.2, 0.1, &t);
  s.begin(t, freshInputs());
  EXPECT_EQ(s.finish(kNaN, output(0.2, 0.1), kSupervisorDiamond).v, 0.0) << "a NaN time never passes a command";
}

// Issue 25: after a wrong /initialpose the robot drove 2.85 m on a pose 3 m off.
TEST(TrackingSupervisor, BadLocalisationStopsAndResumesOnTheRampWhenGood) {
  TrackingSupervisor s;
  s.enable();
  SupervisorInputs lost = freshInputs();
  lost.localization_problem = "match 0.31 < min_match 0.50";
  EXPECT_TRUE(s.begin(0.0, freshInputs()).step);
  s.finish(0.0, output(0.1, 0.0), kSupervisorDiamond);
  const auto d = s.begin(kPeriod, lost);
  EXPECT_FALSE(d.step);
  EXPECT_TRUE(d.publish);
  EXPECT_EQ(d.u.v, 0.0);
  EXPECT_EQ(s.status(), "localisation: match 0.31 < min_match 0.50");
  const auto back = s.begin(2 * kPeriod, freshInputs());
  EXPECT_TRUE(back.step);
  EXPECT_TRUE(back.restart);
  EXPECT_TRUE(s.ramping());
}

TEST(TrackingSupervisor, APoseJumpBeyondTheTrackingBoundHoldsUntilLocalisationSettles) {
  SupervisorConfig config;
  config.pose_jump_limit = 0.1;  // rho_inf
  config.max_speed = 0.3;
  config.jump_settle = 1.0;
  TrackingSupervisor s(config);
  s.enable();
  SupervisorInputs in = freshInputs();
  double t = 0.0;
  for (; t < 1.0; t += kPeriod) {  // driving at 0.3 m/s is no jump, nor a late cycle
    in.pose_position.x() += 0.3 * kPeriod;
    EXPECT_TRUE(s.begin(t, in).step) << t << ": " << s.status();
    s.finish(t, output(0.1, 0.0), kSupervisorDiamond);
  }
  in.pose_position.x() += 0.3 * 0.5;  // a cycle 0.5 s late
  EXPECT_TRUE(s.begin(t += 0.5, in).step) << s.status();
  in.pose_position.x() += 3.0;  // a wrong initial pose
  EXPECT_FALSE(s.begin(t += kPeriod, in).step);
  EXPECT_EQ(s.status().rfind("localisation: pose jumped 3.", 0), 0u) << s.status();
  SupervisorInputs bad = in;
  bad.localization_problem = "match 0.20 < min_match 0.50";
  for (int i = 0; i < 60; ++i) EXPECT_FALSE(s.begin(t += kPeriod, bad).step);  // 3 s lost: held
  const double last_bad = t;
  EXPECT_FALSE(s.begin(last_bad + kPeriod, in).step) << "good again, but not yet for jump_settle";
  EXPECT_FALSE(s.begin(last_bad + 0.95, in).step);
  const auto resumed = s.begin(last_bad + 1.01, in);
  EXPECT_TRUE(resumed.step) << s.status();
  EXPECT_TRUE(resumed.restart);
}
