#include "amigobot_tracking/sim/simulator.h"

#include "amigobot_tracking/sim/config_json.h"
#include "amigobot_tracking/sim/json.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace amigobot_tracking {
namespace sim {

RunResult runScenario(const Scenario& scenario, bool log) {
  RunResult result;
  const auto reference = scenario.makeReference();
  double next_log = 0.0;
  sim::ClosedLoopObserver observer;
  if (log) {
    result.rows.reserve(static_cast<size_t>(
        scenario.setup.duration / std::max(scenario.log_period, scenario.setup.control_period) + 16));
    observer = [&](const sim::ClosedLoopStep& s) {
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
  result.summary = sim::runClosedLoop(scenario.setup, *reference, observer);
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

std::string metricsJson(const Scenario& scenario, const RunResult& result) {
  const sim::RunMetrics& m = result.summary.metrics;
  const sim::ClosedLoopSetup& setup = scenario.setup;
  const core::ControllerConfig& c = setup.controller;
  Json j = m;
  j["wall_time_s"] = jsonNumber(result.wall_time);
  j["realtime_factor"] = jsonNumber(result.realtimeFactor());
  Json& s = j["scenario"];
  s["name"] = scenario.name;
  s["file"] = scenario.file;
  s["controller"] = c;
  s["reference"] = scenario.reference.type;
  s["variant"] = setup.law;
  s["estimator"] = toString(setup.velocity_source);
  s["body_safe"] = c.body_safe;
  s["tangential_avoidance"] = c.paper.tangential_avoidance;
  s["moving_obstacles"] = c.moving_obstacles;
  s["predict_target"] = c.predict_target;
  s["compensate_pose_age"] = c.compensate_pose_age;
  s["target_delay"] = jsonNumber(setup.sensor.delay);
  s["target_sample_period"] = jsonNumber(setup.sample_period);
  s["pose_delay"] = jsonNumber(setup.pose_sensor.delay);
  s["pose_sample_period"] = jsonNumber(setup.pose_sensor.sample_period);
  s["robot_radius"] = jsonNumber(c.robot_radius);
  s["offset"] = jsonNumber(c.offset);
  s["effective_radius"] = jsonNumber(c.effectiveRadius());
  s["v_max"] = jsonNumber(c.v_max);
  s["w_max"] = jsonNumber(c.w_max);
  s["rho_inf"] = jsonNumber(c.rho_inf);
  s["rho_o"] = jsonNumber(c.estimator.rho_o);
  s["control_period"] = jsonNumber(setup.control_period);
  s["max_step"] = jsonNumber(setup.max_step);
  s["integrator"] = toString(setup.integrator);
  s["duration"] = jsonNumber(setup.duration);
  s["obstacles"] = Json::array();
  for (size_t i = 0; i < setup.obstacles.size(); ++i) {
    // The velocity at the start (a motion of legs: its first leg's, even before it starts).
    const bool moves = !setup.obstacle_motions.empty() && !setup.obstacle_motions[i].legs.empty();
    s["obstacles"].push_back(
        obstacleJson(setup.obstacles[i], moves ? setup.obstacle_motions[i].legs[0].velocity : Eigen::Vector2d::Zero()));
  }
  return dumpJson(j);
}

}  // namespace sim
}  // namespace amigobot_tracking
