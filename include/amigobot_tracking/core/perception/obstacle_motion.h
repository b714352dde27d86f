// How a moving obstacle (a person, a trolley) moves: piecewise-constant velocities from a start
// point, so it can walk, stop, turn and speed up. The one description of such a motion, read by
// the offline simulator's scenarios and the emulated world alike, so the laser emulators, the
// ground truth and the simulator agree on where a person is at every instant.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace amigobot_tracking {
namespace core {

struct MotionLeg {
  double duration = 0.0;                                 // [s] > 0
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();    // [m/s] world frame; zero = standing
};

struct ObstacleMotion {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();  // [m] where it stands until start_time
  double start_time = 0.0;                           // [s] when the first leg begins
  std::vector<MotionLeg> legs;                       // walked in order; then it stands still
  bool repeat = false;                               // true: the legs start again after the last

  // Position and velocity at time t [s]. Before start_time and after the last leg (when not
  // repeating) the obstacle stands still. A motion without legs never moves.
  Eigen::Vector2d positionAt(double t) const;
  Eigen::Vector2d velocityAt(double t) const;
  // Standing at t after walking: the velocity of the last leg walked (where a person who stopped
  // may walk on, Disk::resume_velocity). Zero while it walks and before it first walked.
  Eigen::Vector2d resumeVelocityAt(double t) const;
  // Sum of the legs' durations [s].
  double period() const;
  // "" when usable, else "legs[i].duration: reason" (finite values, durations > 0, a repeating
  // motion returns to its start so it does not drift away, at most 10000 legs).
  std::string validate() const;
};

}  // namespace core
}  // namespace amigobot_tracking
