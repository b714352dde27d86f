// A synthetic room for the localisation tests and benchmark: a 6 m x 4 m rectangle with a
// partial partition and three pillars (asymmetric, so a global search has one answer), and a
// loop through it (a circle of 1.2 m about (2, 1)) clear of them all.
// A world (world/world.h): walls are segments, pillars disks; its occupancy map is drawn
// from the same world, and scans are ray cast against it by world::raycastScan.
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "amigobot_tracking/core/perception/scan_obstacles.h"
#include "amigobot_tracking/localization/occupancy_map.h"
#include "amigobot_tracking/localization/poses.h"
#include "amigobot_tracking/localization/range_scan.h"
#include "amigobot_tracking/world/geometry.h"
#include "amigobot_tracking/world/raycast.h"
#include "amigobot_tracking/world/world.h"

namespace amigobot_test {

using amigobot_tracking::core::Disk;
using amigobot_tracking::core::Pose2;
namespace loc = amigobot_tracking::localization;

constexpr double kRoomMinX = -1.0, kRoomMinY = -1.0, kRoomMaxX = 5.0, kRoomMaxY = 3.0;

inline amigobot_tracking::world::World roomWorld() {
  amigobot_tracking::world::World room;
  const Eigen::Vector2d sw(kRoomMinX, kRoomMinY), se(kRoomMaxX, kRoomMinY), ne(kRoomMaxX, kRoomMaxY),
      nw(kRoomMinX, kRoomMaxY);
  room.walls = {{sw, se}, {se, ne}, {ne, nw}, {nw, sw}, {{2.5, kRoomMinY}, {2.5, -0.4}}};  // + a partition
  room.obstacles = {Disk{{0.0, 2.2}, 0.3}, Disk{{3.8, 0.1}, 0.2}, Disk{{4.2, 2.2}, 0.25}};
  return room;
}

// The map of the room: occupied where a wall or pillar comes within half a cell of a cell's
// centre, free inside the room, unknown outside.
inline loc::OccupancyMap roomMap(double resolution = 0.05) {
  const double margin = 0.5;
  const int w = static_cast<int>(std::ceil((kRoomMaxX - kRoomMinX + 2 * margin) / resolution));
  const int h = static_cast<int>(std::ceil((kRoomMaxY - kRoomMinY + 2 * margin) / resolution));
  loc::OccupancyMap map = loc::makeMap(resolution, kRoomMinX - margin, kRoomMinY - margin, w, h);
  const amigobot_tracking::world::World room = roomWorld();
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const Eigen::Vector2d c = map.cellCenter(x, y);
      const bool occupied = amigobot_tracking::world::clearance(room, c, 0.5 * resolution * (1.0 + 1e-6)) <= 0.0;
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
  amigobot_tracking::world::World world = roomWorld();
  world.obstacles.insert(world.obstacles.end(), clutter.begin(), clutter.end());
  scan.ranges = amigobot_tracking::world::raycastScan(loc::compose(robot, scan.mount), world, geometry, beams);
  if (random) {
    std::normal_distribution<float> n(0.0f, static_cast<float>(noise));
    for (float& r : scan.ranges)
      if (std::isfinite(r)) r += n(*random);
  }
  return scan;
}

}  // namespace amigobot_test
