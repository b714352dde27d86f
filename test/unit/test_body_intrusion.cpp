// Something inside the body stops the robot (core/perception/body_intrusion.h).
#include <gtest/gtest.h>

#include "amigobot_tracking/core/perception/body_intrusion.h"

using namespace amigobot_tracking::core;

TEST(BodyIntrusion, NothingNearIsNothing) {
  const std::vector<Disk> wall = {{{0.30, 0.0}, 0.10, {0, 0}}};  // body edge 0.18, wall 0.02 beyond
  EXPECT_EQ(bodyIntrusion({0, 0}, 0.18, wall, {}), "");
}

TEST(BodyIntrusion, ALaserDiskCentredInsideTheBodyIsNamed) {  // issue 25: points at 0.06 m
  const std::vector<Disk> blind = {{{1.06, 2.0}, 0.03, {0, 0}}};
  const std::string why = bodyIntrusion({1.0, 2.0}, 0.18, blind, {});
  EXPECT_EQ(why.rfind("laser obstacle 0.060 m from the centre", 0), 0u) << why;
}

TEST(BodyIntrusion, AVirtualObstacleAroundTheRobotIsNamed) {  // issue 25: radius 1e6 around it
  VirtualObstacle huge;
  huge.id = "huge";
  huge.disk = {{5.0, 0.0}, 100.0, {0, 0}};
  const std::string why = bodyIntrusion({0, 0}, 0.18, {}, {huge});
  EXPECT_NE(why.find("virtual obstacle 'huge'"), std::string::npos) << why;
  huge.disk.radius = 4.9;  // beside the robot, not around it
  EXPECT_EQ(bodyIntrusion({0, 0}, 0.18, {}, {huge}), "");
}
