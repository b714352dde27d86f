// Odometry from SIPs: wrap-safe deltas, exact arcs, both THPOS readings, SI units.
#include <gtest/gtest.h>

#include <cmath>

#include "amigobot_tracking/aria/odometry.h"
#include "amigobot_tracking/core/robot/unicycle.h"

using namespace amigobot_tracking::aria;
using amigobot_tracking::core::Pose2;

namespace {
// The SIP a firmware with these factors would send for a true pose.
Sip sipAt(const Pose2& pose, const RobotParams& p, double unwrapped_theta) {
  Sip s;
  auto pos = [&](double m) {
    const long units = std::lround(m * 1e3 / p.dist_conv_factor);
    return static_cast<std::uint16_t>(((units % 0x8000) + 0x8000) % 0x8000);
  };
  s.x = pos(pose.x);
  s.y = pos(pose.y);
  const long th = std::lround(unwrapped_theta / p.angle_conv_factor);
  s.theta = static_cast<std::int16_t>(((th % p.angle_units_per_turn) + p.angle_units_per_turn) % p.angle_units_per_turn);
  return s;
}
}  // namespace

TEST(AriaOdometry, DeltasWrapAt15Bits) {
  EXPECT_EQ(positionDelta(5, 0x7FFB), 10);
  EXPECT_EQ(positionDelta(0x7FFB, 5), -10);
  EXPECT_EQ(positionDelta(100, 40), 60);
  EXPECT_EQ(angleDelta(3, 4090, 4096), 9);
  EXPECT_EQ(angleDelta(4090, 3, 4096), -9);
  EXPECT_EQ(angleDelta(-2040, 2040, 4096), 16);
  EXPECT_EQ(angleDelta(2, 358, 360), 4);
}

class AriaOdometryTurn : public ::testing::TestWithParam<bool> {};

// Driving circles across the 15-bit wrap of XPOS and the angle wrap, with the THPOS
// reading set to ARIA's 4096 units per turn or the AmigoSH manual's degrees.
TEST_P(AriaOdometryTurn, CircleAcrossTheWrapTracksTheTruePose) {
  RobotParams p = RobotParams::amigo();
  if (GetParam()) {
    p.angle_conv_factor = M_PI / 180.0;
    p.angle_units_per_turn = 360;
  }
  SipOdometry odom(p);
  // Start near the XPOS wrap: 16383 units * 0.5083 mm = 8.33 m.
  Pose2 truth{16380 * p.dist_conv_factor * 1e-3, 0.0, 0.0};
  double unwrapped = 0.0;
  odom.update(sipAt(truth, p, unwrapped));
  odom.reset(truth);
  const double v = 0.3, w = 0.6, dt = 0.1;
  for (int i = 0; i < 300; ++i) {  // 30 s: 18 rad, almost three turns
    truth = amigobot_tracking::core::integrateUnicycle(truth, {v, w}, dt);
    unwrapped += w * dt;
    odom.update(sipAt(truth, p, unwrapped));
  }
  const Pose2& est = odom.state().pose;
  // Errors come only from the firmware's quantisation (0.5 mm, 0.09 or 1 degree).
  const double angle_tol = GetParam() ? 0.01 : 0.002;
  EXPECT_NEAR(est.x, truth.x, 0.01);
  EXPECT_NEAR(est.y, truth.y, 0.01);
  EXPECT_NEAR(amigobot_tracking::core::wrapAngle(est.theta - truth.theta), 0.0, angle_tol);
}

INSTANTIATE_TEST_SUITE_P(ThposReadings, AriaOdometryTurn, ::testing::Values(false, true));

TEST(AriaOdometry, CrossingTheXposWrapKeepsMovingForward) {
  const RobotParams p = RobotParams::amigo();
  SipOdometry odom(p);
  Sip s;
  s.x = 0x7FF0;
  odom.update(s);
  s.x = 0x0010;  // +32 units after the wrap
  odom.update(s);
  EXPECT_NEAR(odom.state().pose.x, 32 * p.dist_conv_factor * 1e-3, 1e-12);
  EXPECT_NEAR(odom.state().pose.y, 0.0, 1e-12);
}

TEST(AriaOdometry, ResetRebasesWithoutLosingTheNextDelta) {
  const RobotParams p = RobotParams::amigoSh();  // 1 mm per unit
  SipOdometry odom(p);
  Sip s;
  s.x = 1000;
  odom.update(s);
  s.x = 1500;
  odom.update(s);
  EXPECT_NEAR(odom.state().pose.x, 0.5, 1e-12);
  odom.reset({1.0, 2.0, M_PI / 2});
  s.x = 1600;  // 100 mm forward in the firmware frame, heading 0 there
  odom.update(s);
  EXPECT_NEAR(odom.state().pose.x, 1.0, 1e-9);
  EXPECT_NEAR(odom.state().pose.y, 2.1, 1e-9);
  odom.relink();
  s.x = 20000;  // a restarted robot: the jump is not motion
  odom.update(s);
  EXPECT_NEAR(odom.state().pose.y, 2.1, 1e-9);
}

TEST(AriaOdometry, TwistUsesRotVelWhenPresent) {
  const RobotParams p = RobotParams::amigo();
  Sip s;
  s.left_vel = 100;
  s.right_vel = 300;
  auto t = sipTwist(s, p);
  EXPECT_NEAR(t.v, 200 * p.vel_conv_factor * 1e-3, 1e-12);
  EXPECT_NEAR(t.omega, 100 * p.vel_conv_factor * p.diff_conv_factor, 1e-12);
  s.rot_vel = 450;  // 45 deg/s
  t = sipTwist(s, p);
  EXPECT_NEAR(t.omega, M_PI / 4, 1e-12);
}
