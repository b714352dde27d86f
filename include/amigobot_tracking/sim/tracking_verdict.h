// Did a run *track*? Safety (no contact, every command in the diamond) is judged elsewhere;
// this judges the tracking error the way the paper's Section 5.3 shows it: small outside the
// obstacle encounters, and back to small within a recovery time after each one.
//
// An *obstacle episode* is a maximal interval where the robot could not be expected to sit
// on the target: the true clearance of the effective disk (R + r with body_safe) around the
// offset point p_r, or around the target p_d (where p_r would be if it tracked exactly), is
// inside the detection band (< delta), so the repulsion (10) is, or would be, at work.
// The error is *judged* at every sample at least `recovery_time` after the start and after
// the end of every episode; the run tracks when, at every judged sample, the true error
// |e*| = |p_d - p_r| stays within rho_inf + tolerance, and the final error does too
// (`tolerance` absorbs the localisation error and the pose/target sampling skew).
#pragma once

#include <string>
#include <vector>

namespace amigobot_tracking {
namespace sim {

struct TrackingVerdictConfig {
  double rho_inf = 0.1;         // [m] the law's steady-state bound
  double tolerance = 0.05;      // [m] added to rho_inf: localisation error, sampling skew
  double recovery_time = 10.0;  // [s] after the start and after each episode, not judged
  double band = 0.25;           // [m] detection band delta: an episode while a clearance < band

  std::string validate() const;  // empty when valid, else "key: reason"
  double bound() const { return rho_inf + tolerance; }
};

struct TrackingSample {
  double t = 0.0;                 // [s]
  double error = 0.0;             // [m] true |e*|
  double clearance_offset = 0.0;  // [m] effective disk around the true p_r to the nearest obstacle
  double clearance_target = 0.0;  // [m] effective disk around the target to the nearest obstacle
};

struct ObstacleEpisode {
  double start = 0.0, end = 0.0;  // [s]
  double peak_error = 0.0;        // [m] largest |e*| from start to end + recovery_time
  double recovered_after = -1.0;  // [s] from end until |e*| <= bound first; < 0: never in the run
};

struct TrackingVerdict {
  bool tracked = false;           // every judged sample and the final error within bound
  double bound = 0.0;             // [m] rho_inf + tolerance
  double judged_time = 0.0;       // [s] time covered by judged samples (held until the next one)
  double judged_fraction = 0.0;   // judged_time / run time
  double max_judged_error = 0.0;  // [m] largest |e*| at a judged sample
  double worst_time = -1.0;       // [s] where it was (< 0: nothing judged)
  double judged_over_bound_time = 0.0;  // [s] judged time with |e*| > bound
  double final_error = 0.0;       // [m] |e*| at the last sample
  std::vector<ObstacleEpisode> episodes;
  std::string reason;             // why not tracked (empty when tracked)
};

// Samples in time order. No samples, or nothing judged, is not tracking.
TrackingVerdict judgeTracking(const std::vector<TrackingSample>& samples, const TrackingVerdictConfig& config);

}  // namespace sim
}  // namespace amigobot_tracking
