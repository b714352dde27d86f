// Ray casting of a planar laser scan against disks, for the simulated laser.
#pragma once

#include <vector>

#include "amigobot_tracking/core/scan_obstacles.h"
#include "amigobot_tracking/core/types.h"

namespace amigobot_tracking {
namespace core {

// Range of each of `beams` beams (geometry as in scan_obstacles.h, angles in the sensor
// frame) from the sensor pose to the nearest disk surface. Following REP 117,
// a beam that hits nothing within range_max reports +inf; hits closer than range_min
// report -inf. A sensor inside a disk sees that disk at range_min (-inf).
std::vector<float> raycastScan(const Pose2& sensor, const std::vector<Disk>& disks, const ScanGeometry& geometry,
                               int beams);

// Distance along the unit ray (origin, direction) to the circle, or a negative value when
// the ray misses it or points away. 0 when the origin is inside the disk.
double rayDiskDistance(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction, const Disk& disk);

}  // namespace core
}  // namespace amigobot_tracking
