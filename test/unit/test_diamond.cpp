// Saturation sigma (12) and the diamond input set (2).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "amigobot_tracking/core/robot/diamond.h"

using namespace amigobot_tracking::core;

namespace {

const DiamondSet kDiamond(0.3, 0.8);

std::vector<Twist2> randomInputs(int count) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> exponent(-8.0, 12.0);
  std::vector<Twist2> inputs = {{0.0, 0.0}, {1e300, 0.0}, {0.0, -1e300}, {1e300, 1e300},
                                {std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()},
                                {0.3, 0.0}, {0.0, 0.8}, {-0.15, 0.4}, {5.0, 0.0}, {0.0, -7.0},
                                {std::numeric_limits<double>::denorm_min(), 0.0}};
  for (int i = 0; i < count; ++i) {
    inputs.push_back({unit(rng) * std::pow(10.0, exponent(rng)), unit(rng) * std::pow(10.0, exponent(rng))});
  }
  return inputs;
}

}  // namespace

TEST(Diamond, OutputAlwaysInsideU) {
  for (const Twist2& u : randomInputs(20000)) {
    const auto out = kDiamond.saturate(u);
    ASSERT_TRUE(out.has_value());
    EXPECT_LE(kDiamond.normalizedNorm(*out), 1.0) << "v=" << u.v << " w=" << u.omega;
  }
}

TEST(Diamond, UnchangedInsideU) {
  for (const Twist2& u : randomInputs(20000)) {
    if (!kDiamond.contains(u)) continue;
    const auto out = kDiamond.saturate(u);
    EXPECT_EQ(out->v, u.v);
    EXPECT_EQ(out->omega, u.omega);
  }
}

TEST(Diamond, OutsidePointsLandOnBoundaryWithSameCurvature) {
  int outside = 0;
  for (const Twist2& u : randomInputs(20000)) {
    if (kDiamond.contains(u)) continue;
    ++outside;
    const auto out = kDiamond.saturate(u);
    EXPECT_NEAR(kDiamond.normalizedNorm(*out), 1.0, 1e-12);
    // Same direction in the (v, w) plane: cross product ~ 0 and same signs.
    const double scale = std::max(std::abs(u.v), std::abs(u.omega));
    const double cross = (u.v / scale) * out->omega - (u.omega / scale) * out->v;
    EXPECT_NEAR(cross, 0.0, 1e-12);
    EXPECT_GE(u.v * out->v, 0.0);
    EXPECT_GE(u.omega * out->omega, 0.0);
  }
  EXPECT_GT(outside, 1000);
}

TEST(Diamond, AxisValuesClip) {
  EXPECT_DOUBLE_EQ(kDiamond.saturate({2.0, 0.0})->v, 0.3);
  EXPECT_DOUBLE_EQ(kDiamond.saturate({-2.0, 0.0})->v, -0.3);
  EXPECT_DOUBLE_EQ(kDiamond.saturate({0.0, 9.0})->omega, 0.8);
  EXPECT_DOUBLE_EQ(kDiamond.saturate({0.0, 9.0})->v, 0.0);
}

TEST(Diamond, NonFiniteInputRejected) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(kDiamond.saturate({nan, 0.0}).has_value());
  EXPECT_FALSE(kDiamond.saturate({0.0, nan}).has_value());
  EXPECT_FALSE(kDiamond.saturate({inf, 0.0}).has_value());
  EXPECT_FALSE(kDiamond.saturate({0.1, -inf}).has_value());
  EXPECT_FALSE(kDiamond.contains({nan, 0.0}));
}

TEST(Diamond, WheelLimitFormIsTheSameSet) {
  // alpha = 0.3 m/s, b = 0.375 m gives v_bar = 0.3, w_bar = 0.8.
  const DiamondSet from_wheels = DiamondSet::fromWheelLimit(0.3, 0.375);
  EXPECT_DOUBLE_EQ(from_wheels.vMax(), 0.3);
  EXPECT_DOUBLE_EQ(from_wheels.wMax(), 0.8);
  // Inside U exactly when both wheel speeds are within +-alpha.
  for (const Twist2& u : randomInputs(5000)) {
    if (std::abs(u.v) > 10 || std::abs(u.omega) > 10) continue;
    const WheelSpeeds w = toWheelSpeeds(u, 0.375);
    const bool wheels_ok = std::abs(w.left) <= 0.3 && std::abs(w.right) <= 0.3;
    const double n = from_wheels.normalizedNorm(u);
    if (std::abs(n - 1.0) > 1e-9) {
      EXPECT_EQ(wheels_ok, n <= 1.0);
    }
  }
}

TEST(Diamond, WheelSpeedConversionRoundTrips) {
  const Twist2 u{0.2, -0.5};
  const WheelSpeeds w = toWheelSpeeds(u, 0.091);
  EXPECT_DOUBLE_EQ(w.left, 0.2 + 0.091 * 0.5);
  EXPECT_DOUBLE_EQ(w.right, 0.2 - 0.091 * 0.5);
  const Twist2 back = fromWheelSpeeds(w, 0.091);
  EXPECT_NEAR(back.v, u.v, 1e-15);
  EXPECT_NEAR(back.omega, u.omega, 1e-14);
}
