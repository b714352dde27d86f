#include <gtest/gtest.h>

#include "amigobot_tracking/core/perception/obstacle_motion.h"

using amigobot_tracking::core::MotionLeg;
using amigobot_tracking::core::ObstacleMotion;

namespace {

// A person who walks 2 s east at 1 m/s, stands 1 s, then walks 1 s north at 0.5 m/s.
ObstacleMotion walkStopTurn() {
  ObstacleMotion m;
  m.start = {1.0, 2.0};
  m.start_time = 3.0;
  m.legs = {MotionLeg{2.0, {1.0, 0.0}}, MotionLeg{1.0, {0.0, 0.0}}, MotionLeg{1.0, {0.0, 0.5}}};
  return m;
}

}  // namespace

TEST(ObstacleMotion, StandsBeforeStartAndAfterTheLastLeg) {
  const ObstacleMotion m = walkStopTurn();
  EXPECT_TRUE(m.positionAt(0.0).isApprox(Eigen::Vector2d(1.0, 2.0)));
  EXPECT_TRUE(m.velocityAt(2.9).isZero());
  EXPECT_TRUE(m.positionAt(100.0).isApprox(Eigen::Vector2d(3.0, 2.5)));
  EXPECT_TRUE(m.velocityAt(100.0).isZero());
}

TEST(ObstacleMotion, WalksStopsAndTurns) {
  const ObstacleMotion m = walkStopTurn();
  EXPECT_TRUE(m.positionAt(4.0).isApprox(Eigen::Vector2d(2.0, 2.0)));
  EXPECT_TRUE(m.velocityAt(4.0).isApprox(Eigen::Vector2d(1.0, 0.0)));
  EXPECT_TRUE(m.velocityAt(5.5).isZero());
  EXPECT_TRUE(m.positionAt(5.5).isApprox(Eigen::Vector2d(3.0, 2.0)));
  EXPECT_TRUE(m.positionAt(6.5).isApprox(Eigen::Vector2d(3.0, 2.25)));
  EXPECT_TRUE(m.velocityAt(6.5).isApprox(Eigen::Vector2d(0.0, 0.5)));
}

// What a tracker knows of a person who stopped: the way they last walked (Disk::resume_velocity).
TEST(ObstacleMotion, AStandingPersonKeepsTheWayTheyLastWalked) {
  const ObstacleMotion m = walkStopTurn();
  EXPECT_TRUE(m.resumeVelocityAt(2.0).isZero()) << "never walked yet";
  EXPECT_TRUE(m.resumeVelocityAt(4.0).isZero()) << "walking: its velocity says it all";
  EXPECT_TRUE(m.resumeVelocityAt(5.5).isApprox(Eigen::Vector2d(1.0, 0.0)));
  EXPECT_TRUE(m.resumeVelocityAt(100.0).isApprox(Eigen::Vector2d(0.0, 0.5))) << "after the last leg: its way";
  ObstacleMotion loop;  // out and back, pausing at each end; the pause at the start wraps round
  loop.legs = {MotionLeg{1.0, {0.0, 0.0}}, MotionLeg{2.0, {0.5, 0.0}}, MotionLeg{1.0, {0.0, 0.0}},
               MotionLeg{2.0, {-0.5, 0.0}}};
  loop.repeat = true;
  EXPECT_TRUE(loop.resumeVelocityAt(0.5).isZero()) << "the first cycle's pause: no walk before it";
  EXPECT_TRUE(loop.resumeVelocityAt(3.5).isApprox(Eigen::Vector2d(0.5, 0.0)));
  EXPECT_TRUE(loop.resumeVelocityAt(6.5).isApprox(Eigen::Vector2d(-0.5, 0.0))) << "the cycle before counts";
}

TEST(ObstacleMotion, RepeatsAClosedPath) {
  ObstacleMotion m;
  m.legs = {MotionLeg{2.0, {0.5, 0.0}}, MotionLeg{2.0, {-0.5, 0.0}}};
  m.repeat = true;
  EXPECT_EQ(m.validate(), "");
  EXPECT_TRUE(m.positionAt(5.0).isApprox(Eigen::Vector2d(0.5, 0.0)));
  EXPECT_TRUE(m.velocityAt(7.0).isApprox(Eigen::Vector2d(-0.5, 0.0)));
}

TEST(ObstacleMotion, NamesTheBadLeg) {
  ObstacleMotion m = walkStopTurn();
  m.legs[1].duration = 0.0;
  EXPECT_NE(m.validate().find("legs[1].duration"), std::string::npos);
  m = walkStopTurn();
  m.legs[2].velocity.x() = NAN;
  EXPECT_NE(m.validate().find("legs[2].velocity"), std::string::npos);
  m = walkStopTurn();
  m.repeat = true;  // ends 2.06 m from its start
  EXPECT_NE(m.validate().find("repeat"), std::string::npos);
}
