// Ray casting for the simulated laser.
#include <gtest/gtest.h>

#include <cmath>

#include "amigobot_tracking/core/raycast.h"

using namespace amigobot_tracking::core;

TEST(Raycast, RayHitsTheNearSideOfADisk) {
  const Disk disk{{3.0, 0.0}, 0.5};
  EXPECT_NEAR(rayDiskDistance({0.0, 0.0}, {1.0, 0.0}, disk), 2.5, 1e-12);
  EXPECT_LT(rayDiskDistance({0.0, 0.0}, {-1.0, 0.0}, disk), 0.0);  // behind
  EXPECT_LT(rayDiskDistance({0.0, 0.0}, {0.0, 1.0}, disk), 0.0);   // misses
  EXPECT_EQ(rayDiskDistance({3.1, 0.0}, {1.0, 0.0}, disk), 0.0);   // inside
  // Tangent ray at distance r: grazes at the tangent point.
  EXPECT_NEAR(rayDiskDistance({0.0, 0.5}, {1.0, 0.0}, disk), 3.0, 1e-6);
}

TEST(Raycast, ScanFollowsRep117AndTheSensorPose) {
  ScanGeometry g;
  g.angle_min = -M_PI / 2;
  g.angle_increment = M_PI / 2;
  g.beams = 3;  // right, ahead, left
  g.range_max = 5.0;
  const std::vector<Disk> disks = {{{0.0, 3.0}, 0.5}, {{0.0, -10.0}, 0.5}};
  // Sensor at the origin facing +x: the disk at +y is on the left beam.
  std::vector<float> r = raycastScan({0.0, 0.0, 0.0}, disks, g);
  EXPECT_TRUE(std::isinf(r[0]) && r[0] > 0);  // beyond range_max: +inf
  EXPECT_TRUE(std::isinf(r[1]) && r[1] > 0);
  EXPECT_NEAR(r[2], 2.5f, 1e-6);
  // Facing +y: the disk is ahead.
  r = raycastScan({0.0, 0.0, M_PI / 2}, disks, g);
  EXPECT_NEAR(r[1], 2.5f, 1e-6);
  // Too close: -inf.
  r = raycastScan({0.0, 2.48, M_PI / 2}, disks, g);
  EXPECT_TRUE(std::isinf(r[1]) && r[1] < 0);
}

TEST(Raycast, NearestOfOverlappingDisksWins) {
  ScanGeometry g;
  g.angle_min = 0.0;
  g.beams = 1;
  const std::vector<float> r = raycastScan({0.0, 0.0, 0.0}, {{{4.0, 0.0}, 1.0}, {{2.0, 0.0}, 0.5}}, g);
  EXPECT_NEAR(r[0], 1.5f, 1e-6);
}
