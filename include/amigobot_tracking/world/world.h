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
//   people:                                       # optional, moving disks (a person, a trolley):
//     - radius: 0.25                              #   [m] > 0
//       start: [x, y]                             #   [m] where it stands until start_time
//       start_time: 12.0                          #   [s] on the emulator's clock (below), default 0
//       legs:                                     #   walked in order, then it stands still:
//         - {duration: 4.0, velocity: [0.0, 0.6]} #   [s] > 0, [m/s] world frame ([0, 0]: stands)
//       repeat: false                             #   true: the legs start again (must end at start)
// People move on the robot emulator's clock: seconds since amigobot_emulator started (the `t`
// of its status line, aria/emulator_status.h), so the laser emulator, the sonar, the ground
// truth and the judges place a person at the same spot at the same instant. The ROS side
// maps its stamps to that clock through ground_truth_localization's `ground_truth_clock`.
// core::ObstacleMotion is the one description of such a path (the simulator's scenarios use it).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "amigobot_tracking/core/perception/obstacle_motion.h"
#include "amigobot_tracking/core/support/types.h"

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

// A disk that walks: its radius and its path on the emulator's clock.
struct Person {
  double radius = 0.25;  // [m] > 0
  core::ObstacleMotion motion;

  core::Disk diskAt(double t) const { return {motion.positionAt(t), radius}; }
};

struct World {
  std::vector<core::Disk> obstacles;  // disks (poles, chairs)
  std::vector<Person> people;         // moving disks; worldAt() places them
  std::vector<Segment> walls;         // every wall segment (chains split into segments)
  std::vector<Polygon> polygons;
  std::optional<core::Pose2> initial_pose;  // absent: the reader's own default

  bool empty() const { return obstacles.empty() && walls.empty() && polygons.empty() && people.empty(); }
};

// The room as it stands at time t [s, the emulator's clock]: each person becomes a disk
// (appended to `obstacles`, after the fixed ones) where it is then; `people` is left empty.
// Every reader that casts rays, judges clearances or draws takes its snapshot from here.
World worldAt(const World& world, double t);

// A world of these disks only (no walls, polygons or start pose).
inline World disksOnly(std::vector<core::Disk> disks) {
  World world;
  world.obstacles = std::move(disks);
  return world;
}

// Reads a world file. Throws std::runtime_error "FILE:LINE: KEY: what is wrong" for an
// unreadable file, a malformed entry or an unknown key. Only a regular file up to
// core::kMaxConfigFileBytes is read, and a tree whose aliases expand past core::kMaxYamlNodes
// is refused (core/support/input_file.h).
World loadWorld(const std::string& path);
// The same from the file's text; `path` names it in the errors.
World parseWorld(const std::string& text, const std::string& path);

// The world as a world file loadWorld reads back (walls as {from, to}; full precision).
std::string worldYaml(const World& world);

// "" when every shape is well formed (finite, disks with r > 0, segments of non-zero
// length, polygons of >= 3 points with non-zero area, people with r > 0 and a valid motion),
// else "key[i]: reason".
std::string validateWorld(const World& world);

}  // namespace world
}  // namespace amigobot_tracking
