#include "amigobot_tracking/aria/wheel_command.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr double kRadPerDeg = M_PI / 180.0;

int towardZero(double value, int limit) {
  return static_cast<int>(std::clamp(std::trunc(value), -static_cast<double>(limit), static_cast<double>(limit)));
}

int stepTowardZero(int value) { return value > 0 ? value - 1 : (value < 0 ? value + 1 : 0); }

}  // namespace

std::optional<CommandMode> parseCommandMode(const std::string& name) {
  if (name == "vel_rvel") return CommandMode::kVelRvel;
  if (name == "vel2") return CommandMode::kVel2;
  return std::nullopt;
}

std::string commandModeName(CommandMode mode) { return mode == CommandMode::kVel2 ? "vel2" : "vel_rvel"; }

core::Twist2 commandTwist(CommandMode mode, int first, int second, const RobotParams& params) {
  if (mode == CommandMode::kVel2) {
    const core::WheelSpeeds wheels{first * params.vel2_divisor * 1e-3, second * params.vel2_divisor * 1e-3};
    return core::fromWheelSpeeds(wheels, params.halfTrack());
  }
  return {first * 1e-3, second * kRadPerDeg};
}

std::optional<QuantizedCommand> quantizeCommand(const core::Twist2& desired, CommandMode mode,
                                                const RobotParams& params, const core::DiamondSet& diamond) {
  const std::optional<core::Twist2> inside = diamond.saturate(desired);
  if (!inside) return std::nullopt;
  QuantizedCommand cmd;
  cmd.mode = mode;
  cmd.saturated = !diamond.contains(desired);
  // Scales that make one lattice step comparable in both components, for choosing which
  // component to shrink when the truncated point is still outside.
  double first_scale = 0.0;
  double second_scale = 0.0;
  if (mode == CommandMode::kVel2) {
    const core::WheelSpeeds w = core::toWheelSpeeds(*inside, params.halfTrack());
    const int limit = std::min(127, static_cast<int>(params.dynamics.max_velocity * 1e3 / params.vel2_divisor));
    cmd.first = towardZero(w.left * 1e3 / params.vel2_divisor, limit);
    cmd.second = towardZero(w.right * 1e3 / params.vel2_divisor, limit);
    first_scale = second_scale = 1.0;
  } else {
    cmd.first = towardZero(inside->v * 1e3, static_cast<int>(params.dynamics.max_velocity * 1e3));
    cmd.second = towardZero(inside->omega / kRadPerDeg, static_cast<int>(params.dynamics.max_rot_velocity / kRadPerDeg));
    first_scale = 1e-3 / diamond.vMax();
    second_scale = kRadPerDeg / diamond.wMax();
  }
  // Truncation keeps each component within the saturated value, but the pair can still
  // leave a diamond with other proportions (e.g. VEL2 wheels near a pure turn): shrink the
  // dominant component until the point is inside. Terminates at (0, 0) at worst.
  while (!diamond.contains(commandTwist(mode, cmd.first, cmd.second, params))) {
    if (std::abs(cmd.first) * first_scale >= std::abs(cmd.second) * second_scale) {
      cmd.first = stepTowardZero(cmd.first);
    } else {
      cmd.second = stepTowardZero(cmd.second);
    }
  }
  cmd.twist = commandTwist(mode, cmd.first, cmd.second, params);
  return cmd;
}

bool rotationFirst(const core::Twist2& held, const core::Twist2& next, const core::DiamondSet& diamond) {
  return diamond.normalizedNorm({next.v, held.omega}) > 1.0 &&
         diamond.normalizedNorm({held.v, next.omega}) <= 1.0;
}

}  // namespace aria
}  // namespace amigobot_tracking
