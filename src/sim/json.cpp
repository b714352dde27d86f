#include "amigobot_tracking/sim/json.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace amigobot_tracking {
namespace sim {

Json jsonNumber(double value) {
  if (!std::isfinite(value)) return nullptr;
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  const double rounded = std::strtod(text, nullptr);
  if (rounded == std::trunc(rounded) && std::abs(rounded) < 1e15) return static_cast<std::int64_t>(rounded);
  return rounded;
}

std::string dumpJson(const Json& json) { return json.dump(2) + "\n"; }

Json pick(const Json& from, std::initializer_list<const char*> keys) {
  Json j = Json::object();
  for (const char* key : keys) j[key] = from.at(key);
  return j;
}

Json sharedMetricsJson(const sim::RunMetrics& metrics) {
  return pick(metrics,
              {"ase", "aae", "ise", "iae", "tec", "max_e_over_rho", "max_rho", "final_error", "min_clearance_offset",
               "min_clearance_body", "body_collisions", "body_contact_time_s", "diamond_violations", "saturated_steps",
               "envelope_widenings", "estimator_rms_error", "estimator_max_error_settled", "steps"});
}

Json obstacleJson(const core::Disk& disk, const Eigen::Vector2d& velocity) {
  Json j;
  j["center"] = {jsonNumber(disk.center.x()), jsonNumber(disk.center.y())};
  j["radius"] = jsonNumber(disk.radius);
  j["velocity"] = {jsonNumber(velocity.x()), jsonNumber(velocity.y())};
  return j;
}

void to_json(Json& j, const RunMetrics& m) {
  using sim::jsonNumber;
  j = sim::Json{{"ase", jsonNumber(m.ase)},
                {"aae", jsonNumber(m.aae)},
                {"ise", jsonNumber(m.ise)},
                {"iae", jsonNumber(m.iae)},
                {"tec", jsonNumber(m.tec)},
                {"max_e_over_rho", jsonNumber(m.max_e_over_rho)},
                {"max_rho", jsonNumber(m.max_rho)},
                {"final_error", jsonNumber(m.final_error)},
                {"min_clearance_offset", jsonNumber(m.min_clearance_offset)},
                {"min_clearance_body", jsonNumber(m.min_clearance_body)},
                {"body_collisions", m.body_collisions},
                {"body_contact_time_s", jsonNumber(m.body_contact_time)},
                {"diamond_violations", m.diamond_violations},
                {"saturated_steps", m.saturated_steps},
                {"envelope_widenings", m.envelope_widenings},
                {"estimator_rms_error", jsonNumber(m.estimator_rms_error)},
                {"estimator_max_error_settled", jsonNumber(m.estimator_max_error_settled)},
                {"steps", m.steps},
                {"offset_collisions", m.offset_collisions},
                {"offset_contact_time_s", jsonNumber(m.offset_contact_time)},
                {"nan_count", m.nan_count},
                {"true_ase", jsonNumber(m.true_ase)},
                {"true_aae", jsonNumber(m.true_aae)},
                {"true_ise", jsonNumber(m.true_ise)},
                {"true_iae", jsonNumber(m.true_iae)},
                {"max_true_error", jsonNumber(m.max_true_error)},
                {"longest_stall_s", jsonNumber(m.longest_stall)},
                {"conflict_steps", m.conflict_steps},
                {"escape_steps", m.escape_steps},
                {"side_flips", m.side_flips},
                {"stall_time_s", jsonNumber(m.stall_time)},
                {"max_orbit_turns", jsonNumber(m.max_orbit_turns)},
                {"escape_toggles", m.escape_toggles},
                {"avoidance_toggles", m.avoidance_toggles},
                {"max_delta_v", jsonNumber(m.max_delta_v)},
                {"max_delta_omega", jsonNumber(m.max_delta_omega)},
                {"omega_reversals", m.omega_reversals},
                {"omega_reversals_per_minute", jsonNumber(m.omega_reversals_per_minute)},
                {"sim_time_s", jsonNumber(m.sim_time)}};
}

}  // namespace sim
}  // namespace amigobot_tracking
