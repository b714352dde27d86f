// Monte Carlo over a scenario: N variants with the obstacles and the initial pose
// perturbed at random (reproducible from the seed), summarised as JSON.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "amigobot_tracking/sim/json.h"
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
  // > 0: each variant's target noise std is drawn uniformly in [0, noise_std_max] [m].
  double noise_std_max = 0.0;
  // Non-empty: each variant's target sample period is drawn from these [s] (the rate varies).
  std::vector<double> sample_periods;
  int jobs = 1;           // threads running the variants (the result does not depend on it)
  bool progress = false;  // print progress and an estimate of the time left on stderr
};

// The time in [0, duration] at which the obstacle (centre + velocity t) is closest to the
// reference's target, sampled every 10 ms.
double encounterTime(const core::Disk& obstacle, const Eigen::Vector2d& velocity, const core::Reference& reference,
                     double duration);

// One randomised variant: a valid scenario (|e(0)| < max_error_ratio rho(0), no initial
// contact of the body or the offset disk); redrawn up to 100 times, else the original.
Scenario randomVariant(const Scenario& base, const MonteCarloOptions& options, std::uint64_t index);

// One randomised run of a batch.
struct MonteCarloRun {
  int index = 0;
  core::Pose2 initial_pose;  // [m, m, rad] as drawn
  sim::RunMetrics metrics;
};

// A batch: what was run, the counts, worst cases and means over its runs, and each run.
struct MonteCarloSummary {
  std::string scenario;  // file of the base scenario
  MonteCarloOptions options;
  std::string variant;
  bool body_safe = false, tangential_avoidance = false, moving_obstacles = false;
  std::uint64_t body_collision_episodes = 0, offset_collision_episodes = 0;
  int runs_with_long_stall = 0;  // a stall longer than 0.5 s (core/metrics.h)
  int runs_with_body_collision = 0, runs_with_offset_collision = 0, runs_with_diamond_violation = 0;
  int runs_with_nan = 0, runs_with_e_over_rho_ge_1 = 0;
  // Steps where rho was widened to keep |e|/rho <= max_error_ratio (start rule included),
  // and the runs with any: the envelope held by the rule rather than by (13).
  std::uint64_t envelope_widenings = 0;
  int runs_with_envelope_widening = 0;
  double worst_stall = 0.0;  // [s]
  double worst_min_clearance_body = std::numeric_limits<double>::infinity();    // [m]
  double worst_min_clearance_offset = std::numeric_limits<double>::infinity();  // [m]
  double worst_max_e_over_rho = 0.0;
  double mean_ase = 0.0, mean_aae = 0.0, mean_true_ase = 0.0;  // [m^2], [m], [m^2]
  double worst_true_ase = 0.0, mean_true_ise = 0.0, worst_true_ise = 0.0;  // [m^2], [m^2 s], [m^2 s]
  // The figures that cannot hide a failure (metrics.h), worst over the runs.
  double worst_orbit_turns = 0.0;
  std::uint64_t worst_escape_toggles = 0, worst_avoidance_toggles = 0, worst_side_flips = 0;
  double worst_max_delta_v = 0.0, worst_max_delta_omega = 0.0;  // [m/s], [rad/s]
  double mean_omega_reversals_per_minute = 0.0, worst_omega_reversals_per_minute = 0.0;  // [1/min]
  std::uint64_t diamond_violations = 0, nan_steps = 0;          // summed over the runs
  double sim_time = 0.0, wall_time = 0.0;  // [s] summed over the runs
  std::vector<MonteCarloRun> per_run;
};

// Runs them all. Prints nothing.
MonteCarloSummary summarizeMonteCarlo(const Scenario& base, const MonteCarloOptions& options);
// monte_carlo.json
void to_json(Json& json, const MonteCarloRun& run);
void to_json(Json& json, const MonteCarloSummary& summary);
// The summary's JSON text.
std::string runMonteCarlo(const Scenario& base, const MonteCarloOptions& options);

}  // namespace sim
}  // namespace amigobot_tracking
