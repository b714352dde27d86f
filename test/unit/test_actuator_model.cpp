#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "amigobot_tracking/core/robot/actuator_model.h"

using amigobot_tracking::core::ActuatorLimits;
using amigobot_tracking::core::ActuatorModel;
using amigobot_tracking::core::kAmigoHalfTrack;
using amigobot_tracking::core::Twist2;

namespace {

constexpr double kStep = 0.001;  // [s]

ActuatorLimits noDelay() {
  ActuatorLimits l;  // the AmigoBot's ramps
  l.cycle = 0.0;
  l.latency = 0.0;
  return l;
}

// Runs `command` for `duration`; returns the distance and turn integrated from the mean velocities.
Twist2 run(ActuatorModel* m, Twist2 command, double duration) {
  Twist2 travelled;
  const long steps = std::lround(duration / kStep);
  for (long i = 0; i < steps; ++i) {
    const Twist2 mean = m->step(command, kStep);
    travelled.v += mean.v * kStep;
    travelled.omega += mean.omega * kStep;
  }
  return travelled;
}

// The first time (from now) at which v reaches `value` within 1e-9.
double timeToReach(ActuatorModel* m, Twist2 command, double value, double give_up = 5.0) {
  const double start = m->time();
  while (m->time() - start < give_up) {
    m->step(command, kStep);
    if (std::abs(m->velocity().v - value) < 1e-9) return m->time() - start;
  }
  return -1.0;
}

}  // namespace

TEST(ActuatorModel, RampsAtTheAccelAndDecelRates) {
  ActuatorModel m(noDelay(), kAmigoHalfTrack);
  EXPECT_NEAR(timeToReach(&m, {0.3, 0.0}, 0.3), 0.3 / 0.3, 2 * kStep);  // TransAccel 0.3 m/s^2
  EXPECT_NEAR(timeToReach(&m, {0.0, 0.0}, 0.0), 0.3 / 0.75, 2 * kStep);  // TransDecel 0.75 m/s^2
  // Rotation: 1 rad/s at 1.745 rad/s^2.
  ActuatorModel r(noDelay(), kAmigoHalfTrack);
  run(&r, {0.0, 1.0}, 0.5);
  EXPECT_NEAR(r.velocity().omega, 0.5 * 1.745, 1e-9);
}

TEST(ActuatorModel, MeanVelocityIntegratesTheRamp) {
  ActuatorModel m(noDelay(), kAmigoHalfTrack);
  // 1 s of ramp to 0.3 m/s covers 0.15 m, then 1 s at 0.3 m/s.
  EXPECT_NEAR(run(&m, {0.3, 0.0}, 2.0).v, 0.15 + 0.3, 1e-9);
  // One long step: the same distance as many short ones.
  ActuatorModel one(noDelay(), kAmigoHalfTrack);
  EXPECT_NEAR(one.step({0.3, 0.0}, 2.0).v * 2.0, 0.45, 1e-12);
}

TEST(ActuatorModel, ReversalDeceleratesToZeroThenAccelerates) {
  ActuatorModel m(noDelay(), kAmigoHalfTrack);
  run(&m, {0.3, 0.0}, 2.0);
  ASSERT_NEAR(m.velocity().v, 0.3, 1e-12);
  // 0.3 -> 0 at 0.75 m/s^2 (0.4 s), then 0 -> -0.3 at 0.3 m/s^2 (1 s).
  EXPECT_NEAR(timeToReach(&m, {-0.3, 0.0}, -0.3), 1.4, 2 * kStep);
  ActuatorModel half(noDelay(), kAmigoHalfTrack);
  run(&half, {0.3, 0.0}, 2.0);
  run(&half, {-0.3, 0.0}, 0.4);
  EXPECT_NEAR(half.velocity().v, 0.0, 1e-9);
}

TEST(ActuatorModel, LatencyAndCycleDelayACommand) {
  ActuatorModel m(ActuatorLimits{}, kAmigoHalfTrack);  // cycle 0.1 s, latency 0.1 s
  run(&m, {0.0, 0.0}, 0.03);
  // Arrives at 0.03 s, counts from the first tick after 0.13 s: the tick at 0.2 s.
  const double start = m.time();
  run(&m, {0.3, 0.0}, 0.2 - start - 0.5 * kStep);
  EXPECT_EQ(m.velocity().v, 0.0) << "moved before the tick at 0.2 s";
  run(&m, {0.3, 0.0}, 0.1);
  EXPECT_NEAR(m.velocity().v, 0.3 * (m.time() - 0.2), 2e-3);
  // Without the cycle: exactly the latency.
  ActuatorLimits l = noDelay();
  l.latency = 0.25;
  ActuatorModel d(l, kAmigoHalfTrack);
  run(&d, {0.3, 0.0}, 0.249);
  EXPECT_EQ(d.velocity().v, 0.0);
  run(&d, {0.3, 0.0}, 0.101);
  EXPECT_NEAR(d.velocity().v, 0.3 * 0.1, 1e-6);
}

TEST(ActuatorModel, ACommandSupersededWithinTheLatencyNeverActs) {
  ActuatorLimits l = noDelay();
  l.latency = 0.1;
  l.cycle = 0.1;
  ActuatorModel m(l, kAmigoHalfTrack);
  // 0.5 m/s between the ticks only: the firmware samples once per cycle and never sees it.
  run(&m, {0.0, 0.0}, 0.02);
  run(&m, {0.5, 0.0}, 0.05);
  run(&m, {0.0, 0.0}, 1.0);
  EXPECT_EQ(m.velocity().v, 0.0);
  EXPECT_EQ(m.setpoint().v, 0.0);
}

TEST(ActuatorModel, WheelSpeedLimitScalesVAndWTogether) {
  ActuatorLimits l = noDelay();
  ActuatorModel m(l, kAmigoHalfTrack);
  // 1 m/s and 5 rad/s ask 1 + 0.0909 * 5 = 1.45 m/s of the outer wheel: scaled by 1/1.45.
  double worst = 0.0;
  for (int i = 0; i < 10000; ++i) {
    m.step({1.0, 5.0}, kStep);
    worst = std::max(worst, std::abs(m.velocity().v) + kAmigoHalfTrack * std::abs(m.velocity().omega));
  }
  const double s = 1.0 / (1.0 + kAmigoHalfTrack * 5.0);
  EXPECT_NEAR(m.velocity().v, s, 1e-9);
  EXPECT_NEAR(m.velocity().omega, 5.0 * s, 1e-9);
  EXPECT_LE(worst, l.max_velocity + 1e-12);
  // The body ceilings clip each axis first.
  ActuatorModel c(l, kAmigoHalfTrack);
  run(&c, {3.0, 0.0}, 10.0);
  EXPECT_NEAR(c.velocity().v, l.max_velocity, 1e-12);
}

TEST(ActuatorModel, RunTimeLimitsTakeEffect) {
  ActuatorModel m(noDelay(), kAmigoHalfTrack);
  ActuatorLimits l = m.limits();
  l.trans_accel = 0.6;  // SETA 600
  m.setLimits(l);
  EXPECT_NEAR(timeToReach(&m, {0.3, 0.0}, 0.3), 0.5, 2 * kStep);
}

TEST(ActuatorModel, BadLimitsAndInputsAreNamed) {
  ActuatorLimits l;
  l.rot_decel = 0.0;
  try {
    ActuatorModel m(l, kAmigoHalfTrack);
    FAIL() << "accepted rot_decel = 0";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("rot_decel"), std::string::npos) << e.what();
  }
  ActuatorLimits nan_latency;
  nan_latency.latency = std::nan("");
  EXPECT_THROW(ActuatorModel(nan_latency, kAmigoHalfTrack), std::invalid_argument);
  EXPECT_THROW(ActuatorModel(ActuatorLimits{}, 0.0), std::invalid_argument);
  ActuatorModel m(ActuatorLimits{}, kAmigoHalfTrack);
  EXPECT_THROW(m.step({std::nan(""), 0.0}, 0.01), std::invalid_argument);
  EXPECT_THROW(m.step({0.0, 0.0}, -0.01), std::invalid_argument);
}
