// A synthetic room for the localisation tests and benchmark: a 6 m x 4 m rectangle with a
// partial partition and three pillars (asymmetric, so a global search has one answer), and a
// loop through it (a circle of 1.2 m about (2, 1)) clear of them all.
// Walls are rows of small disks (radius 0.05 m every 0.08 m) until the world module has
// segments; its occupancy map is rasterised from the same disks, and scans are ray cast
// against them by world::raycastScan.
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "amigobot_tracking/core/scan_obstacles.h"
#include "amigobot_tracking/localization/occupancy_map.h"
#include "amigobot_tracking/localization/poses.h"
#include "amigobot_tracking/localization/range_scan.h"
#include "amigobot_tracking/world/raycast.h"

namespace amigobot_test {

using amigobot_tracking::core::Disk;
using amigobot_tracking::core::Pose2;
namespace loc = amigobot_tracking::localization;

constexpr double kRoomMinX = -1.0, kRoomMinY = -1.0, kRoomMaxX = 5.0, kRoomMaxY = 3.0;

inline void addWall(std::vector<Disk>* disks, Eigen::Vector2d a, Eigen::Vector2d b) {
  const int n = static_cast<int>(std::ceil((b - a).norm() / 0.08));
  for (int i = 0; i <= n; ++i) disks->push_back(Disk{a + (b - a) * (static_cast<double>(i) / n), 0.05});
}

inline std::vector<Disk> roomDisks() {
  std::vector<Disk> disks;
  addWall(&disks, {kRoomMinX, kRoomMinY}, {kRoomMaxX, kRoomMinY});
  addWall(&disks, {kRoomMaxX, kRoomMinY}, {kRoomMaxX, kRoomMaxY});
  addWall(&disks, {kRoomMaxX, kRoomMaxY}, {kRoomMinX, kRoomMaxY});
  addWall(&disks, {kRoomMinX, kRoomMaxY}, {kRoomMinX, kRoomMinY});
  addWall(&disks, {2.5, kRoomMinY}, {2.5, -0.4});  // partition from the south wall
  disks.push_back(Disk{{0.0, 2.2}, 0.3});
  disks.push_back(Disk{{3.8, 0.1}, 0.2});
  disks.push_back(Disk{{4.2, 2.2}, 0.25});
  return disks;
}

// The map of the disks: occupied where a cell's centre is within a disk (+ half a cell),
// free inside the room, unknown outside.
inline loc::OccupancyMap roomMap(double resolution = 0.05) {
  const double margin = 0.5;
  const int w = static_cast<int>(std::ceil((kRoomMaxX - kRoomMinX + 2 * margin) / resolution));
  const int h = static_cast<int>(std::ceil((kRoomMaxY - kRoomMinY + 2 * margin) / resolution));
  loc::OccupancyMap map = loc::makeMap(resolution, kRoomMinX - margin, kRoomMinY - margin, w, h);
  const std::vector<Disk> disks = roomDisks();
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const Eigen::Vector2d c = map.cellCenter(x, y);
      bool occupied = false;
      for (const Disk& d : disks) occupied = occupied || (c - d.center).norm() <= d.radius + 0.5 * resolution;
      const bool inside = c.x() > kRoomMinX && c.x() < kRoomMaxX && c.y() > kRoomMinY && c.y() < kRoomMaxY;
      map.at(x, y) = occupied ? loc::OccupancyMap::kOccupied : inside ? loc::OccupancyMap::kFree : loc::OccupancyMap::kUnknown;
    }
  }
  return map;
}

const Pose2 kLoopStart{2.0, -0.2, 0.0};
constexpr double kLoopRadius = 1.2;

// A laser 0.11 m ahead of the base, `beams` beams over 270 deg, 10 m range.
inline loc::RangeScan emptyScan(int beams) {
  loc::RangeScan scan;
  scan.angle_min = -0.75 * M_PI;
  scan.angle_increment = 1.5 * M_PI / (beams - 1);
  scan.range_min = 0.05;
  scan.range_max = 10.0;
  scan.mount = Pose2{0.11, 0.0, 0.0};
  return scan;
}

// The scan the robot at `robot` (map -> base) takes, with Gaussian range noise, in the room
// plus `clutter` (obstacles the map does not have).
inline loc::RangeScan scanAt(const Pose2& robot, int beams, std::mt19937* random = nullptr, double noise = 0.01,
                             const std::vector<Disk>& clutter = {}) {
  loc::RangeScan scan = emptyScan(beams);
  amigobot_tracking::core::ScanGeometry geometry;
  geometry.angle_min = scan.angle_min;
  geometry.angle_increment = scan.angle_increment;
  geometry.range_min = scan.range_min;
  geometry.range_max = scan.range_max;
  static const std::vector<Disk> room = roomDisks();
  std::vector<Disk> disks = room;
  disks.insert(disks.end(), clutter.begin(), clutter.end());
  scan.ranges = amigobot_tracking::world::raycastScan(loc::compose(robot, scan.mount), disks, geometry, beams);
  if (random) {
    std::normal_distribution<float> n(0.0f, static_cast<float>(noise));
    for (float& r : scan.ranges)
      if (std::isfinite(r)) r += n(*random);
  }
  return scan;
}

}  // namespace amigobot_test
