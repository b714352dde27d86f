// The recommended law with moving obstacles (navigation_field.h's withPredictedPaths and
// goalOutOfPaths, recommended_law.cpp): the field routes round where a person will be, not
// only where they are, and aims beside the path of one about to walk through the target.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "amigobot_tracking/core/law/navigation_field.h"
#include "amigobot_tracking/core/law/recommended_law.h"

using namespace amigobot_tracking::core;

namespace {

Disk person(double x, double y, double vx, double vy) {
  Disk d;
  d.center = {x, y};
  d.radius = 0.25;
  d.velocity = {vx, vy};
  return d;
}

// The robot at the origin heading +x (p_r at (0.3, 0)), the target 1 m ahead of p_r, still.
RecommendedCommand commandAmong(const std::vector<Disk>& disks, double lookahead) {
  ControllerConfig config;
  config.law = "recommended";
  config.recommended.obstacle_lookahead = lookahead;
  RecommendedInput in;
  in.pose = {0.0, 0.0, 0.0};
  in.p_r = {0.3, 0.0};
  in.e = {1.0, 0.0};
  in.rho = 1.5;
  return recommendedCommand(config, DiamondSet(config.v_max, config.w_max), in, disks);
}

}  // namespace

TEST(ObstaclePaths, CopiesAMovingDiskAlongItsPathAndLeavesStaticOnesAlone) {
  const Disk still{Eigen::Vector2d(1.0, 1.0), 0.3, Eigen::Vector2d::Zero()};
  const Disk walker = person(0.0, -2.0, 0.0, 0.8);
  const std::vector<Disk> seen = withPredictedPaths({still, walker}, 2.0, Eigen::Vector2d(0.0, -1.0), 100.0, 0.18);
  ASSERT_GT(seen.size(), 2u);
  EXPECT_EQ(seen[0].center, still.center);
  EXPECT_EQ(seen[1].center, walker.center);
  // Copies at most half a radius apart, the last where the walker is after 2 s.
  Eigen::Vector2d last = walker.center;
  for (size_t k = 2; k < seen.size(); ++k) {
    EXPECT_LE((seen[k].center - last).norm(), 0.5 * walker.radius + 1e-12);
    EXPECT_DOUBLE_EQ(seen[k].radius, walker.radius);
    last = seen[k].center;
  }
  EXPECT_TRUE(last.isApprox(Eigen::Vector2d(0.0, -0.4), 1e-12));
  EXPECT_EQ(withPredictedPaths({still, walker}, 0.0, Eigen::Vector2d(0.0, -1.0), 100.0, 0.18).size(), 2u);
  // A robot 10 m away at 0.3 m/s reaches none of the copies before the walker has gone by.
  EXPECT_EQ(withPredictedPaths({still, walker}, 2.0, Eigen::Vector2d(10.0, 0.0), 0.3, 0.18).size(), 2u);
}

// A person who walked north and stands (velocity 0, resume_velocity north) may walk on at any
// moment: the field sees the path they would walk, every copy of it (a walking person's far
// copies are dropped once the robot cannot reach them before the person has gone by), and the
// goal moves off it. A standing disk never seen walking stays as it is.
TEST(ObstaclePaths, APersonWhoStoppedIsSeenAlongTheWayTheyWouldWalkOn) {
  Disk stood = person(0.0, -0.3, 0.0, 0.0);
  stood.resume_velocity = {0.0, 0.7};
  const std::vector<Disk> seen = withPredictedPaths({stood}, 2.0, Eigen::Vector2d(10.0, 0.0), 0.3, 0.18);
  ASSERT_GT(seen.size(), 10u) << "a robot 10 m off still meets a person who starts when it arrives";
  EXPECT_TRUE(seen.back().center.isApprox(Eigen::Vector2d(0.0, -0.3 + 1.4), 1e-12));
  for (const Disk& d : seen) EXPECT_NEAR(d.center.x(), 0.0, 1e-12);
  EXPECT_EQ(withPredictedPaths({person(0.0, -0.3, 0.0, 0.0)}, 2.0, Eigen::Vector2d(10.0, 0.0), 0.3, 0.18).size(), 1u);
  // The target 0.3 m ahead of them, on that way: the goal moves beside it, to the robot's side.
  const Eigen::Vector2d goal = goalOutOfPaths({0.0, 0.0}, {-1.0, 0.0}, {stood}, 2.0, 0.18, 0.1);
  EXPECT_NEAR(goal.x(), -(0.18 + 0.25 + 0.1), 1e-9);
}

TEST(ObstaclePaths, GoalOnAPathMovesToItsEdgeOnTheRobotsSide) {
  const Disk walker = person(-2.0, 0.0, 0.8, 0.0);  // walks along y = 0 toward +x
  const double zone = 0.18 + 0.25 + 0.1;
  // On the line: to p_r's side (p_r below it).
  const Eigen::Vector2d below = goalOutOfPaths({1.0, 0.0}, {0.3, -0.05}, {walker}, 5.0, 0.18, 0.1);
  EXPECT_NEAR(below.x(), 1.0, 1e-12);
  EXPECT_NEAR(below.y(), -zone, 1e-12);
  // Off the line, within the zone: straight out on its own side.
  const Eigen::Vector2d above = goalOutOfPaths({1.0, 0.2}, {0.3, -0.05}, {walker}, 5.0, 0.18, 0.1);
  EXPECT_NEAR(above.y(), zone, 1e-12);
  // Beyond where the walker gets within the horizon, or without a horizon: unchanged.
  EXPECT_EQ(goalOutOfPaths({3.0, 0.0}, {0.3, 0.0}, {walker}, 5.0, 0.18, 0.1), Eigen::Vector2d(3.0, 0.0));
  EXPECT_EQ(goalOutOfPaths({1.0, 0.0}, {0.3, 0.0}, {walker}, 0.0, 0.18, 0.1), Eigen::Vector2d(1.0, 0.0));
}

// A person walks up from behind along the robot's line at 0.8 m/s. The law used to drive on at
// the target (and, once they were close, ahead of them); now it heads out of their path.
TEST(ObstaclePaths, StepsAsideForAPersonComingFromBehind) {
  const std::vector<Disk> behind = {person(-1.5, 0.05, 0.8, 0.0)};
  const RecommendedCommand now = commandAmong(behind, 0.0);
  ASSERT_TRUE(now.valid);
  EXPECT_NEAR(now.direction.y(), 0.0, 1e-9);
  const RecommendedCommand aside = commandAmong(behind, 2.0);
  ASSERT_TRUE(aside.valid);
  EXPECT_LT(aside.direction.y(), -0.2);  // to p_r's side of the path line (below it)
}
