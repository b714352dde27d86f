// The world file: the physical obstacles of an emulated room (disks today) and where the
// robot starts. Read by amigobot_emulator (sonar), sim_laser (ray casts) and run_report
// (true clearances), so all three see the same room.
//   initial_pose: [x, y, theta]                  # [m, m, rad] optional
//   obstacles: [{center: [x, y], radius: r}, ...] # [m] optional, r > 0
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "amigobot_tracking/core/types.h"

namespace amigobot_tracking {
namespace world {

struct World {
  std::vector<core::Disk> obstacles;
  std::optional<core::Pose2> initial_pose;  // absent: the reader's own default
};

// Reads a world file. Throws std::runtime_error "FILE:LINE: KEY: what is wrong" for an
// unreadable file, a malformed entry or an unknown key.
World loadWorld(const std::string& path);

}  // namespace world
}  // namespace amigobot_tracking
