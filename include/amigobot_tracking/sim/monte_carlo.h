// Monte Carlo over a scenario: N variants with the obstacles and the initial pose
// perturbed at random (reproducible from the seed), summarised as JSON.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "amigobot_tracking/sim/scenario.h"

namespace amigobot_tracking {
namespace sim {

struct MonteCarloOptions {
  int runs = 10;
  std::uint64_t seed = 1;
  double obstacle_shift = 0.3;  // [m] each obstacle centre moves uniformly within this disk
  double pose_shift = 0.3;      // [m] the initial position likewise
  double heading_shift = 0.5;   // [rad] the initial heading uniformly within +-this
  // > 0: every moving obstacle gets a speed drawn uniformly in [0, obstacle_speed] [m/s],
  // its direction kept, re-timed so that it still reaches its (shifted) encounter point --
  // where the scenario's obstacle comes closest to the target -- at the same time.
  double obstacle_speed = 0.0;
};

// The time in [0, duration] at which the obstacle (centre + velocity t) is closest to the
// reference's target, sampled every 10 ms.
double encounterTime(const core::Disk& obstacle, const Eigen::Vector2d& velocity, const core::Reference& reference,
                     double duration);

// One randomised variant: a valid scenario (|e(0)| < max_error_ratio rho(0), no initial
// contact of the body or the offset disk); redrawn up to 100 times, else the original.
Scenario randomVariant(const Scenario& base, const MonteCarloOptions& options, std::uint64_t index);

// Runs them all and returns the summary JSON (collisions, violations, worst clearances,
// per-run figures). Prints nothing.
std::string runMonteCarlo(const Scenario& base, const MonteCarloOptions& options);

}  // namespace sim
}  // namespace amigobot_tracking
