#include "amigobot_tracking/world/raycast.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace amigobot_tracking {
namespace world {

using core::Disk;
using core::Pose2;
using core::ScanGeometry;

double rayDiskDistance(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction, const Disk& disk) {
  // |origin + s d - c|^2 = r^2 with |d| = 1: s^2 + 2 b s + q = 0.
  const Eigen::Vector2d offset = origin - disk.center;
  const double q = offset.squaredNorm() - disk.radius * disk.radius;
  if (q <= 0.0) return 0.0;
  const double b = offset.dot(direction);
  if (b >= 0.0) return -1.0;  // pointing away
  const double discriminant = b * b - q;
  if (discriminant < 0.0) return -1.0;
  return -b - std::sqrt(discriminant);
}

std::vector<float> raycastScan(const Pose2& sensor, const std::vector<Disk>& disks, const ScanGeometry& geometry,
                               int beams) {
  std::vector<float> ranges(static_cast<size_t>(std::max(0, beams)));
  const Eigen::Vector2d origin = sensor.position();
  for (size_t i = 0; i < ranges.size(); ++i) {
    const double angle = sensor.theta + geometry.angle_min + geometry.angle_increment * static_cast<double>(i);
    const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    double nearest = std::numeric_limits<double>::infinity();
    for (const Disk& disk : disks) {
      const double s = rayDiskDistance(origin, direction, disk);
      if (s >= 0.0 && s < nearest) nearest = s;
    }
    if (nearest > geometry.range_max) {
      ranges[i] = std::numeric_limits<float>::infinity();
    } else if (nearest < geometry.range_min) {
      ranges[i] = -std::numeric_limits<float>::infinity();
    } else {
      ranges[i] = static_cast<float>(nearest);
    }
  }
  return ranges;
}

}  // namespace world
}  // namespace amigobot_tracking
