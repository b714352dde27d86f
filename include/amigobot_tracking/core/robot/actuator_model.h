// What the robot's base does to a velocity command: the one actuator model of the robot
// emulator and the offline simulator (and what a fit of a recorded run identifies).
//
// The firmware (AmigOS/ARCOS) samples the newest command once per control cycle (ticks at
// k * cycle from the model's start); a command counts at a tick only once `latency` has passed
// since it arrived, so it reaches the wheels latency ... latency + cycle after its arrival. The
// sampled setpoint is clipped to the body ceilings and to the wheel-speed limit; each axis then
// ramps toward it: at the accel rate while |v| grows, at the decel rate while |v| shrinks (a
// sign reversal decelerates to zero, then accelerates). With cycle = 0 every command counts
// exactly `latency` after it arrives.
//
// Wheel-speed limit: |v| + b |w| <= max_velocity (b: half the wheel track). The reference
// documents name MaxVelocity as the wheels' ceiling without saying how a setpoint beyond it is
// cut; this model scales v and w by one factor (the turn's curvature is kept), as the robot
// emulator always did. The ramped state is cut the same way when the two axes' ramps would
// pass outside the limit on their way.
#pragma once

#include <deque>
#include <string>

#include "amigobot_tracking/core/robot/actuator_limits.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

// AmigoBot: ARIA's w = (R - L)/2 * DiffConvFactor with DiffConvFactor 0.011 /mm.
constexpr double kAmigoHalfTrack = 1.0 / 0.011 * 1e-3;  // [m]

// Problems of a set of limits ("field: reason; ..."), empty when usable: rates and ceilings
// > 0 (infinity allowed), cycle and latency >= 0 and finite, half_track > 0.
std::string validateActuatorLimits(const ActuatorLimits& limits, double half_track);

// The setpoint the firmware would accept: clipped to the body ceilings, then scaled into the
// wheel-speed limit.
Twist2 clipToLimits(const Twist2& command, const ActuatorLimits& limits, double half_track);

class ActuatorModel {
 public:
  // Throws std::invalid_argument naming the bad field (validateActuatorLimits).
  ActuatorModel(const ActuatorLimits& limits, double half_track);

  // Advances dt >= 0 seconds. `command` is the newest command the base has received; when it
  // differs from the previous one it counts as arriving now (at time()). Returns the mean
  // velocity over the step (integrate the pose with it); velocity() is the one at the end.
  Twist2 step(const Twist2& command, double dt);

  const Twist2& velocity() const { return velocity_; }
  const Twist2& setpoint() const { return setpoint_; }
  double time() const { return time_; }
  double halfTrack() const { return half_track_; }
  const ActuatorLimits& limits() const { return limits_; }
  // The firmware's run-time commands (SETA, SETV, ...) change the limits; the same checks
  // as the constructor (throws std::invalid_argument).
  void setLimits(const ActuatorLimits& limits);

 private:
  struct Arrival {
    double time;
    Twist2 command;
  };
  void sample(double at);          // the newest command that counts at `at` becomes the setpoint
  double nextEvent(double after) const;  // next tick (or, with cycle 0, next command due)
  void ramp(double duration, Twist2* area);

  ActuatorLimits limits_;
  double half_track_;
  double time_ = 0.0;
  long next_tick_ = 0;  // index of the next firmware tick (k * cycle)
  std::deque<Arrival> arrivals_;  // received, not yet superseded commands (front: the newest one counted)
  Twist2 setpoint_;
  Twist2 velocity_;
};

// Holds `command` for `duration` through the model and moves the body with the velocity it
// produces, in sub-steps of at most `substep` (the ramp is linear inside each, the pose
// follows the mean velocity of each: 1 mm over a 5 s ramp at the default).
Pose2 driveBody(ActuatorModel* model, const Pose2& pose, const Twist2& command, double duration,
                double substep = 0.005);

}  // namespace core
}  // namespace amigobot_tracking
