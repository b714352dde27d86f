// Something inside the robot's body (issue 25: scan points at 0.06 m gave full speed
// forward; a virtual obstacle of radius 1e6 around the robot made it reverse). Either the
// laser is blind (dirt, a hand, a wrong range_min) or the robot is already where it must not
// be: the supervisor stops (SupervisorInputs::body_intrusion).
// A laser disk intrudes when its centre is inside the body circle (the disks of a wall the
// robot passes close to have their centres on the wall); a virtual obstacle when it contains
// the robot's centre. Pure, Eigen only.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/support/types.h"
#include "amigobot_tracking/core/perception/virtual_obstacles.h"

namespace amigobot_tracking {
namespace core {

// "" when nothing intrudes; else what does, e.g. "laser obstacle 0.060 m from the centre
// (body radius 0.180 m)" or "virtual obstacle 'wall' (radius 1000000.000 m) contains the robot".
std::string bodyIntrusion(const Eigen::Vector2d& centre, double body_radius, const std::vector<Disk>& laser_disks,
                          const std::vector<VirtualObstacle>& virtuals);

}  // namespace core
}  // namespace amigobot_tracking
