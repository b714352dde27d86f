// Ray casting for the simulated laser.
#include <gtest/gtest.h>

#include <cmath>

#include "amigobot_tracking/world/raycast.h"

using namespace amigobot_tracking::core;
using namespace amigobot_tracking::world;

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
  ScanGeometry g;  // 3 beams: right, ahead, left
  g.angle_min = -M_PI / 2;
  g.angle_increment = M_PI / 2;
  g.range_min = 0.05;
  g.range_max = 5.0;
  const std::vector<Disk> disks = {{{0.0, 3.0}, 0.5}, {{0.0, -10.0}, 0.5}};
  // Sensor at the origin facing +x: the disk at +y is on the left beam.
  std::vector<float> r = raycastScan({0.0, 0.0, 0.0}, disks, g, 3);
  EXPECT_TRUE(std::isinf(r[0]) && r[0] > 0);  // beyond range_max: +inf
  EXPECT_TRUE(std::isinf(r[1]) && r[1] > 0);
  EXPECT_NEAR(r[2], 2.5f, 1e-6);
  // Facing +y: the disk is ahead.
  r = raycastScan({0.0, 0.0, M_PI / 2}, disks, g, 3);
  EXPECT_NEAR(r[1], 2.5f, 1e-6);
  // Too close: -inf.
  r = raycastScan({0.0, 2.48, M_PI / 2}, disks, g, 3);
  EXPECT_TRUE(std::isinf(r[1]) && r[1] < 0);
}

TEST(Raycast, RaycastScanTurnsBackIntoTheSameDisks) {
  // Round trip with the laser -> obstacles extraction: a 0.1 m pillar 2 m ahead.
  ScanGeometry g;
  g.angle_min = -M_PI;
  g.angle_increment = 2 * M_PI / 720;
  g.range_min = 0.05;
  g.range_max = 8.0;
  const Disk pillar{{2.0, 0.0}, 0.1};
  const std::vector<float> ranges = raycastScan({0.0, 0.0, 0.0}, {pillar}, g, 720);
  std::vector<Disk> disks;
  ASSERT_TRUE(scanToObstacles(g, ranges, Eigen::Affine2d::Identity(), ScanObstacleConfig(), &disks));
  ASSERT_FALSE(disks.empty());
  for (const Disk& d : disks) EXPECT_LT((d.center - pillar.center).norm(), 0.15);
}

TEST(Raycast, NearestOfOverlappingDisksWins) {
  ScanGeometry g;
  g.angle_increment = 0.01;
  g.range_min = 0.05;
  g.range_max = 8.0;
  const std::vector<float> r = raycastScan({0.0, 0.0, 0.0}, {{{4.0, 0.0}, 1.0}, {{2.0, 0.0}, 0.5}}, g, 1);
  EXPECT_NEAR(r[0], 1.5f, 1e-6);
}
