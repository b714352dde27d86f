// Distances in the world: clearance of a disk-shaped body to everything solid, the sonar's
// cone range, and the segments a ray or a cone can meet (walls and polygon edges).
#pragma once

#include <vector>

#include "amigobot_tracking/world/world.h"

namespace amigobot_tracking {
namespace world {

// Every straight surface: the walls, then each polygon's edges (closing edge included).
std::vector<Segment> surfaceSegments(const World& world);

// [m] from `point` to the nearest point of the segment.
double pointSegmentDistance(const Eigen::Vector2d& point, const Segment& segment);

// Even-odd rule; a point on an edge may count either way.
bool insidePolygon(const Eigen::Vector2d& point, const Polygon& polygon);

// [m] clearance of a disk of `radius` at `center` to the world: the smallest gap to a disk,
// a wall or a polygon (distance minus radii), negative on overlap; a centre inside a
// polygon counts as overlapping it by its depth. +inf in an empty world.
double clearance(const World& world, const Eigen::Vector2d& center, double radius);

// [m] range a sonar at `sensor` (x along its axis) reports: the nearest surface point
// inside its cone of half-angle `half_cone` (< pi/2), 0 when the sensor is inside a disk or
// polygon, +inf when nothing is in the cone.
double coneRange(const World& world, const core::Pose2& sensor, double half_cone);

}  // namespace world
}  // namespace amigobot_tracking
