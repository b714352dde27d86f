// Offset-point feedback linearisation (5)-(8) and the exact unicycle integrator.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "amigobot_tracking/core/robot/offset_point.h"
#include "amigobot_tracking/core/robot/unicycle.h"

using namespace amigobot_tracking::core;

TEST(OffsetPoint, JacobianTimesInverseIsIdentity) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-10.0, 10.0), offset(0.01, 2.0);
  for (int i = 0; i < 1000; ++i) {
    const double th = angle(rng), r = offset(rng);
    const Eigen::Matrix2d product = offsetJacobian(th, r) * offsetJacobianInverse(th, r);
    EXPECT_TRUE(product.isApprox(Eigen::Matrix2d::Identity(), 1e-12)) << product;
  }
}

TEST(OffsetPoint, PointIsAheadOfTheCentre) {
  const Eigen::Vector2d p = offsetPoint({1.0, 2.0, M_PI / 2}, 0.3);
  EXPECT_NEAR(p.x(), 1.0, 1e-15);
  EXPECT_NEAR(p.y(), 2.3, 1e-15);
}

TEST(OffsetPoint, MovesWithUrUnderTheUnicycle) {
  // Finite-difference check of (7): commanding (v, w) = G^-1 u_r moves p_r at u_r.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  const double r = 0.3, h = 1e-6;
  for (int i = 0; i < 200; ++i) {
    const Pose2 pose{uni(rng), uni(rng), 3.0 * uni(rng)};
    const Eigen::Vector2d u_r(uni(rng), uni(rng));
    const Twist2 u = offsetVelocityToTwist(u_r, pose.theta, r);
    const Pose2 next = integrateUnicycle(pose, u, h);
    const Eigen::Vector2d rate = (offsetPoint(next, r) - offsetPoint(pose, r)) / h;
    EXPECT_NEAR(rate.x(), u_r.x(), 1e-5);
    EXPECT_NEAR(rate.y(), u_r.y(), 1e-5);
    const Eigen::Vector2d back = twistToOffsetVelocity(u, pose.theta, r);
    EXPECT_TRUE(back.isApprox(u_r, 1e-12));
  }
}

TEST(Unicycle, FullCircleReturnsToStart) {
  Pose2 pose{1.0, -1.0, 0.3};
  const Twist2 u{0.5, 2.0 * M_PI / 10.0};
  for (int i = 0; i < 1000; ++i) pose = integrateUnicycle(pose, u, 0.01);
  EXPECT_NEAR(pose.x, 1.0, 1e-9);
  EXPECT_NEAR(pose.y, -1.0, 1e-9);
  EXPECT_NEAR(std::remainder(pose.theta - 0.3, 2 * M_PI), 0.0, 1e-9);
}

TEST(Unicycle, ArcIsExactForOneLargeStep) {
  // A quarter circle of radius 1 in one step lands exactly on the arc.
  const Pose2 next = integrateUnicycle({0.0, 0.0, 0.0}, {M_PI / 2, M_PI / 2}, 1.0);
  EXPECT_NEAR(next.x, 1.0, 1e-12);
  EXPECT_NEAR(next.y, 1.0, 1e-12);
  EXPECT_NEAR(next.theta, M_PI / 2, 1e-12);
}

TEST(Unicycle, StraightLineWithoutTurn) {
  const Pose2 next = integrateUnicycle({0.0, 0.0, M_PI / 4}, {1.0, 0.0}, 2.0);
  EXPECT_NEAR(next.x, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(next.y, std::sqrt(2.0), 1e-12);
}

TEST(Unicycle, HeadingWrapped) {
  const Pose2 next = integrateUnicycle({0.0, 0.0, 3.0}, {0.0, 1.0}, 1.0);
  EXPECT_NEAR(next.theta, 4.0 - 2 * M_PI, 1e-12);
  EXPECT_NEAR(wrapAngle(-M_PI), M_PI, 1e-15);
}
