// Ray casting of a planar laser scan against the world's disks, for the simulated lasers.
#pragma once

#include <vector>

#include "amigobot_tracking/core/scan_obstacles.h"
#include "amigobot_tracking/core/types.h"

namespace amigobot_tracking {
namespace world {

// Range of each of `beams` beams (geometry as in scan_obstacles.h, angles in the sensor
// frame) from the sensor pose to the nearest disk surface. Following REP 117,
// a beam that hits nothing within range_max reports +inf; hits closer than range_min
// report -inf. A sensor inside a disk sees that disk at range_min (-inf).
std::vector<float> raycastScan(const core::Pose2& sensor, const std::vector<core::Disk>& disks, const core::ScanGeometry& geometry,
                               int beams);

// Distance along the unit ray (origin, direction) to the circle, or a negative value when
// the ray misses it or points away. 0 when the origin is inside the disk.
double rayDiskDistance(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction, const core::Disk& disk);

}  // namespace world
}  // namespace amigobot_tracking
