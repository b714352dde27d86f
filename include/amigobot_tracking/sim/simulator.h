// Runs a scenario and writes its outputs: trajectory.csv (one row per logged step),
// metrics.json (core/metrics.h figures plus the scenario facts the plots need).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "amigobot_tracking/sim/closed_loop.h"
#include "amigobot_tracking/sim/scenario.h"

namespace amigobot_tracking {
namespace sim {

// Columns of trajectory.csv, in order (units: m, rad, s, m/s, rad/s).
// p_r_x/p_r_y are the controller's belief (a delayed pose); p_r_true_* the true offset point.
constexpr std::array<const char*, 36> kCsvColumns = {
    "t",        "x",          "y",          "theta",     "p_r_x",   "p_r_y",   "p_d_x",   "p_d_y",
    "meas_x",   "meas_y",     "v_hat_x",    "v_hat_y",   "v_d_x",   "v_d_y",   "e_x",     "e_y",
    "e_norm",   "rho",        "v",          "omega",     "v_d",     "omega_d", "u_c_x",   "u_c_y",
    "clearance_offset", "clearance_body", "h", "saturated", "avoiding", "envelope_widened", "diamond_norm",
    "u_t_x",    "u_t_y",      "p_r_true_x", "p_r_true_y", "passing_side"};
using CsvRow = std::array<double, kCsvColumns.size()>;

struct RunResult {
  sim::ClosedLoopSummary summary;
  std::vector<CsvRow> rows;  // empty unless logging was asked for
  double wall_time = 0.0;    // [s] of the closed loop alone (rows are buffered, written later)
  double realtimeFactor() const { return wall_time > 0.0 ? summary.metrics.sim_time / wall_time : 0.0; }
};

// Runs the scenario; with `log`, keeps a row every scenario.log_period (every step when 0;
// the first and last steps always).
RunResult runScenario(const Scenario& scenario, bool log);

// Throws std::runtime_error naming the file when it cannot be written.
void writeTrajectoryCsv(const std::string& path, const std::vector<CsvRow>& rows);
std::string metricsJson(const Scenario& scenario, const RunResult& result);
void writeText(const std::string& path, const std::string& text);

}  // namespace sim
}  // namespace amigobot_tracking
