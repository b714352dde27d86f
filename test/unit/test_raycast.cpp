// Ray casting for the simulated lasers: disks, walls and solid polygons, REP 117 values.
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
  World disks;
  disks.obstacles = {{{0.0, 3.0}, 0.5}, {{0.0, -10.0}, 0.5}};
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
  const std::vector<float> ranges = raycastScan({0.0, 0.0, 0.0}, disksOnly({pillar}), g, 720);
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
  World overlapping;
  overlapping.obstacles = {{{4.0, 0.0}, 1.0}, {{2.0, 0.0}, 0.5}};
  const std::vector<float> r = raycastScan({0.0, 0.0, 0.0}, overlapping, g, 1);
  EXPECT_NEAR(r[0], 1.5f, 1e-6);
}

TEST(Raycast, RayMeetsASegmentAtItsAnalyticDistance) {
  const Segment wall{{2.0, -1.0}, {2.0, 3.0}};
  EXPECT_NEAR(raySegmentDistance({0.0, 0.0}, {1.0, 0.0}, wall), 2.0, 1e-12);
  const Eigen::Vector2d diagonal = Eigen::Vector2d(1.0, 1.0).normalized();
  EXPECT_NEAR(raySegmentDistance({0.0, 0.0}, diagonal, wall), 2.0 * std::sqrt(2.0), 1e-12);
  EXPECT_LT(raySegmentDistance({0.0, 0.0}, {-1.0, 0.0}, wall), 0.0);               // behind
  EXPECT_LT(raySegmentDistance({0.0, 0.0}, {0.0, 1.0}, wall), 0.0);                // parallel
  EXPECT_LT(raySegmentDistance({0.0, 3.5}, {1.0, 0.0}, wall), 0.0);                // past its end
  EXPECT_NEAR(raySegmentDistance({0.0, 3.0}, {1.0, 0.0}, wall), 2.0, 1e-12);       // its end point
}

TEST(Raycast, WallsInARoomFollowRep117) {
  // A 4 m x 2 m room around the origin, a 0.5 m gap (doorway) in its east wall at y = 0.
  World room;
  room.walls = {{{-2.0, -1.0}, {2.0, -1.0}}, {{2.0, -1.0}, {2.0, -0.25}}, {{2.0, 0.25}, {2.0, 1.0}},
                {{2.0, 1.0}, {-2.0, 1.0}}, {{-2.0, 1.0}, {-2.0, -1.0}}};
  ScanGeometry g;  // 8 beams, 45 degrees apart, from straight back
  g.angle_min = -M_PI;
  g.angle_increment = M_PI / 4;
  g.range_min = 0.05;
  g.range_max = 8.0;
  const std::vector<float> r = raycastScan({0.5, 0.0, 0.0}, room, g, 8);
  EXPECT_NEAR(r[0], 2.5f, 1e-6);                                   // west wall, straight back
  EXPECT_NEAR(r[1], static_cast<float>(std::sqrt(2.0)), 1e-6);     // south, 45 deg: 1 / sin 45
  EXPECT_NEAR(r[2], 1.0f, 1e-6);                                   // south wall
  EXPECT_NEAR(r[3], static_cast<float>(std::sqrt(2.0)), 1e-6);     // south-east: the south wall at x = 1.5
  EXPECT_TRUE(std::isinf(r[4]) && r[4] > 0) << "through the doorway: nothing within range";
  EXPECT_NEAR(r[6], 1.0f, 1e-6);                                   // north wall
  // range_max short of the walls: +inf; a sensor on a wall: -inf.
  g.range_max = 0.9;
  EXPECT_TRUE(std::isinf(raycastScan({0.5, 0.0, 0.0}, room, g, 8)[2]));
  g.range_max = 8.0;
  const std::vector<float> touching = raycastScan({0.5, -0.99, 0.0}, room, g, 8);
  EXPECT_TRUE(std::isinf(touching[2]) && touching[2] < 0) << touching[2];
}

TEST(Raycast, APolygonIsSolidFromOutsideAndInside) {
  World table;
  table.polygons = {{{{1.0, -0.5}, {2.0, -0.5}, {2.0, 0.5}, {1.0, 0.5}}}};
  ScanGeometry g;  // 4 beams: back, right, ahead, left
  g.angle_min = -M_PI;
  g.angle_increment = M_PI / 2;
  g.range_min = 0.05;
  g.range_max = 8.0;
  std::vector<float> r = raycastScan({0.0, 0.0, 0.0}, table, g, 4);
  EXPECT_NEAR(r[2], 1.0f, 1e-6);  // its near edge, not its far one
  EXPECT_TRUE(std::isinf(r[0]) && r[0] > 0);
  // Seen from beyond, turned around: the far edge is now the near one.
  r = raycastScan({3.0, 0.0, M_PI}, table, g, 4);
  EXPECT_NEAR(r[2], 1.0f, 1e-6);
  // A sensor inside the table sees it at range 0 on every beam: -inf.
  r = raycastScan({1.5, 0.2, 0.3}, table, g, 4);
  for (float range : r) EXPECT_TRUE(std::isinf(range) && range < 0) << range;
}

TEST(Raycast, NearestOfDisksAndWallsWins) {
  World w;
  w.obstacles = {{{3.0, 0.0}, 0.5}};
  w.walls = {{{2.0, -1.0}, {2.0, 1.0}}};
  ScanGeometry g;
  g.angle_increment = 0.01;
  g.range_min = 0.05;
  g.range_max = 8.0;
  EXPECT_NEAR(raycastScan({0.0, 0.0, 0.0}, w, g, 1)[0], 2.0f, 1e-6);
  w.obstacles[0].center.x() = 1.0;  // the disk now in front of the wall
  EXPECT_NEAR(raycastScan({0.0, 0.0, 0.0}, w, g, 1)[0], 0.5f, 1e-6);
}
