// The world file: the physical obstacles of an emulated room (disks, walls, solid polygons)
// and where the robot starts. Read by amigobot_emulator (sonar), laser_emulator and sim_laser
// (ray casts), world_markers (rviz) and run_report (true clearances), so all see one room.
//   initial_pose: [x, y, theta]                  # [m, m, rad] optional
//   obstacles: [{center: [x, y], radius: r}, ...] # [m] optional, r > 0
//   walls:                                        # [m] optional, thin walls:
//     - {from: [x, y], to: [x, y]}                #   one segment, from != to
//     - {points: [[x, y], [x, y], ...]}           #   an open chain of >= 2 points (a room's
//                                                 #   outline: repeat the first point to close it)
//   polygons:                                     # [m] optional, solid outlines (a table):
//     - {points: [[x, y], [x, y], [x, y], ...]}   #   >= 3 points, closed implicitly; inside
//                                                 #   counts as collision
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "amigobot_tracking/core/types.h"

namespace amigobot_tracking {
namespace world {

// A thin wall between two distinct points [m] in the world frame.
struct Segment {
  Eigen::Vector2d from = Eigen::Vector2d::Zero();
  Eigen::Vector2d to = Eigen::Vector2d::Zero();
};

// A solid simple polygon [m]; the last point joins the first.
struct Polygon {
  std::vector<Eigen::Vector2d> points;
};

struct World {
  std::vector<core::Disk> obstacles;  // disks (poles, chairs)
  std::vector<Segment> walls;         // every wall segment (chains split into segments)
  std::vector<Polygon> polygons;
  std::optional<core::Pose2> initial_pose;  // absent: the reader's own default

  bool empty() const { return obstacles.empty() && walls.empty() && polygons.empty(); }
};

// A world of these disks only (no walls, polygons or start pose).
inline World disksOnly(std::vector<core::Disk> disks) {
  World world;
  world.obstacles = std::move(disks);
  return world;
}

// Reads a world file. Throws std::runtime_error "FILE:LINE: KEY: what is wrong" for an
// unreadable file, a malformed entry or an unknown key. Only a regular file up to
// core::kMaxConfigFileBytes is read, and a tree whose aliases expand past core::kMaxYamlNodes
// is refused (core/input_file.h).
World loadWorld(const std::string& path);
// The same from the file's text; `path` names it in the errors.
World parseWorld(const std::string& text, const std::string& path);

// The world as a world file loadWorld reads back (walls as {from, to}; full precision).
std::string worldYaml(const World& world);

// "" when every shape is well formed (finite, disks with r > 0, segments of non-zero
// length, polygons of >= 3 points with non-zero area), else "key[i]: reason".
std::string validateWorld(const World& world);

}  // namespace world
}  // namespace amigobot_tracking
