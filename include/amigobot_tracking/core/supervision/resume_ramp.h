// The resume ramp: after a stop (target or robot pose lost, tracking disabled) the command
// leaves zero at the robot's accelerations instead of jumping to the controller's command in
// one control period. A pure step function; the tracking nodelet holds the state (the last
// command sent, whether the ramp is still on).
#pragma once

#include <string>

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

// Acceleration bounds of the ramp; defaults = the AmigoBot firmware's (config/robots/amigo.yaml).
struct RampLimits {
  double v_accel = 0.3;    // [m/s^2] translational (trans_accel)
  double w_accel = 1.745;  // [rad/s^2] rotational (rot_accel, 100 deg/s^2)

  // Empty when valid (both finite and > 0), else names the bad field.
  std::string validate() const;
};

struct RampStep {
  Twist2 u;              // the command to send
  bool limited = false;  // u was scaled down (the ramp is not over)
};

// One control period dt [s] of the ramp from `previous` (the last command sent) toward
// `desired` (the controller's command): desired scaled by one factor s in [0, 1], the
// largest with each component either within accel * dt of previous or between 0 and
// previous. So the direction of (v, w) is kept, a command inside the diamond stays inside
// (the diamond is star-shaped around 0), growth is at most accel * dt per period, and
// braking toward zero is never held back. s = 1 (desired unchanged, limited = false) once
// desired is within reach. Non-finite desired, or dt < 0 or not finite, gives zero.
RampStep rampTowards(const Twist2& desired, const Twist2& previous, const RampLimits& limits, double dt);

}  // namespace core
}  // namespace amigobot_tracking
