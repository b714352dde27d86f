// Gain tuning (the paper's future work): a pattern search over some controller gains on a
// suite of scenarios, each candidate judged by Monte Carlo under hard constraints (no
// contact, no command outside the diamond, no widening of rho by the guard, no NaN, no orbit
// of a turn or more, at most 4 side flips: issue 20's bar for the recommended law), the
// objective the mean true ASE relative to the starting gains. `amigobot_sim --tune SUITE`.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "amigobot_tracking/sim/monte_carlo.h"

namespace amigobot_tracking {
namespace sim {

// One line of a suite file: a scenario and how its Monte Carlo variants are drawn.
struct TuningEntry {
  std::string scenario;         // path (relative ones are resolved against the suite file)
  MonteCarloOptions variants;   // shifts, noise, sample periods, obstacle speed (runs, seed, jobs: the tuner's)
  int line = 0;                 // in the suite file, for messages
};

struct TuningSuite {
  std::string file;
  std::vector<TuningEntry> entries;
};

// A suite file: one scenario per line, `PATH [key=value ...]` with the keys obstacle_shift,
// pose_shift, heading_shift (m, m, rad), noise (m), sample_periods (s, comma-separated),
// obstacle_speed (m/s); `#` starts a comment. Throws std::runtime_error("FILE:LINE: reason").
TuningSuite parseTuningSuite(const std::string& text, const std::string& file);
TuningSuite loadTuningSuite(const std::string& path);

// A gain the search may change, as a scenario key, within [min, max].
struct TunedGain {
  std::string key;  // "controller.k_d"
  double min = 0.0, max = 0.0;
};
// The recommended law's gains: k_d, lambda, k_r, barrier_rate, field_margin.
std::vector<TunedGain> recommendedLawGains();

struct TunerOptions {
  std::vector<TunedGain> gains = recommendedLawGains();
  std::vector<std::string> overrides;  // applied to every scenario first ("controller.variant=recommended")
  int runs = 8;                        // Monte Carlo variants per scenario and candidate
  std::uint64_t seed = 1;              // the same variants for every candidate
  int jobs = 1;                        // threads of each Monte Carlo batch
  int max_evaluations = 30;            // candidates judged, the start included
  double step = 1.5;                   // first multiplicative step of the pattern search (> 1)
  bool progress = false;               // progress and the time left on stderr
};

struct Evaluation {
  std::map<std::string, double> gains;  // key -> value
  bool feasible = false;
  std::string violation;                // the first broken constraint ("" when feasible)
  double objective = 0.0;               // mean over the suite of true ASE / the start's true ASE
  std::vector<double> mean_true_ase;    // per entry [m^2]
};

struct TuningResult {
  Evaluation start, best;
  int evaluations = 0;
  double wall_time = 0.0;  // [s]
};

// Throws std::runtime_error naming the scenario or gain that is wrong.
TuningResult tuneGains(const TuningSuite& suite, const TunerOptions& options);

// The tuned gains as controller YAML (the tracking nodelet's private parameters, like
// config/controller_experiment.yaml), with the search's figures as comments.
std::string tunedGainsYaml(const TuningResult& result, const TuningSuite& suite, const TunerOptions& options);

}  // namespace sim
}  // namespace amigobot_tracking
