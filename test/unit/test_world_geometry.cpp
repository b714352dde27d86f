// Distances in the world (world/geometry.h): body clearance to disks, walls and polygons
// (inside a polygon is a collision), and the sonar's cone range to each kind of shape.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "amigobot_tracking/world/geometry.h"

using namespace amigobot_tracking::core;
using namespace amigobot_tracking::world;

namespace {

World table() {
  World w;
  w.polygons = {{{{1.0, -0.5}, {2.0, -0.5}, {2.0, 0.5}, {1.0, 0.5}}}};
  return w;
}

}  // namespace

TEST(WorldGeometry, PointSegmentDistanceAlongAndBeyondTheEnds) {
  const Segment s{{0.0, 0.0}, {2.0, 0.0}};
  EXPECT_DOUBLE_EQ(pointSegmentDistance({1.0, 0.7}, s), 0.7);
  EXPECT_DOUBLE_EQ(pointSegmentDistance({3.0, 0.0}, s), 1.0);
  EXPECT_DOUBLE_EQ(pointSegmentDistance({-3.0, 4.0}, s), 5.0);
}

TEST(WorldGeometry, InsidePolygonIncludingAConcaveOne) {
  EXPECT_TRUE(insidePolygon({1.5, 0.0}, table().polygons[0]));
  EXPECT_FALSE(insidePolygon({0.5, 0.0}, table().polygons[0]));
  const Polygon l_shape{{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};
  EXPECT_TRUE(insidePolygon({0.5, 1.5}, l_shape));
  EXPECT_FALSE(insidePolygon({1.5, 1.5}, l_shape)) << "the notch of the L";
}

TEST(WorldGeometry, ClearanceToWallsIsCentreDistanceMinusRadius) {
  World w;
  w.walls = {{{-1.0, 1.0}, {1.0, 1.0}}};
  EXPECT_DOUBLE_EQ(clearance(w, {0.0, 0.0}, 0.18), 1.0 - 0.18);
  EXPECT_DOUBLE_EQ(clearance(w, {4.0, 1.0}, 0.18), 3.0 - 0.18) << "beyond its end: to the end point";
  EXPECT_LT(clearance(w, {0.0, 0.9}, 0.18), 0.0) << "the body touches the wall";
  w.obstacles = {{{0.0, -0.5}, 0.1}};
  EXPECT_DOUBLE_EQ(clearance(w, {0.0, 0.0}, 0.18), 0.5 - 0.1 - 0.18) << "the nearer of disk and wall";
  EXPECT_EQ(clearance(World{}, {0.0, 0.0}, 0.18), std::numeric_limits<double>::infinity());
}

TEST(WorldGeometry, InsideAPolygonIsACollisionByItsDepth) {
  EXPECT_DOUBLE_EQ(clearance(table(), {0.0, 0.0}, 0.18), 1.0 - 0.18);
  EXPECT_DOUBLE_EQ(clearance(table(), {1.1, 0.0}, 0.18), -0.1 - 0.18);
  EXPECT_DOUBLE_EQ(clearance(table(), {1.5, 0.0}, 0.18), -0.5 - 0.18);
}

TEST(WorldGeometry, ConeRangeSeesAWallAheadObliqueAndNotBehind) {
  World w;
  w.walls = {{{2.0, -5.0}, {2.0, 5.0}}};
  const double half = 0.2;
  EXPECT_NEAR(coneRange(w, {0.0, 0.0, 0.0}, half), 2.0, 1e-12) << "perpendicular: the foot";
  // Turned 0.5 rad away: the foot is outside the cone; the nearest point inside is on the
  // cone's edge nearest to the wall's normal, at 2 / cos(0.5 - 0.2).
  EXPECT_NEAR(coneRange(w, {0.0, 0.0, 0.5}, half), 2.0 / std::cos(0.5 - half), 1e-12);
  EXPECT_EQ(coneRange(w, {0.0, 0.0, M_PI}, half), std::numeric_limits<double>::infinity());
  // A short wall off to the side, partly inside the cone: its end point inside is the range.
  World stub;
  stub.walls = {{{1.0, 0.1}, {1.0, 3.0}}};
  EXPECT_NEAR(coneRange(stub, {0.0, 0.0, 0.0}, half), std::hypot(1.0, 0.1), 1e-12);
  stub.walls = {{{1.0, 0.5}, {1.0, 3.0}}};  // wholly outside the cone (0.46 rad)
  EXPECT_EQ(coneRange(stub, {0.0, 0.0, 0.0}, half), std::numeric_limits<double>::infinity());
}

TEST(WorldGeometry, ConeRangeToDisksAndPolygons) {
  World w;
  w.obstacles = {{{3.0, 0.0}, 0.5}};
  EXPECT_NEAR(coneRange(w, {0.0, 0.0, 0.0}, 0.2), 2.5, 1e-12);
  EXPECT_EQ(coneRange(w, {3.1, 0.0, 0.0}, 0.2), 0.0) << "inside the disk";
  EXPECT_NEAR(coneRange(table(), {0.0, 0.0, 0.0}, 0.2), 1.0, 1e-12);
  EXPECT_EQ(coneRange(table(), {1.5, 0.0, 0.0}, 0.2), 0.0) << "inside the polygon";
}

TEST(WorldGeometry, SurfaceSegmentsCloseEachPolygon) {
  World w = table();
  w.walls = {{{5.0, 5.0}, {6.0, 5.0}}};
  const std::vector<Segment> s = surfaceSegments(w);
  ASSERT_EQ(s.size(), 5u);
  EXPECT_EQ(s[4].from, Eigen::Vector2d(1.0, 0.5));
  EXPECT_EQ(s[4].to, Eigen::Vector2d(1.0, -0.5));
}
