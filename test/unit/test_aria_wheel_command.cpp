// Command quantisation: never outside the diamond, never from NaN, as close as the
// resolution allows, VEL2's +128 clamp.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "amigobot_tracking/aria/wheel_command.h"

using namespace amigobot_tracking::aria;
using amigobot_tracking::core::DiamondSet;
using amigobot_tracking::core::Twist2;

TEST(AriaWheelCommand, ModeNamesRoundTrip) {
  EXPECT_EQ(parseCommandMode("vel2"), CommandMode::kVel2);
  EXPECT_EQ(parseCommandMode("vel_rvel"), CommandMode::kVelRvel);
  EXPECT_FALSE(parseCommandMode("VEL2"));
  EXPECT_EQ(commandModeName(CommandMode::kVel2), "vel2");
}

TEST(AriaWheelCommand, NaNAndInfinityNeverBecomeCommands) {
  const RobotParams p = RobotParams::amigo();
  const DiamondSet d(0.3, 0.8);
  for (CommandMode mode : {CommandMode::kVel2, CommandMode::kVelRvel}) {
    EXPECT_FALSE(quantizeCommand({std::nan(""), 0.0}, mode, p, d));
    EXPECT_FALSE(quantizeCommand({0.1, std::nan("")}, mode, p, d));
    EXPECT_FALSE(quantizeCommand({INFINITY, 0.0}, mode, p, d));
  }
}

TEST(AriaWheelCommand, RandomCommandsStayInsideTheDiamondAndNearTheTarget) {
  const RobotParams p = RobotParams::amigo();
  std::mt19937 rng(7);
  for (const auto& [v_max, w_max] : {std::pair{0.3, 0.8}, std::pair{0.5, 5.0}, std::pair{0.05, 0.1}}) {
    const DiamondSet d(v_max, w_max);
    std::uniform_real_distribution<double> v(-2 * v_max, 2 * v_max), w(-2 * w_max, 2 * w_max);
    for (int i = 0; i < 5000; ++i) {
      const Twist2 target{v(rng), w(rng)};
      const Twist2 inside = *d.saturate(target);
      for (CommandMode mode : {CommandMode::kVel2, CommandMode::kVelRvel}) {
        const auto cmd = quantizeCommand(target, mode, p, d);
        ASSERT_TRUE(cmd);
        ASSERT_TRUE(d.contains(cmd->twist)) << "v " << target.v << " w " << target.omega;
        EXPECT_EQ(cmd->saturated, !d.contains(target));
        // Each commanded component (VEL and RVEL, or each wheel) moves toward zero.
        if (mode == CommandMode::kVel2) {
          const auto want = amigobot_tracking::core::toWheelSpeeds(inside, p.halfTrack());
          const auto got = amigobot_tracking::core::toWheelSpeeds(cmd->twist, p.halfTrack());
          EXPECT_LE(std::abs(got.left), std::abs(want.left) + 1e-12);
          EXPECT_LE(std::abs(got.right), std::abs(want.right) + 1e-12);
          EXPECT_LE(std::abs(got.left - want.left), 0.04 + 1e-12);
        } else {
          EXPECT_LE(std::abs(cmd->twist.v), std::abs(inside.v) + 1e-12);
          EXPECT_LE(std::abs(cmd->twist.omega), std::abs(inside.omega) + 1e-12);
          EXPECT_LE(std::abs(cmd->twist.v - inside.v), 2e-3 + 1e-12);
          EXPECT_LE(std::abs(cmd->twist.omega - inside.omega), 2 * M_PI / 180 + 1e-12);
        }
      }
    }
  }
}

TEST(AriaWheelCommand, Vel2UsesTwentyMillimetreStepsTowardZero) {
  const RobotParams p = RobotParams::amigo();
  const DiamondSet d(1.0, 1.0 / p.halfTrack());
  auto cmd = quantizeCommand({0.039, 0.0}, CommandMode::kVel2, p, d);
  ASSERT_TRUE(cmd);
  EXPECT_EQ(cmd->first, 1);  // 39 mm/s -> one 20 mm/s unit, not two
  EXPECT_EQ(cmd->second, 1);
  EXPECT_NEAR(cmd->twist.v, 0.02, 1e-12);
  cmd = quantizeCommand({-0.039, 0.0}, CommandMode::kVel2, p, d);
  EXPECT_EQ(cmd->first, -1);
}

TEST(AriaWheelCommand, Vel2NeverSendsPlus128) {
  RobotParams p = RobotParams::amigo();
  p.dynamics.max_velocity = 5.0;  // a fast robot: 5000 mm/s / 20 = 250 units would overflow a byte
  const DiamondSet d(5.0, 5.0 / p.halfTrack());
  const auto cmd = quantizeCommand({4.0, 0.0}, CommandMode::kVel2, p, d);
  ASSERT_TRUE(cmd);
  EXPECT_EQ(cmd->first, 127);
  EXPECT_EQ(cmd->second, 127);
}

TEST(AriaWheelCommand, VelRvelIsExactOnTheLattice) {
  const RobotParams p = RobotParams::amigo();
  const DiamondSet d(0.3, 0.8);
  const auto cmd = quantizeCommand({0.1, -10 * M_PI / 180}, CommandMode::kVelRvel, p, d);
  ASSERT_TRUE(cmd);
  EXPECT_EQ(cmd->first, 100);
  EXPECT_EQ(cmd->second, -10);
}

TEST(WheelCommand, VelAndRvelOrderNeverLeavesTheRobotOutsideTheDiamond) {
  const DiamondSet diamond(0.3, 0.8);
  // Turning on the spot -> straight at full speed: VEL first would hold (0.3, 0.8).
  EXPECT_TRUE(rotationFirst({0.0, 0.8}, {0.3, 0.0}, diamond));
  // Straight -> turning on the spot: VEL first holds (0, 0), which is inside.
  EXPECT_FALSE(rotationFirst({0.3, 0.0}, {0.0, 0.8}, diamond));
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto randomInside = [&]() {
    const Twist2 u{0.3 * unit(rng), 0.8 * unit(rng)};
    return *diamond.saturate(u);
  };
  for (int i = 0; i < 20000; ++i) {
    const Twist2 held = randomInside(), next = randomInside();
    const Twist2 between = rotationFirst(held, next, diamond) ? Twist2{held.v, next.omega}
                                                                    : Twist2{next.v, held.omega};
    ASSERT_LE(diamond.normalizedNorm(between), 1.0 + 1e-12) << "held " << held.v << "," << held.omega
                                                            << " next " << next.v << "," << next.omega;
  }
}
