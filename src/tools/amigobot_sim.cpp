// Offline simulator: runs a scenario file (config/scenarios/*.yaml) through the core's
// closed loop and writes DIR/trajectory.csv, DIR/metrics.json and the paper's figures
// (scripts/reports/plot_run.py). No ROS at run time.
//
//   amigobot_sim --scenario FILE.yaml --out DIR [options]
//   amigobot_sim --scenario FILE.yaml --benchmark N [--benchmark-json F]  (real-time factor)
//   amigobot_sim --scenario FILE.yaml --out DIR --set controller.k_d=2 --set target.delay=0.1
//   amigobot_sim --scenario FILE.yaml --out DIR --monte-carlo N --seed S [--jobs J]
//   amigobot_sim --identify RUN.csv --identify-out ROBOT.yaml  (scripts/tools/identify_robot.py: from a bag)
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
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include "amigobot_tracking/core/law/law_registry.h"
#include "amigobot_tracking/sim/actuator_fit.h"
#include "amigobot_tracking/sim/gain_tuner.h"
#include "amigobot_tracking/sim/monte_carlo.h"
#include "amigobot_tracking/sim/robot_description.h"
#include "amigobot_tracking/sim/scenario.h"
#include "amigobot_tracking/sim/simulator.h"
#include "amigobot_tracking/sim_mrpt/reactive_law.h"

extern char** environ;

using namespace amigobot_tracking;

namespace {

// The flags that are shorthands for a scenario key: each becomes `--set section.key=value`.
struct Shorthand {
  const char* flag;
  const char* key;
  const char* help;
};
constexpr Shorthand kShorthands[] = {
    {"--variant", "controller.variant",
     "control law (default: the file's, else recommended)"},
    {"--estimator", "controller.estimator", "target velocity source paper|finite_difference|kalman"},
    {"--body-safe", "controller.body_safe", "effective radius R + r in (10) (true|false)"},
    {"--tangential", "controller.tangential_avoidance", "tangential escape (true|false)"},
    {"--moving-obstacles", "controller.moving_obstacles", "obstacle velocities in (10) (true|false)"},
    {"--predict-target", "controller.predict_target", "p_d + v_hat * sample age (true|false)"},
    {"--compensate-pose-age", "controller.compensate_pose_age", "replay the commands over the pose's age"},
    {"--target-delay", "target.delay", "target measurement delay [s]"},
    {"--target-period", "target.sample_period", "target sampling period [s]"},
    {"--pose-delay", "localization.delay", "robot pose delay [s]"},
    {"--pose-period", "localization.sample_period", "robot pose sampling period [s]"},
    {"--max-step", "simulation.max_step", "variable step up to S seconds; 0 = fixed"},
    {"--control-period", "simulation.control_period", "the fine step [s]"},
    {"--integrator", "simulation.integrator", "explicit|band_implicit|second_order"},
    {"--log-period", "simulation.log_period", "CSV row spacing [s]; 0 = every step"},
    {"--seed", "simulation.seed", "noise seed of a single run; Monte Carlo: the base seed"},
};

// --benchmark: N runs without output; the wall-time figures on stdout and, with a path, as JSON.
int runBenchmark(const sim::Scenario& scenario, int runs, const std::string& json_path) {
  std::vector<double> walls;
  sim::RunResult r;
  for (int i = 0; i < runs; ++i) {
    r = sim::runScenario(scenario, false);
    walls.push_back(r.wall_time);
  }
  std::sort(walls.begin(), walls.end());
  const double median = walls[walls.size() / 2];
  const bool variable = scenario.setup.max_step > scenario.setup.control_period;
  const sim::RunMetrics& m = r.summary.metrics;
  std::printf("%s: %s, %s, %llu steps for %.3f s simulated; wall median %.3f ms, best %.3f ms over %d runs\n",
              scenario.name.c_str(), variable ? "variable step" : "fixed step",
              sim::toString(scenario.setup.integrator).c_str(), static_cast<unsigned long long>(m.steps), m.sim_time,
              median * 1e3, walls.front() * 1e3, runs);
  std::printf("realtime_factor %.0f x (median), %.0f x (best)\n", m.sim_time / median, m.sim_time / walls.front());
  if (json_path.empty()) return 0;
  const nlohmann::json j = {{"scenario", scenario.name},
                            {"variable_step", variable},
                            {"integrator", sim::toString(scenario.setup.integrator)},
                            {"steps", m.steps},
                            {"sim_time", m.sim_time},
                            {"runs", runs},
                            {"wall_median", median},
                            {"wall_best", walls.front()},
                            {"realtime_factor_median", m.sim_time / median},
                            {"realtime_factor_best", m.sim_time / walls.front()}};
  sim::writeText(json_path, j.dump(2) + "\n");
  return 0;
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

bool namesVariant(const std::vector<std::string>& sets) {
  for (const std::string& s : sets)
    if (s.rfind("controller.variant=", 0) == 0) return true;
  return false;
}

// The file's controller section has a variant key (an unreadable file is reported by loadScenario).
bool fileNamesVariant(const std::string& path) {
  try {
    const YAML::Node root = YAML::LoadFile(path);
    return root["controller"] && root["controller"]["variant"];
  } catch (const std::exception&) {
    return false;
  }
}

// The --set equivalents of the shorthand flags given on the command line.
std::vector<std::string> shorthandOverrides(const CLI::App& app, const std::map<std::string, std::string>& values) {
  std::vector<std::string> overrides;
  for (const Shorthand& s : kShorthands)
    if (app.count(s.flag)) overrides.push_back(std::string(s.key) + "=" + values.at(s.flag));
  return overrides;
}

// --tune: the overrides of the command line apply to every scenario of the suite; the law
// tuned is the recommended one unless --variant or --set names another.
int runTuner(const CLI::App& app, const std::string& suite_path, const std::string& out_path, int evaluations,
             int runs, int jobs, const std::vector<std::string>& sets,
             const std::map<std::string, std::string>& shorthand_values) {
  sim::TunerOptions options;
  if (!app.count("--variant") && !namesVariant(sets)) options.overrides.push_back("controller.variant=recommended");
  const std::vector<std::string> shorthands = shorthandOverrides(app, shorthand_values);
  options.overrides.insert(options.overrides.end(), shorthands.begin(), shorthands.end());
  options.overrides.insert(options.overrides.end(), sets.begin(), sets.end());
  options.runs = runs > 0 ? runs : 8;
  options.jobs = jobs;
  options.max_evaluations = evaluations;
  options.progress = true;
  try {
    if (app.count("--seed")) options.seed = std::stoull(shorthand_values.at("--seed"));
    const sim::TuningSuite suite = sim::loadTuningSuite(suite_path);
    const sim::TuningResult result = sim::tuneGains(suite, options);
    const std::filesystem::path parent = std::filesystem::path(out_path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    const std::string yaml = sim::tunedGainsYaml(result, suite, options);
    sim::writeText(out_path, yaml);
    std::printf("%swrote %s\n", yaml.c_str(), out_path.c_str());
    return result.best.feasible ? 0 : 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "amigobot_sim: %s\n", e.what());
    return 2;
  }
}

// --identify: the actuator model fitted to a recorded run, written as a robot YAML that
// scenarios name with robot.description (and --tune with --set robot.description=FILE).
int runIdentify(const std::string& run_path, const std::string& out_path, double half_track) {
  if (run_path.size() > 4 && run_path.compare(run_path.size() - 4, 4, ".bag") == 0) {
    std::fprintf(stderr, "amigobot_sim: --identify reads a CSV; for a bag run scripts/tools/identify_robot.py %s\n",
                 run_path.c_str());
    return 2;
  }
  try {
    sim::ActuatorRecording run = sim::readActuatorCsv(run_path);
    run.half_track = half_track;
    const sim::ActuatorFit fit = sim::fitActuator(run);
    char origin[200];
    std::snprintf(origin, sizeof(origin), "fitted by amigobot_sim --identify from %zu commands and %zu odometry samples "
                  "(rms velocity error %.4f m/s)", run.commands.size(), run.odometry.size(), fit.rms_error);
    std::string yaml = sim::robotDynamicsYaml(fit.dynamics, std::string(origin) + " of " + run_path);
    for (const std::string& note : fit.notes) yaml = "# Note: " + note + ".\n" + yaml;
    const std::filesystem::path parent = std::filesystem::path(out_path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    sim::writeText(out_path, yaml);
    std::printf("%swrote %s\n", yaml.c_str(), out_path.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "amigobot_sim: --identify %s: %s\n", run_path.c_str(), e.what());
    return 2;
  }
}

}  // namespace

int main(int argc, char** argv) {
  sim_mrpt::provideReactiveLaw();  // the registry's mrpt_reactive
  CLI::App app{"Offline simulator: a scenario file through the core's closed loop (no ROS)", "amigobot_sim"};
  std::string scenario_path, out, benchmark_json;
  std::vector<std::string> sets;
  int monte_carlo = 0, benchmark = 0;
  long long replay = -1;  // --mc-replay K
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  double obstacle_speed = 0.0;
  sim::MonteCarloOptions mc;
  bool no_plot = false;
  std::string tune_suite, tune_out;
  int tune_evaluations = 30;
  std::string identify_run, identify_out;
  double half_track = core::kAmigoHalfTrack;
  app.add_option("--scenario", scenario_path, "scenario file (config/scenarios/*.yaml); required but with --tune");
  app.add_option("--tune", tune_suite, "tune the law's gains on this suite (config/scenarios/*_suite.txt): "
                 "--monte-carlo N variants per scenario (8), writes --tune-out");
  app.add_option("--tune-out", tune_out, "with --tune: the YAML of the tuned gains (default OUT/tuned_gains.yaml)");
  app.add_option("--tune-evaluations", tune_evaluations, "with --tune: candidates judged, the start included")
      ->check(CLI::Range(1, 100000));
  app.add_option("--identify", identify_run, "fit the robot's dynamics (ramps, latency, wheel limit) to a recorded run: "
                 "CSV lines cmd|odom,t,v,w (scripts/tools/identify_robot.py makes one from a bag); writes --identify-out");
  app.add_option("--identify-out", identify_out, "with --identify: the robot YAML (default OUT/robot.yaml)");
  app.add_option("--half-track", half_track, "with --identify: half the wheel track [m] (default the AmigoBot's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--out", out, "output folder: trajectory.csv, metrics.json, figures");
  app.add_option("--set", sets, "section.key=value: any scenario key (repeatable), checked like the file");
  std::map<std::string, std::string> shorthand_values;
  for (const Shorthand& s : kShorthands)
    app.add_option(s.flag, shorthand_values[s.flag],
                   std::string(s.help) + (std::string(s.key) == "controller.variant" ? ": " + core::lawNameList(core::lawNames()) : "") +
                       " (= --set " + s.key + "=...)");
  app.add_option("--monte-carlo", monte_carlo, "N randomised variants; writes DIR/monte_carlo.json")
      ->check(CLI::Range(1, 1000000));
  app.add_option("--obstacle-speed", obstacle_speed, "Monte Carlo: moving obstacles at speeds drawn in [0, S] m/s")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--jobs", jobs, "Monte Carlo: threads running the variants (default: every core)")
      ->check(CLI::Range(1, 1024));
  app.add_option("--mc-obstacle-shift", mc.obstacle_shift, "Monte Carlo: obstacle centres shift within this disk [m]")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--mc-pose-shift", mc.pose_shift, "Monte Carlo: the start shifts within this disk [m]")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--mc-heading-shift", mc.heading_shift, "Monte Carlo: the start heading within +-this [rad]")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--mc-noise", mc.noise_std_max, "Monte Carlo: target noise std drawn in [0, S] m")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--mc-sample-periods", mc.sample_periods, "Monte Carlo: target sample period drawn from these [s]")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--mc-replay", replay,
                 "run Monte Carlo variant K alone (per_run[].index of monte_carlo.json, same --seed and --mc-* options), "
                 "writing its trajectory and metrics like a single run")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--benchmark", benchmark, "run N times without output; print the real-time factor")
      ->check(CLI::Range(1, 1000000));
  app.add_option("--benchmark-json", benchmark_json, "with --benchmark: also write its figures to this JSON file");
  app.add_flag("--no-plot", no_plot, "write CSV and JSON only");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? 0 : 2;  // --help: 0; a bad command line: 2, as a bad scenario
  }
  if (!identify_run.empty()) {
    if (out.empty() && identify_out.empty()) {
      std::fprintf(stderr, "amigobot_sim: --identify needs --out DIR or --identify-out FILE\n");
      return 2;
    }
    return runIdentify(identify_run, identify_out.empty() ? out + "/robot.yaml" : identify_out, half_track);
  }
  if (!tune_suite.empty()) {
    if (out.empty() && tune_out.empty()) {
      std::fprintf(stderr, "amigobot_sim: --tune needs --out DIR or --tune-out FILE\n");
      return 2;
    }
    return runTuner(app, tune_suite, tune_out.empty() ? out + "/tuned_gains.yaml" : tune_out, tune_evaluations,
                    monte_carlo, jobs, sets, shorthand_values);
  }
  if (scenario_path.empty()) {
    std::fprintf(stderr, "amigobot_sim: --scenario FILE is required (or --tune SUITE)\n");
    return 2;
  }
  if (out.empty() && benchmark == 0) {
    std::fprintf(stderr, "amigobot_sim: --out DIR is required (or --benchmark N)\n%s", app.help().c_str());
    return 2;
  }

  std::vector<std::string> overrides = shorthandOverrides(app, shorthand_values);
  // No law named on the command line nor in the file: the recommended law.
  if (!app.count("--variant") && !namesVariant(sets) && !fileNamesVariant(scenario_path))
    overrides.insert(overrides.begin(), "controller.variant=recommended");
  overrides.insert(overrides.end(), sets.begin(), sets.end());
  sim::Scenario scenario;
  try {
    scenario = sim::loadScenario(scenario_path, overrides);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "amigobot_sim: %s\n", e.what());
    return 2;
  }
  // Monte Carlo's base seed: --seed, else 1 (not the file's simulation.seed).
  const std::uint64_t seed = app.count("--seed") ? scenario.setup.sensor.seed : 1;
  if (benchmark > 0) return runBenchmark(scenario, benchmark, benchmark_json);

  try {
    std::filesystem::create_directories(out);
    mc.seed = seed;  // the variants' draw, for --monte-carlo and --mc-replay alike
    mc.obstacle_speed = obstacle_speed;
    if (monte_carlo > 0) {
      mc.runs = monte_carlo;
      mc.jobs = jobs;
      mc.progress = true;  // on stderr: progress and the time left
      const std::string json = sim::runMonteCarlo(scenario, mc);
      sim::writeText(out + "/monte_carlo.json", json);
      std::printf("%s", json.substr(0, json.find("\"per_run\"")).c_str());
      std::printf("  ...\n}\nwrote %s/monte_carlo.json\n", out.c_str());
      return 0;
    }
    if (replay >= 0) {  // one variant, drawn as runMonteCarlo draws it
      scenario = sim::randomVariant(scenario, mc, static_cast<std::uint64_t>(replay));
    }
    const sim::RunResult result = sim::runScenario(scenario, true);
    sim::writeTrajectoryCsv(out + "/trajectory.csv", result.rows);
    sim::writeText(out + "/metrics.json", sim::metricsJson(scenario, result));
    const sim::RunMetrics& m = result.summary.metrics;
    char ratio[32] = "- (no rho)";
    if (core::findLaw(scenario.setup.law)->has_rho_bound)
      std::snprintf(ratio, sizeof ratio, "%.3f", m.max_e_over_rho);
    const core::ControllerConfig& c = scenario.setup.controller;
    std::string beyond;  // the switches beyond the paper that are on
    for (const auto& [on, name] : {std::pair<bool, const char*>{c.paper.tangential_avoidance, "tangential"},
                                   {c.moving_obstacles, "moving_obstacles"},
                                   {c.predict_target, "predict_target"},
                                   {c.compensate_pose_age, "compensate_pose_age"}})
      if (on) beyond += std::string(", ") + name;
    std::printf("%s [%s, estimator %s, body_safe %s%s]: ASE %.5f AAE %.5f TEC %.4f max|e|/rho %s\n",
                scenario.name.c_str(), scenario.setup.law.c_str(),
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
  if (!no_plot) {
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
