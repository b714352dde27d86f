#include "amigobot_tracking/sim/tracking_verdict.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace amigobot_tracking {
namespace sim {

std::string TrackingVerdictConfig::validate() const {
  if (!(std::isfinite(rho_inf) && rho_inf > 0.0)) return "rho_inf: must be > 0 m";
  if (!(std::isfinite(tolerance) && tolerance >= 0.0)) return "tolerance: must be >= 0 m";
  if (!(std::isfinite(recovery_time) && recovery_time >= 0.0)) return "recovery_time: must be >= 0 s";
  if (!(std::isfinite(band) && band >= 0.0)) return "band: must be >= 0 m";
  return "";
}

namespace {

std::string format(const char* fmt, double a, double b, double c) {
  char text[160];
  std::snprintf(text, sizeof text, fmt, a, b, c);
  return text;
}

std::vector<ObstacleEpisode> findEpisodes(const std::vector<TrackingSample>& samples, double band) {
  std::vector<ObstacleEpisode> episodes;
  bool inside = false;
  for (const TrackingSample& s : samples) {
    const bool near = std::min(s.clearance_offset, s.clearance_target) < band;
    if (near && !inside) episodes.push_back(ObstacleEpisode{s.t, s.t, 0.0, -1.0});
    if (near) episodes.back().end = s.t;  // extended below to the first sample outside
    if (!near && inside) episodes.back().end = s.t;
    inside = near;
  }
  return episodes;
}

}  // namespace

TrackingVerdict judgeTracking(const std::vector<TrackingSample>& samples, const TrackingVerdictConfig& config) {
  TrackingVerdict v;
  v.bound = config.bound();
  if (samples.empty()) {
    v.reason = "no samples";
    return v;
  }
  v.episodes = findEpisodes(samples, config.band);
  const double t0 = samples.front().t, run_time = samples.back().t - t0;
  std::size_t first_episode = 0;  // episodes ending before t - recovery_time no longer matter
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const TrackingSample& s = samples[k];
    const double held = k + 1 < samples.size() ? samples[k + 1].t - s.t : 0.0;
    for (ObstacleEpisode& e : v.episodes) {
      if (s.t >= e.start && s.t < e.end + config.recovery_time) e.peak_error = std::max(e.peak_error, s.error);
      if (e.recovered_after < 0.0 && s.t >= e.end && s.error <= v.bound) e.recovered_after = s.t - e.end;
    }
    while (first_episode < v.episodes.size() &&
           v.episodes[first_episode].end + config.recovery_time <= s.t) {
      ++first_episode;
    }
    bool judged = s.t >= t0 + config.recovery_time;
    for (std::size_t i = first_episode; judged && i < v.episodes.size(); ++i) {
      const ObstacleEpisode& e = v.episodes[i];
      if (s.t >= e.start && s.t < e.end + config.recovery_time) judged = false;
    }
    if (!judged) continue;
    v.judged_time += held;
    if (s.error > v.bound) v.judged_over_bound_time += held;
    if (v.worst_time < 0.0 || s.error > v.max_judged_error) {
      v.max_judged_error = s.error;
      v.worst_time = s.t;
    }
  }
  v.judged_fraction = run_time > 0.0 ? v.judged_time / run_time : 0.0;
  v.final_error = samples.back().error;
  if (v.worst_time < 0.0) {
    v.reason = "nothing judged: the run is shorter than the recovery time after the start and every obstacle";
  } else if (v.max_judged_error > v.bound) {
    v.reason = format("|e*| %.3f m > rho_inf + tolerance = %.3f m at t = %.1f s (outside obstacle episodes)",
                      v.max_judged_error, v.bound, v.worst_time);
  } else if (v.final_error > v.bound) {
    v.reason = format("final |e*| %.3f m > rho_inf + tolerance = %.3f m at t = %.1f s", v.final_error, v.bound,
                      samples.back().t);
  }
  v.tracked = v.reason.empty();
  return v;
}

}  // namespace sim
}  // namespace amigobot_tracking
