// The resume ramp (core/supervision/resume_ramp.h): leaves zero at the robot's accelerations, keeps the
// direction of (v, w) and the diamond, never holds back braking.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "amigobot_tracking/core/robot/diamond.h"
#include "amigobot_tracking/core/supervision/resume_ramp.h"

using namespace amigobot_tracking::core;

namespace {

const RampLimits kLimits;  // 0.3 m/s^2, 1.745 rad/s^2 (AmigoBot)
const double kDt = 0.05;   // [s] one control period at 20 Hz
const DiamondSet kRampDiamond(0.3, 0.8);

// The component moved at most `step` from p, or stayed between 0 and p (braking).
bool withinStepOrBraking(double u, double p, double step) {
  const double eps = 1e-9;  // rampTowards rounds s within 1e-9 of 1 up to 1
  if (std::abs(u - p) <= step + eps) return true;
  return (p >= 0.0 ? u >= -eps && u <= p + eps : u <= eps && u >= p - eps);
}

}  // namespace

// The known case: on resume the controller asks (0.15, 0.4) at once; the ramp takes it there
// in steps of at most (0.015 m/s, 0.087 rad/s), on the same ray through zero.
TEST(ResumeRamp, LeavesZeroAtTheAccelerationLimits) {
  const Twist2 desired{0.15, 0.4};
  Twist2 sent;
  int periods = 0;
  for (bool limited = true; limited; ++periods) {
    ASSERT_LT(periods, 100);
    const RampStep r = rampTowards(desired, sent, kLimits, kDt);
    EXPECT_LE(std::abs(r.u.v - sent.v), kLimits.v_accel * kDt + 1e-9);
    EXPECT_LE(std::abs(r.u.omega - sent.omega), kLimits.w_accel * kDt + 1e-9);
    EXPECT_NEAR(r.u.v * desired.omega, r.u.omega * desired.v, 1e-12) << "direction kept";
    limited = r.limited;
    sent = r.u;
  }
  // v is the binding component: 0.15 / 0.015 = 10 periods.
  EXPECT_EQ(periods, 10);
  EXPECT_DOUBLE_EQ(sent.v, desired.v);
  EXPECT_DOUBLE_EQ(sent.omega, desired.omega);
}

TEST(ResumeRamp, FirstStepFromZeroIsOneFactorOfTheCommand) {
  const RampStep r = rampTowards({0.15, 0.4}, {}, kLimits, kDt);
  EXPECT_TRUE(r.limited);
  EXPECT_NEAR(r.u.v, 0.015, 1e-12);  // s = min(0.015 / 0.15, 0.08725 / 0.4) = 0.1
  EXPECT_NEAR(r.u.omega, 0.04, 1e-12);
}

TEST(ResumeRamp, BrakingIsNeverHeldBack) {
  const RampStep lower = rampTowards({0.05, 0.1}, {0.2, 0.5}, kLimits, kDt);
  EXPECT_FALSE(lower.limited);
  EXPECT_EQ(lower.u.v, 0.05);
  EXPECT_EQ(lower.u.omega, 0.1);
  const RampStep stop = rampTowards({0.0, 0.0}, {0.3, 0.0}, kLimits, kDt);
  EXPECT_FALSE(stop.limited);
  EXPECT_EQ(stop.u.v, 0.0);
  EXPECT_EQ(stop.u.omega, 0.0);
}

TEST(ResumeRamp, CrossingZeroCountsFromThePreviousCommand) {
  // 0.01 m/s forward, asked 0.1 backward: 0.015 of change allows 0.005 backward.
  const RampStep r = rampTowards({-0.1, 0.0}, {0.01, 0.0}, kLimits, kDt);
  EXPECT_TRUE(r.limited);
  EXPECT_NEAR(r.u.v, -0.005, 1e-12);
  // Already past the step: zero, which is braking.
  const RampStep far = rampTowards({-0.1, 0.2}, {0.05, 0.2}, kLimits, kDt);
  EXPECT_EQ(far.u.v, 0.0);
  EXPECT_EQ(far.u.omega, 0.0);
}

TEST(ResumeRamp, DiamondDirectionAndStepOnRandomCommands) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> v(-0.3, 0.3), w(-0.8, 0.8), dt(0.0, 0.2);
  for (int i = 0; i < 20000; ++i) {
    const Twist2 desired = *kRampDiamond.saturate({v(rng), w(rng)});
    const Twist2 previous = *kRampDiamond.saturate({v(rng), w(rng)});
    const double h = dt(rng);
    const RampStep r = rampTowards(desired, previous, kLimits, h);
    ASSERT_TRUE(kRampDiamond.contains(r.u, 1e-12));
    ASSERT_NEAR(r.u.v * desired.omega, r.u.omega * desired.v, 1e-12);
    ASSERT_GE(r.u.v * desired.v, 0.0);  // same ray, not the opposite one
    ASSERT_GE(r.u.omega * desired.omega, 0.0);
    ASSERT_TRUE(withinStepOrBraking(r.u.v, previous.v, kLimits.v_accel * h)) << i;
    ASSERT_TRUE(withinStepOrBraking(r.u.omega, previous.omega, kLimits.w_accel * h)) << i;
    if (!r.limited) {
      ASSERT_EQ(r.u.v, desired.v);
      ASSERT_EQ(r.u.omega, desired.omega);
    }
  }
}

TEST(ResumeRamp, BadInputGivesZero) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const RampStep& r : {rampTowards({nan, 0.1}, {}, kLimits, kDt), rampTowards({0.1, 0.1}, {}, kLimits, -1.0),
                            rampTowards({0.1, 0.1}, {}, kLimits, nan), rampTowards({0.1, 0.1}, {nan, 0.0}, kLimits, kDt)}) {
    EXPECT_EQ(r.u.v, 0.0);
    EXPECT_EQ(r.u.omega, 0.0);
    EXPECT_TRUE(r.limited);
  }
  EXPECT_EQ(rampTowards({0.1, 0.1}, {}, kLimits, 0.0).u.v, 0.0);
}

TEST(ResumeRamp, LimitsValidate) {
  EXPECT_EQ(RampLimits().validate(), "");
  RampLimits bad;
  bad.v_accel = 0.0;
  EXPECT_NE(bad.validate().find("v_accel"), std::string::npos);
  bad = RampLimits();
  bad.w_accel = std::numeric_limits<double>::infinity();
  EXPECT_NE(bad.validate().find("w_accel"), std::string::npos);
}
