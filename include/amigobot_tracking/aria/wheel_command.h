// Turning a desired (v, w) into what the robot can be sent: saturated into the diamond,
// then quantised to the command's resolution toward the inside of the diamond, so the
// command actually sent is never outside it. NaN never becomes a command.
#pragma once

#include <optional>
#include <string>

#include "amigobot_tracking/aria/robot_params.h"
#include "amigobot_tracking/core/robot/diamond.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace aria {

enum class CommandMode {
  kVelRvel,  // VEL [mm/s] + RVEL [deg/s]: 1 mm/s and 1 deg/s steps
  kVel2,     // VEL2: each wheel in Vel2Divisor (20 mm/s) steps
};

std::optional<CommandMode> parseCommandMode(const std::string& name);  // "vel_rvel" | "vel2"
std::string commandModeName(CommandMode mode);

struct QuantizedCommand {
  CommandMode mode = CommandMode::kVelRvel;
  // kVelRvel: first = VEL [mm/s], second = RVEL [deg/s].
  // kVel2: first = left, second = right wheel [Vel2Divisor units].
  int first = 0;
  int second = 0;
  core::Twist2 twist;  // [m/s, rad/s] the robot is asked for by (first, second)
  bool saturated = false;  // the desired twist was outside the diamond
};

// nullopt for a non-finite desired twist. Otherwise the largest lattice point, component
// by component toward zero, whose twist lies inside `diamond` (within the robot's limits).
std::optional<QuantizedCommand> quantizeCommand(const core::Twist2& desired, CommandMode mode,
                                                const RobotParams& params, const core::DiamondSet& diamond);

// VEL and RVEL arrive as two packets, so between them the robot holds (next v, held w) or
// (held v, next w). One of the two is always inside the diamond (their normalised norms add
// up to norm(held) + norm(next) <= 2): true when RVEL must go first for that; VEL goes
// first otherwise.
bool rotationFirst(const core::Twist2& held, const core::Twist2& next, const core::DiamondSet& diamond);

// The twist a command lattice point stands for.
core::Twist2 commandTwist(CommandMode mode, int first, int second, const RobotParams& params);

}  // namespace aria
}  // namespace amigobot_tracking
