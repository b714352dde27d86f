// Ray casting of a planar laser scan against the world (disks, walls, polygons), for the
// simulated lasers.
#pragma once

#include <vector>

#include "amigobot_tracking/core/perception/scan_obstacles.h"
#include "amigobot_tracking/core/support/types.h"
#include "amigobot_tracking/world/world.h"

namespace amigobot_tracking {
namespace world {

// Range of each of `beams` beams (geometry as in scan_obstacles.h, angles in the sensor
// frame) from the sensor pose to the nearest surface of the world. Following REP 117,
// a beam that hits nothing within range_max reports +inf; hits closer than range_min
// report -inf. A sensor inside a disk or a polygon sees it at range 0 (-inf) on every beam.
std::vector<float> raycastScan(const core::Pose2& sensor, const World& world, const core::ScanGeometry& geometry,
                               int beams);

// Distance along the unit ray (origin, direction) to the circle, or a negative value when
// the ray misses it or points away. 0 when the origin is inside the disk.
double rayDiskDistance(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction, const core::Disk& disk);

// Distance along the unit ray (origin, direction) to the segment, or a negative value when
// the ray misses it (parallel rays included).
double raySegmentDistance(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction, const Segment& segment);

}  // namespace world
}  // namespace amigobot_tracking
