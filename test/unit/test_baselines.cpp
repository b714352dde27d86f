// The baselines of the comparison: proportional feedback linearisation, fixed rho, and a
// velocity given from outside the paper's estimator.
#include <gtest/gtest.h>

#include <cmath>

#include "amigobot_tracking/core/law/controller.h"
#include "amigobot_tracking/core/law/proportional_controller.h"
#include "amigobot_tracking/core/robot/offset_point.h"

using namespace amigobot_tracking::core;

namespace {

ControllerConfig wide() {
  ControllerConfig c;
  c.v_max = c.w_max = 100.0;  // never saturates
  c.robot_radius = 0.2;
  c.offset = 0.3;
  return c;
}

}  // namespace

TEST(ProportionalController, IsFeedbackLinearisationWithAProportionalGain) {
  ProportionalController law(wide(), 2.0);
  const Pose2 pose{0.0, 0.0, 0.3};
  TargetSample target{0.0, {1.0, 0.5}};
  target.has_velocity = true;
  target.velocity = {0.2, -0.1};
  const ControllerOutput out = law.step(0.0, PoseSample{0.0, pose}, target, {});
  ASSERT_TRUE(out.valid);
  const Eigen::Vector2d e = target.position - offsetPoint(pose, 0.3);
  const Eigen::Vector2d u_r = target.velocity + 2.0 * e;
  const Twist2 expected = offsetVelocityToTwist(u_r, pose.theta, 0.3);
  EXPECT_NEAR(out.u.v, expected.v, 1e-12);
  EXPECT_NEAR(out.u.omega, expected.omega, 1e-12);
  EXPECT_EQ(out.rho, 0.0);  // no performance function
}

TEST(ProportionalController, SaturatesIntoTheDiamondAndRefusesNonFiniteInput) {
  ControllerConfig c = wide();
  c.v_max = 0.3;
  c.w_max = 0.8;
  ProportionalController law(c, 50.0);
  const ControllerOutput out = law.step(0.0, PoseSample{0.0, {0.0, 0.0, 0.0}}, {0.0, {5.0, 3.0}}, {});
  ASSERT_TRUE(out.valid);
  EXPECT_TRUE(out.active.saturated);
  EXPECT_TRUE(law.diamond().contains(out.u, 1e-12));
  const ControllerOutput bad = law.step(0.1, PoseSample{0.1, {NAN, 0.0, 0.0}}, {0.1, {5.0, 3.0}}, {});
  EXPECT_FALSE(bad.valid);
  EXPECT_EQ(bad.u.v, 0.0);
}

TEST(ProportionalController, RepelsFromAnObstacleLikeThePaperLaw) {
  ControllerConfig c = wide();
  c.delta = 0.1;
  c.body_safe = false;
  ProportionalController law(c, 1.0);
  const Pose2 pose{0.0, 0.0, 0.0};  // p_r = (0.3, 0)
  const std::vector<Disk> obstacles = {{{0.3, 0.6}, 0.3}};  // 0.05 m from p_r's disk, inside delta
  const ControllerOutput out = law.step(0.0, PoseSample{0.0, pose}, {0.0, {0.3, 0.0}}, obstacles);
  EXPECT_EQ(out.detected_obstacles, 1);
  EXPECT_LT(out.u_c.y(), 0.0);  // pushed away (down)
  EXPECT_NEAR(out.u_r.y(), c.k_o * out.u_c.y(), 1e-12);
}

TEST(FixedRho, FollowsThePrescribedDecayWhileSaturated) {
  ControllerConfig c = wide();
  c.v_max = 0.2;
  c.w_max = 0.5;
  c.adaptive_rho = false;
  c.rho_0 = 3.0;
  PerformanceController law(c);
  Pose2 pose{0.0, 0.0, 0.0};
  double rho_prev = 0.0;
  bool saturated = false;
  int checked = 0;
  for (int k = 0; k <= 100; ++k) {
    const double t = 0.01 * k;
    const ControllerOutput out = law.step(t, pose, {t, {1.5, 1.0}}, {});
    saturated = saturated || out.active.saturated;
    if (k > 0 && !out.active.envelope_widened) {
      const double prescribed = c.rho_inf + (rho_prev - c.rho_inf) * std::exp(-c.lambda * 0.01);
      EXPECT_NEAR(out.rho, prescribed, 1e-12) << "t = " << t;
      checked += out.active.saturated;
    }
    rho_prev = out.rho;
  }
  EXPECT_TRUE(saturated);
  EXPECT_GT(checked, 50);  // saturated steps where the adaptive law would have widened rho
}

TEST(ExternalVelocity, ReplacesTheEstimatorsVelocity) {
  PerformanceController law(wide());
  TargetSample target{0.0, {1.0, 0.0}};
  target.has_velocity = true;
  target.velocity = {0.7, -0.4};
  const ControllerOutput out = law.step(0.0, {0.0, 0.0, 0.0}, target, {});
  EXPECT_EQ(out.v_hat, target.velocity);
  target.has_velocity = false;
  const ControllerOutput own = law.step(0.01, {0.0, 0.0, 0.0}, {0.01, {1.0, 0.0}}, {});
  EXPECT_EQ(own.v_hat, law.estimator().velocity());
}
