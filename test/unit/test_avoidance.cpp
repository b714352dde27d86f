// Repulsive term u_c of eq. (10).
#include <gtest/gtest.h>

#include <cmath>

#include "amigobot_tracking/core/law/avoidance.h"

using namespace amigobot_tracking::core;

namespace {
const Eigen::Vector2d kHeading(1.0, 0.0);
const double kRadius = 0.2, kDelta = 0.1;
const Disk kDisk{{1.0, 0.5}, 0.3};
}  // namespace

TEST(Avoidance, ZeroOutsideDetectionDistance) {
  // Detection distance from the centre: delta + R + r_o = 0.6.
  for (double angle = 0.0; angle < 2 * M_PI; angle += 0.1) {
    const Eigen::Vector2d p = kDisk.center + 0.6001 * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    const AvoidanceResult r = repulsiveTerm(p, {kDisk}, kRadius, kDelta, kHeading);
    EXPECT_EQ(r.u_c, Eigen::Vector2d::Zero());
    EXPECT_EQ(r.detected, 0);
    EXPECT_NEAR(r.min_clearance, 0.1001, 1e-9);
  }
}

TEST(Avoidance, PointsAwayAndGrowsTowardContact) {
  const Eigen::Vector2d dir = Eigen::Vector2d(1.0, -2.0).normalized();
  double previous = 0.0;
  for (double margin = 0.099; margin > 1e-3; margin *= 0.8) {
    const Eigen::Vector2d p = kDisk.center + (0.5 + margin) * dir;
    const AvoidanceResult r = repulsiveTerm(p, {kDisk}, kRadius, kDelta, kHeading);
    EXPECT_EQ(r.detected, 1);
    EXPECT_GT(r.u_c.dot(dir), 0.0);
    EXPECT_NEAR(std::abs(r.u_c.normalized().dot(dir)), 1.0, 1e-12);
    EXPECT_GT(r.u_c.norm(), previous);
    // Closed form: (1/margin - 1/delta) * distance.
    EXPECT_NEAR(r.u_c.norm(), (1.0 / margin - 1.0 / kDelta) * (0.5 + margin), 1e-9);
    previous = r.u_c.norm();
  }
}

TEST(Avoidance, VanishesContinuouslyAtTheDetectionEdge) {
  const Eigen::Vector2d p = kDisk.center + Eigen::Vector2d(0.5999999, 0.0);
  EXPECT_LT(repulsiveTerm(p, {kDisk}, kRadius, kDelta, kHeading).u_c.norm(), 1e-4);
}

TEST(Avoidance, FiniteInsideContactAndOnTheCentre) {
  const AvoidanceResult inside = repulsiveTerm(kDisk.center + Eigen::Vector2d(0.1, 0.0), {kDisk}, kRadius, kDelta,
                                               kHeading, 1e-3);
  EXPECT_TRUE(inside.u_c.allFinite());
  EXPECT_GT(inside.u_c.x(), 0.0);
  EXPECT_LT(inside.min_clearance, 0.0);
  const AvoidanceResult centre = repulsiveTerm(kDisk.center, {kDisk}, kRadius, kDelta, kHeading, 1e-3);
  EXPECT_TRUE(centre.u_c.allFinite());
  EXPECT_LT(centre.u_c.x(), 0.0);  // backs away against the heading
}

TEST(Avoidance, SumsOverDetectedObstaclesOnly) {
  const Disk left{{-0.55, 0.0}, 0.3}, right{{0.55, 0.0}, 0.3}, far{{5.0, 5.0}, 0.3};
  const AvoidanceResult r = repulsiveTerm({0.0, 0.0}, {left, right, far}, 0.2, kDelta, kHeading);
  EXPECT_EQ(r.detected, 2);
  EXPECT_NEAR(r.u_c.norm(), 0.0, 1e-12);  // symmetric pushes cancel
  EXPECT_NEAR(r.min_clearance, 0.05, 1e-12);
  const AvoidanceResult one = repulsiveTerm({0.1, 0.0}, {left, right, far}, 0.2, kDelta, kHeading);
  EXPECT_LT(one.u_c.x(), 0.0);  // closer to the right disk: pushed left
}

TEST(Avoidance, ClearanceWithoutObstaclesIsInfinite) {
  EXPECT_TRUE(std::isinf(clearance({0.0, 0.0}, 0.2, {})));
  EXPECT_NEAR(clearance({0.0, 0.0}, 0.2, {kDisk}), std::hypot(1.0, 0.5) - 0.5, 1e-12);
}
