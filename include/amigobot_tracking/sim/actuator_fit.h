// Identifies the actuator model (core/robot/actuator_model.h) from a recorded run: the commands as
// the base received them (cmd_vel) and the velocities it reported (odometry twist). Replays
// the commands through the model and minimises the squared velocity error over the ramps,
// the latency and the wheel-speed limit. The cycle is the odometry's period (one report per
// firmware cycle, the SIP cycle) and its ticks fall on the odometry's stamps.
// The latency found is the whole delay from a cmd_vel stamp to the odometry that shows it,
// the odometry's own reporting delay included: what the planner has to expect.
#pragma once

#include <string>
#include <vector>

#include "amigobot_tracking/sim/closed_loop.h"

namespace amigobot_tracking {
namespace sim {

struct TimedTwist {
  double t = 0.0;  // [s] any clock shared by the two streams
  core::Twist2 u;
};

struct ActuatorRecording {
  std::vector<TimedTwist> commands;  // as sent, in time order
  std::vector<TimedTwist> odometry;  // as reported, in time order
  double half_track = core::kAmigoHalfTrack;  // [m] known from the robot (not fitted)
};

struct ActuatorFit {
  RobotDynamics dynamics;            // the fitted values (ideal = false)
  double rms_error = 0.0;            // [m/s] of v and b w over the odometry samples
  double largest_wheel_speed = 0.0;  // [m/s] largest |v| + b|w| in the odometry
  bool wheel_limit_seen = false;     // false: the run never reached the limit; max_velocity kept
  std::vector<std::string> notes;    // what the run could not tell
};

// Throws std::invalid_argument naming the problem: too few samples, time going back, NaN.
ActuatorFit fitActuator(const ActuatorRecording& recording);

// CSV of a run: lines "cmd,t,v,w" and "odom,t,v,w" (SI; '#' comments, blank lines skipped).
// Throws std::runtime_error naming the file and line.
ActuatorRecording readActuatorCsv(const std::string& path);

}  // namespace sim
}  // namespace amigobot_tracking
