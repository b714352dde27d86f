// The simulator's side of a robot description (config/robots/<model>.yaml): only the keys of
// the base's dynamics (core::ActuatorLimits, under the file's names) and the wheel track; the
// robot driver reads the rest of the file. Also writes such a file (amigobot_sim --identify).
#pragma once

#include <string>

#include "amigobot_tracking/sim/closed_loop.h"

namespace amigobot_tracking {
namespace sim {

// Reads `path`; keys it does not name keep the AmigoBot's values. Throws ScenarioError
// ("FILE: key: reason") for an unreadable file, a non-number or an unusable value.
RobotDynamics loadRobotDynamics(const std::string& path);
RobotDynamics parseRobotDynamics(const std::string& text, const std::string& file);

// The same keys as YAML with a comment per key (the robot driver reads them too); `origin`
// says where the values came from (a comment at the top).
std::string robotDynamicsYaml(const RobotDynamics& dynamics, const std::string& origin);

}  // namespace sim
}  // namespace amigobot_tracking
