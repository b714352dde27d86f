#include "amigobot_tracking/sim/simulator.h"

#include "amigobot_tracking/sim/config_json.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace amigobot_tracking {
namespace sim {

std::string jsonNumber(double value) {
  if (!std::isfinite(value)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", value);
  return buf;
}

RunResult runScenario(const Scenario& scenario, bool log) {
  RunResult result;
  const auto reference = scenario.makeReference();
  double next_log = 0.0;
  core::ClosedLoopObserver observer;
  if (log) {
    result.rows.reserve(static_cast<size_t>(
        scenario.setup.duration / std::max(scenario.log_period, scenario.setup.control_period) + 16));
    observer = [&](const core::ClosedLoopStep& s) {
      const bool last = s.h <= 0.0;
      if (!last && s.t + 1e-12 < next_log) return;
      next_log = scenario.log_period > 0.0 ? s.t + scenario.log_period : 0.0;
      const core::ControllerOutput& o = s.output;
      result.rows.push_back({s.t, s.pose.x, s.pose.y, s.pose.theta, o.p_r.x(), o.p_r.y(), s.reference.position.x(),
                             s.reference.position.y(), s.sample.position.x(), s.sample.position.y(), o.v_hat.x(),
                             o.v_hat.y(), s.reference.velocity.x(), s.reference.velocity.y(), o.e.x(), o.e.y(),
                             o.e.norm(), o.rho, o.u.v, o.u.omega, o.u_d.v, o.u_d.omega, o.u_c.x(), o.u_c.y(),
                             s.clearance_offset, s.clearance_body, s.h, o.active.saturated ? 1.0 : 0.0,
                             o.active.avoiding ? 1.0 : 0.0, o.active.envelope_widened ? 1.0 : 0.0,
                             std::abs(o.u.v) / scenario.setup.controller.v_max +
                                 std::abs(o.u.omega) / scenario.setup.controller.w_max,
                             o.u_t.x(), o.u_t.y(), s.p_r_true.x(), s.p_r_true.y(),
                             static_cast<double>(o.passing_side)});
    };
  }
  const auto start = std::chrono::steady_clock::now();
  result.summary = core::runClosedLoop(scenario.setup, *reference, observer);
  result.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error(path + ": cannot write");
}

void writeTrajectoryCsv(const std::string& path, const std::vector<CsvRow>& rows) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error(path + ": cannot write");
  for (size_t i = 0; i < kCsvColumns.size(); ++i) std::fprintf(f, "%s%s", i ? "," : "", kCsvColumns[i]);
  std::fputc('\n', f);
  for (const CsvRow& row : rows) {
    for (size_t i = 0; i < row.size(); ++i) std::fprintf(f, "%s%.9g", i ? "," : "", row[i]);
    std::fputc('\n', f);
  }
  const bool ok = std::ferror(f) == 0;
  if (std::fclose(f) != 0 || !ok) throw std::runtime_error(path + ": write failed");
}

void writeSharedMetricsJson(std::ostream& j, const core::RunMetrics& m) {
  auto num = [&](const char* key, double value) { j << "  \"" << key << "\": " << jsonNumber(value) << ",\n"; };
  num("ase", m.ase);
  num("aae", m.aae);
  num("tec", m.tec);
  num("max_e_over_rho", m.max_e_over_rho);
  num("max_rho", m.max_rho);
  num("final_error", m.final_error);
  num("min_clearance_offset", m.min_clearance_offset);
  num("min_clearance_body", m.min_clearance_body);
  num("body_collisions", static_cast<double>(m.body_collisions));
  num("body_contact_time_s", m.body_contact_time);
  num("diamond_violations", static_cast<double>(m.diamond_violations));
  num("saturated_steps", static_cast<double>(m.saturated_steps));
  num("envelope_widenings", static_cast<double>(m.envelope_widenings));
  num("estimator_rms_error", m.estimator_rms_error);
  num("estimator_max_error_settled", m.estimator_max_error_settled);
  num("steps", static_cast<double>(m.steps));
}

std::string metricsJson(const Scenario& scenario, const RunResult& result) {
  const core::RunMetrics& m = result.summary.metrics;
  const core::ClosedLoopSetup& setup = scenario.setup;
  const core::ControllerConfig& c = setup.controller;
  std::ostringstream j;
  auto num = [&](const char* key, double value, bool comma = true) {
    j << "  \"" << key << "\": " << jsonNumber(value) << (comma ? ",\n" : "\n");
  };
  j << "{\n";
  writeSharedMetricsJson(j, m);
  num("offset_collisions", static_cast<double>(m.offset_collisions));
  num("offset_contact_time_s", m.offset_contact_time);
  num("nan_count", static_cast<double>(m.nan_count));
  num("true_ase", m.true_ase);
  num("true_aae", m.true_aae);
  num("max_true_error", m.max_true_error);
  num("longest_stall_s", m.longest_stall);
  num("conflict_steps", static_cast<double>(m.conflict_steps));
  num("escape_steps", static_cast<double>(m.escape_steps));
  num("side_flips", static_cast<double>(m.side_flips));
  num("sim_time_s", m.sim_time);
  num("wall_time_s", result.wall_time);
  num("realtime_factor", result.realtimeFactor());
  j << "  \"scenario\": {\n"
    << "    \"name\": " << nlohmann::json(scenario.name).dump() << ",\n"
    << "    \"file\": " << nlohmann::json(scenario.file).dump() << ",\n"
    << "    \"controller\": " << nlohmann::json(c).dump() << ",\n"
    << "    \"reference\": \"" << scenario.reference.type << "\",\n"
    << "    \"variant\": \"" << toString(setup.law) << "\",\n"
    << "    \"estimator\": \"" << toString(setup.velocity_source) << "\",\n"
    << "    \"body_safe\": " << (c.body_safe ? "true" : "false") << ",\n"
    << "    \"tangential_avoidance\": " << (c.tangential_avoidance ? "true" : "false") << ",\n"
    << "    \"moving_obstacles\": " << (c.moving_obstacles ? "true" : "false") << ",\n"
    << "    \"predict_target\": " << (c.predict_target ? "true" : "false") << ",\n"
    << "    \"compensate_pose_age\": " << (c.compensate_pose_age ? "true" : "false") << ",\n"
    << "    \"target_delay\": " << jsonNumber(setup.sensor.delay) << ",\n"
    << "    \"target_sample_period\": " << jsonNumber(setup.sample_period) << ",\n"
    << "    \"pose_delay\": " << jsonNumber(setup.pose_sensor.delay) << ",\n"
    << "    \"pose_sample_period\": " << jsonNumber(setup.pose_sensor.sample_period) << ",\n"
    << "    \"robot_radius\": " << jsonNumber(c.robot_radius) << ",\n"
    << "    \"offset\": " << jsonNumber(c.offset) << ",\n"
    << "    \"effective_radius\": " << jsonNumber(c.effectiveRadius()) << ",\n"
    << "    \"v_max\": " << jsonNumber(c.v_max) << ",\n"
    << "    \"w_max\": " << jsonNumber(c.w_max) << ",\n"
    << "    \"rho_inf\": " << jsonNumber(c.rho_inf) << ",\n"
    << "    \"rho_o\": " << jsonNumber(c.estimator.rho_o) << ",\n"
    << "    \"control_period\": " << jsonNumber(setup.control_period) << ",\n"
    << "    \"max_step\": " << jsonNumber(setup.max_step) << ",\n"
    << "    \"integrator\": \"" << toString(setup.integrator) << "\",\n"
    << "    \"duration\": " << jsonNumber(setup.duration) << ",\n"
    << "    \"obstacles\": [";
  for (size_t i = 0; i < setup.obstacles.size(); ++i) {
    const core::Disk& d = setup.obstacles[i];
    const Eigen::Vector2d v =
        setup.obstacle_velocities.empty() ? Eigen::Vector2d::Zero() : setup.obstacle_velocities[i];
    j << (i ? ", " : "") << "{\"center\": [" << jsonNumber(d.center.x()) << ", " << jsonNumber(d.center.y())
      << "], \"radius\": " << jsonNumber(d.radius) << ", \"velocity\": [" << jsonNumber(v.x()) << ", "
      << jsonNumber(v.y()) << "]}";
  }
  j << "]\n  }\n}\n";
  return j.str();
}

}  // namespace sim
}  // namespace amigobot_tracking
