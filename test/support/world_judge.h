// The e2e judge's view of the world file (beside judge.h): the true body's clearance to
// everything solid, with the world's people where they are on the emulator's clock.
#pragma once

#include "amigobot_tracking/aria/emulator_status.h"
#include "amigobot_tracking/world/geometry.h"
#include "amigobot_tracking/world/world.h"

namespace e2e {

// [m] the true body's clearance (base_link's disk of `robot_radius`) to everything solid of
// `room` with its people where they are at the status's emulator time; < 0 is a contact.
inline double bodyClearance(const amigobot_tracking::world::World& room,
                            const amigobot_tracking::aria::EmulatorStatus& s, double robot_radius = 0.18) {
  return amigobot_tracking::world::clearance(amigobot_tracking::world::worldAt(room, s.t), s.pose.position(),
                                             robot_radius);
}

}  // namespace e2e
