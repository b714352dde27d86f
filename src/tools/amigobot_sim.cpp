// Offline simulator: runs a scenario file (config/scenarios/*.yaml) through the core's
// closed loop and writes DIR/trajectory.csv, DIR/metrics.json and the paper's figures
// (scripts/reports/plot_run.py). No ROS at run time.
//
//   amigobot_sim --scenario FILE.yaml --out DIR [options]
//   amigobot_sim --scenario FILE.yaml --benchmark N        (real-time factor, nothing written)
//   amigobot_sim --scenario FILE.yaml --out DIR --monte-carlo N --seed S
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "amigobot_tracking/sim/monte_carlo.h"
#include "amigobot_tracking/sim/scenario.h"
#include "amigobot_tracking/sim/simulator.h"

extern char** environ;

using namespace amigobot_tracking;

namespace {

const char* kUsage =
    "usage: amigobot_sim --scenario FILE.yaml --out DIR [options]\n"
    "  --variant paper|fixed_rho|proportional   control law (overrides controller.variant)\n"
    "  --estimator paper|finite_difference|kalman  target velocity source (controller.estimator)\n"
    "  --body-safe true|false                   effective radius R + r in (10) (controller.body_safe)\n"
    "  --max-step S                             variable step up to S seconds; 0 = fixed (simulation.max_step)\n"
    "  --tangential true|false                  tangential escape (controller.tangential_avoidance)\n"
    "  --moving-obstacles true|false            obstacle velocities in (10) (controller.moving_obstacles)\n"
    "  --predict-target true|false              p_d + v_hat * sample age (controller.predict_target)\n"
    "  --compensate-pose-age true|false         replay the commands over the pose's age (controller.compensate_pose_age)\n"
    "  --target-delay S                         target measurement delay [s] (target.delay)\n"
    "  --target-period S                        target sampling period [s] (target.sample_period)\n"
    "  --pose-delay S                           robot pose delay [s] (localization.delay)\n"
    "  --pose-period S                          robot pose sampling period [s] (localization.sample_period)\n"
    "  --obstacle-speed S                       Monte Carlo: moving obstacles at speeds drawn in [0, S] m/s\n"
    "  --control-period S                       the fine step [s] (simulation.control_period)\n"
    "  --integrator explicit|band_implicit|second_order  how steps are formed (simulation.integrator)\n"
    "  --log-period S                           CSV row spacing [s]; 0 = every step (simulation.log_period)\n"
    "  --no-plot                                write CSV and JSON only\n"
    "  --monte-carlo N --seed S                 N randomised variants; writes DIR/monte_carlo.json\n"
    "  --seed S                                 noise seed of a single run (simulation.seed)\n"
    "  --benchmark N                            run N times without output; print the real-time factor\n";

int usage(const std::string& why) {
  std::fprintf(stderr, "amigobot_sim: %s\n%s", why.c_str(), kUsage);
  return 2;
}

double toNumber(const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) throw sim::ScenarioError(flag + ": not a number: '" + text + "'");
  return v;
}

bool toBool(const std::string& flag, const std::string& text) {
  if (text != "true" && text != "false") throw sim::ScenarioError(flag + ": expected true or false, got '" + text + "'");
  return text == "true";
}

// A number >= 0 (delays, periods, speeds).
double toNonNegative(const std::string& flag, const std::string& text) {
  const double v = toNumber(flag, text);
  if (v < 0.0) throw sim::ScenarioError(flag + ": must be >= 0, got '" + text + "'");
  return v;
}

// A whole number in [lo, hi] (counts and seeds).
long long toWhole(const std::string& flag, const std::string& text, double lo, double hi) {
  const double v = toNumber(flag, text);
  if (v != std::floor(v) || v < lo || v > hi)
    throw sim::ScenarioError(flag + ": expected a whole number in [" + std::to_string(static_cast<long long>(lo)) + ", " +
                             std::to_string(static_cast<long long>(hi)) + "], got '" + text + "'");
  return static_cast<long long>(v);
}

int runPlot(const std::string& csv) {
  const char* script = std::getenv("AMIGOBOT_PLOT_SCRIPT");
  const std::string path = script ? script : AMIGOBOT_PLOT_SCRIPT;
  std::vector<std::string> args = {"/usr/bin/python3", path, csv};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

int main(int argc, char** argv) {
  std::map<std::string, std::string> opt;
  bool plot = true;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--no-plot") {
      plot = false;
    } else if (flag == "--help" || flag == "-h") {
      std::printf("%s", kUsage);
      return 0;
    } else if (flag.rfind("--", 0) == 0 && i + 1 < argc) {
      opt[flag] = argv[++i];
    } else {
      return usage("unexpected argument '" + flag + "'");
    }
  }
  static const char* known[] = {"--scenario", "--out", "--variant", "--estimator", "--body-safe", "--max-step",
                                "--control-period", "--log-period", "--monte-carlo", "--seed", "--benchmark",
                                "--tangential", "--moving-obstacles", "--predict-target", "--compensate-pose-age", "--target-delay",
                                "--target-period", "--pose-delay", "--pose-period", "--obstacle-speed", "--integrator"};
  for (const auto& [flag, value] : opt) {
    if (std::find_if(std::begin(known), std::end(known), [&](const char* k) { return flag == k; }) == std::end(known))
      return usage("unknown option '" + flag + "'");
  }
  if (!opt.count("--scenario")) return usage("--scenario FILE.yaml is required");
  if (!opt.count("--out") && !opt.count("--benchmark")) return usage("--out DIR is required");

  sim::Scenario scenario;
  int monte_carlo = 0, benchmark = 0;
  double obstacle_speed = 0.0;
  std::uint64_t seed = 1;
  try {
    scenario = sim::loadScenario(opt["--scenario"]);
    sim::ClosedLoopSetup& setup = scenario.setup;
    try {
      if (opt.count("--variant")) setup.law = sim::parseControlLaw(opt["--variant"]);
    } catch (const std::invalid_argument& e) {
      throw sim::ScenarioError(std::string("--variant: ") + e.what());
    }
    try {
      if (opt.count("--estimator")) setup.velocity_source = sim::parseVelocitySource(opt["--estimator"]);
    } catch (const std::invalid_argument& e) {
      throw sim::ScenarioError(std::string("--estimator: ") + e.what());
    }
    try {
      if (opt.count("--integrator")) setup.integrator = sim::parseIntegrator(opt["--integrator"]);
    } catch (const std::invalid_argument& e) {
      throw sim::ScenarioError(std::string("--integrator: ") + e.what());
    }
    core::ControllerConfig& c = setup.controller;
    if (opt.count("--body-safe")) c.body_safe = toBool("--body-safe", opt["--body-safe"]);
    if (opt.count("--tangential")) c.tangential_avoidance = toBool("--tangential", opt["--tangential"]);
    if (opt.count("--moving-obstacles")) c.moving_obstacles = toBool("--moving-obstacles", opt["--moving-obstacles"]);
    if (opt.count("--predict-target")) c.predict_target = toBool("--predict-target", opt["--predict-target"]);
    if (opt.count("--compensate-pose-age"))
      c.compensate_pose_age = toBool("--compensate-pose-age", opt["--compensate-pose-age"]);
    if (opt.count("--target-delay")) setup.sensor.delay = toNonNegative("--target-delay", opt["--target-delay"]);
    if (opt.count("--target-period")) setup.sample_period = toNonNegative("--target-period", opt["--target-period"]);
    if (opt.count("--pose-delay")) setup.pose_sensor.delay = toNonNegative("--pose-delay", opt["--pose-delay"]);
    if (opt.count("--pose-period"))
      setup.pose_sensor.sample_period = toNonNegative("--pose-period", opt["--pose-period"]);
    if (opt.count("--obstacle-speed")) obstacle_speed = toNonNegative("--obstacle-speed", opt["--obstacle-speed"]);
    if (opt.count("--max-step")) setup.max_step = toNumber("--max-step", opt["--max-step"]);
    if (opt.count("--control-period")) setup.control_period = toNumber("--control-period", opt["--control-period"]);
    if (opt.count("--log-period")) scenario.log_period = toNumber("--log-period", opt["--log-period"]);
    if (opt.count("--monte-carlo")) monte_carlo = static_cast<int>(toWhole("--monte-carlo", opt["--monte-carlo"], 1, 1e6));
    if (opt.count("--benchmark")) benchmark = static_cast<int>(toWhole("--benchmark", opt["--benchmark"], 1, 1e6));
    if (opt.count("--seed")) {
      seed = static_cast<std::uint64_t>(toWhole("--seed", opt["--seed"], 0, 9e15));
      setup.sensor.seed = seed;  // a single run: the noise seed; Monte Carlo: the base of every variant
    }
    sim::checkScenario(scenario);  // again, with the overrides
  } catch (const std::exception& e) {
    std::fprintf(stderr, "amigobot_sim: %s\n", e.what());
    return 2;
  }

  if (benchmark > 0) {
    std::vector<double> walls;
    sim::RunResult r;
    for (int i = 0; i < benchmark; ++i) {
      r = sim::runScenario(scenario, false);
      walls.push_back(r.wall_time);
    }
    std::sort(walls.begin(), walls.end());
    const double median = walls[walls.size() / 2];
    std::printf("%s: %s, %s, %llu steps for %.3f s simulated; wall median %.3f ms, best %.3f ms over %d runs\n",
                scenario.name.c_str(), scenario.setup.max_step > scenario.setup.control_period ? "variable step" : "fixed step",
                sim::toString(scenario.setup.integrator).c_str(),
                static_cast<unsigned long long>(r.summary.metrics.steps), r.summary.metrics.sim_time, median * 1e3,
                walls.front() * 1e3, benchmark);
    std::printf("realtime_factor %.0f x (median), %.0f x (best)\n", r.summary.metrics.sim_time / median,
                r.summary.metrics.sim_time / walls.front());
    return 0;
  }

  const std::string out = opt["--out"];
  try {
    std::filesystem::create_directories(out);
    if (monte_carlo > 0) {
      sim::MonteCarloOptions mc;
      mc.runs = monte_carlo;
      mc.seed = seed;
      mc.obstacle_speed = obstacle_speed;
      const std::string json = sim::runMonteCarlo(scenario, mc);
      sim::writeText(out + "/monte_carlo.json", json);
      std::printf("%s", json.substr(0, json.find("\"per_run\"")).c_str());
      std::printf("  ...\n}\nwrote %s/monte_carlo.json\n", out.c_str());
      return 0;
    }
    const sim::RunResult result = sim::runScenario(scenario, true);
    sim::writeTrajectoryCsv(out + "/trajectory.csv", result.rows);
    sim::writeText(out + "/metrics.json", sim::metricsJson(scenario, result));
    const sim::RunMetrics& m = result.summary.metrics;
    char ratio[32] = "- (no rho)";
    if (scenario.setup.law != sim::ControlLaw::kProportional) std::snprintf(ratio, sizeof ratio, "%.3f", m.max_e_over_rho);
    const core::ControllerConfig& c = scenario.setup.controller;
    std::string beyond;  // the switches beyond the paper that are on
    for (const auto& [on, name] : {std::pair<bool, const char*>{c.tangential_avoidance, "tangential"},
                                   {c.moving_obstacles, "moving_obstacles"},
                                   {c.predict_target, "predict_target"},
                                   {c.compensate_pose_age, "compensate_pose_age"}})
      if (on) beyond += std::string(", ") + name;
    std::printf("%s [%s, estimator %s, body_safe %s%s]: ASE %.5f AAE %.5f TEC %.4f max|e|/rho %s\n",
                scenario.name.c_str(), sim::toString(scenario.setup.law).c_str(),
                sim::toString(scenario.setup.velocity_source).c_str(), c.body_safe ? "true" : "false",
                beyond.c_str(), m.ase, m.aae, m.tec, ratio);
    std::printf("  true error (true target, true robot): ASE %.5f, peak %.4f m; longest stall %.2f s\n", m.true_ase,
                m.max_true_error, m.longest_stall);
    std::printf("  clearance offset %.4f m, body %.4f m; collisions offset %llu, body %llu; diamond violations %llu; "
                "NaN %llu\n",
                m.min_clearance_offset, m.min_clearance_body, static_cast<unsigned long long>(m.offset_collisions),
                static_cast<unsigned long long>(m.body_collisions),
                static_cast<unsigned long long>(m.diamond_violations), static_cast<unsigned long long>(m.nan_count));
    std::printf("  %llu steps, %.3f s simulated in %.4f s: %.0f x real time\n",
                static_cast<unsigned long long>(m.steps), m.sim_time, result.wall_time, result.realtimeFactor());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "amigobot_sim: %s\n", e.what());
    return 1;
  }
  if (plot) {
    std::fflush(stdout);  // our lines before the plotter's
    const int rc = runPlot(out + "/trajectory.csv");
    if (rc != 0) {
      std::fprintf(stderr, "amigobot_sim: plotting failed (exit %d); the CSV and JSON are written. Re-plot with\n"
                   "  /usr/bin/python3 scripts/reports/plot_run.py %s/trajectory.csv\n", rc, out.c_str());
      return 1;
    }
  }
  return 0;
}
