#include "amigobot_tracking/sim/monte_carlo.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <atomic>
#include <cstdio>
#include <exception>
#include <mutex>
#include <random>
#include <thread>

#include "amigobot_tracking/core/law/avoidance.h"
#include "amigobot_tracking/core/robot/offset_point.h"
#include "amigobot_tracking/sim/simulator.h"

namespace amigobot_tracking {
namespace sim {
namespace {

Eigen::Vector2d inDisk(std::mt19937_64& rng, double radius) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double r = radius * std::sqrt(unit(rng)), a = 2.0 * M_PI * unit(rng);
  return {r * std::cos(a), r * std::sin(a)};
}

bool acceptable(const Scenario& s) {
  const sim::ClosedLoopSetup& setup = s.setup;
  const core::ControllerConfig& c = setup.controller;
  const Eigen::Vector2d p_r = core::offsetPoint(setup.initial_pose, c.offset);
  const Eigen::Vector2d p_d = s.makeReference()->at(0.0).position;
  if ((p_d - p_r).norm() >= c.max_error_ratio * c.rho_0) return false;
  return core::clearance(p_r, c.effectiveRadius() + c.delta, setup.obstacles) > 0.0 &&
         core::clearance(setup.initial_pose.position(), c.robot_radius, setup.obstacles) > 0.0;
}

struct VariantResult {
  core::Pose2 initial_pose;
  RunResult result;
};

// Every variant, on options.jobs threads (each takes the next index; results by index, so
// the summary is the same for any number of jobs), with progress on stderr when asked.
std::vector<VariantResult> runVariants(const Scenario& base, const MonteCarloOptions& options) {
  const int runs = std::max(0, options.runs);
  std::vector<VariantResult> results(runs);
  std::atomic<int> next{0}, done{0};
  std::mutex print;
  const auto start = std::chrono::steady_clock::now();
  std::exception_ptr failure;  // the first run that threw (a peer's error): the batch fails with it
  auto worker = [&] {
    for (int i = next++; i < runs; i = next++) {
      const Scenario s = randomVariant(base, options, static_cast<std::uint64_t>(i));
      try {
        results[i] = {s.setup.initial_pose, runScenario(s, false)};
      } catch (...) {
        std::lock_guard<std::mutex> lock(print);
        if (!failure) failure = std::current_exception();
        next = runs;  // the others stop at their next run
        return;
      }
      const int finished = ++done;
      if (!options.progress) continue;
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::lock_guard<std::mutex> lock(print);
      std::fprintf(stderr, "\r%s [%s]: %d/%d runs, %.0f s elapsed, about %.0f s left   ", base.name.c_str(),
                   base.setup.law.c_str(), finished, runs, elapsed, elapsed / finished * (runs - finished));
      if (finished == runs) std::fputc('\n', stderr);
    }
  };
  const int jobs = std::max(1, std::min(options.jobs, runs));
  std::vector<std::thread> threads;
  for (int j = 1; j < jobs; ++j) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
  return results;
}

}  // namespace

double encounterTime(const core::Disk& obstacle, const Eigen::Vector2d& velocity, const core::Reference& reference,
                     double duration) {
  double best_t = 0.0, best = std::numeric_limits<double>::infinity();
  const int n = static_cast<int>(std::ceil(duration / 0.01));
  for (int k = 0; k <= n; ++k) {
    const double t = std::min(duration, 0.01 * k);
    const double d = (obstacle.center + velocity * t - reference.at(t).position).norm();
    if (d < best) best = d, best_t = t;
  }
  return best_t;
}

Scenario randomVariant(const Scenario& base, const MonteCarloOptions& options, std::uint64_t index) {
  std::mt19937_64 rng(options.seed * 1000003ULL + index);
  std::uniform_real_distribution<double> heading(-options.heading_shift, options.heading_shift);
  std::uniform_real_distribution<double> speed(0.0, options.obstacle_speed);
  // Re-timed: the obstacles at a constant velocity (a scenario's `velocity`); a motion of legs
  // keeps its timing and only shifts.
  const size_t count = base.setup.obstacle_motions.size();
  std::vector<Eigen::Vector2d> velocity(count, Eigen::Vector2d::Zero());
  std::vector<bool> retime(count, false);
  std::vector<double> encounter(count, 0.0);
  if (options.obstacle_speed > 0.0) {
    const auto reference = base.makeReference();
    for (size_t j = 0; j < count; ++j) {
      retime[j] = isConstantMotion(base.setup.obstacle_motions[j], &velocity[j]) && !velocity[j].isZero(0.0);
      if (retime[j])
        encounter[j] = encounterTime(base.setup.obstacles[j], velocity[j], *reference, base.setup.duration);
    }
  }
  for (int attempt = 0; attempt < 100; ++attempt) {
    Scenario s = base;
    for (size_t j = 0; j < s.setup.obstacles.size(); ++j) {
      core::Disk& d = s.setup.obstacles[j];
      d.center += inDisk(rng, options.obstacle_shift);
      if (j >= count) continue;
      core::ObstacleMotion& motion = s.setup.obstacle_motions[j];
      if (retime[j]) {
        const Eigen::Vector2d meet = d.center + velocity[j] * encounter[j];
        const Eigen::Vector2d v = velocity[j].normalized() * speed(rng);
        d.center = meet - v * encounter[j];
        motion = constantMotion(d.center, v);
      }
      motion.start = d.center;
    }
    const Eigen::Vector2d shift = inDisk(rng, options.pose_shift);
    s.setup.initial_pose.x += shift.x();
    s.setup.initial_pose.y += shift.y();
    s.setup.initial_pose.theta = core::wrapAngle(s.setup.initial_pose.theta + heading(rng));
    s.setup.sensor.seed = base.setup.sensor.seed + index + 1;
    if (options.noise_std_max > 0.0)
      s.setup.sensor.noise_std = std::uniform_real_distribution<double>(0.0, options.noise_std_max)(rng);
    if (!options.sample_periods.empty())
      s.setup.sample_period = options.sample_periods[std::uniform_int_distribution<size_t>(
          0, options.sample_periods.size() - 1)(rng)];
    if (acceptable(s)) return s;
  }
  return base;
}

void to_json(Json& j, const MonteCarloRun& r) {
  j["index"] = r.index;
  j["initial_pose"] = {jsonNumber(r.initial_pose.x), jsonNumber(r.initial_pose.y), jsonNumber(r.initial_pose.theta)};
  j.update(pick(r.metrics, {"ase", "true_ase", "max_true_error", "longest_stall_s", "aae", "max_e_over_rho",
                            "min_clearance_offset", "min_clearance_body", "body_collisions", "offset_collisions",
                            "diamond_violations", "nan_count", "true_ise", "envelope_widenings", "stall_time_s",
                            "max_orbit_turns", "escape_toggles", "avoidance_toggles", "side_flips", "max_delta_v",
                            "max_delta_omega", "omega_reversals_per_minute"}));
}

MonteCarloSummary summarizeMonteCarlo(const Scenario& base, const MonteCarloOptions& options) {
  MonteCarloSummary sum;
  sum.scenario = base.file;
  sum.options = options;
  sum.variant = base.setup.law;
  sum.body_safe = base.setup.controller.body_safe;
  sum.tangential_avoidance = base.setup.controller.paper.tangential_avoidance;
  sum.moving_obstacles = base.setup.controller.moving_obstacles;
  double sum_ase = 0.0, sum_aae = 0.0, sum_true_ase = 0.0, sum_true_ise = 0.0;
  const std::vector<VariantResult> results = runVariants(base, options);
  for (int i = 0; i < options.runs; ++i) {
    const RunResult& r = results[i].result;
    const sim::RunMetrics& m = r.summary.metrics;
    sum.runs_with_body_collision += m.body_collisions > 0;
    sum.body_collision_episodes += m.body_collisions;
    sum.offset_collision_episodes += m.offset_collisions;
    sum_true_ase += m.true_ase;
    sum.runs_with_long_stall += m.longest_stall > 0.5;
    sum.worst_stall = std::max(sum.worst_stall, m.longest_stall);
    sum.worst_true_ase = std::max(sum.worst_true_ase, m.true_ase);
    sum.worst_true_ise = std::max(sum.worst_true_ise, m.true_ise);
    sum_true_ise += m.true_ise;
    sum.worst_orbit_turns = std::max(sum.worst_orbit_turns, m.max_orbit_turns);
    sum.worst_escape_toggles = std::max(sum.worst_escape_toggles, m.escape_toggles);
    sum.worst_avoidance_toggles = std::max(sum.worst_avoidance_toggles, m.avoidance_toggles);
    sum.worst_side_flips = std::max(sum.worst_side_flips, m.side_flips);
    sum.worst_max_delta_v = std::max(sum.worst_max_delta_v, m.max_delta_v);
    sum.worst_max_delta_omega = std::max(sum.worst_max_delta_omega, m.max_delta_omega);
    sum.worst_omega_reversals_per_minute = std::max(sum.worst_omega_reversals_per_minute, m.omega_reversals_per_minute);
    sum.mean_omega_reversals_per_minute += m.omega_reversals_per_minute;
    sum.diamond_violations += m.diamond_violations;
    sum.nan_steps += m.nan_count;
    sum.runs_with_offset_collision += m.offset_collisions > 0;
    sum.runs_with_diamond_violation += m.diamond_violations > 0;
    sum.runs_with_nan += m.nan_count > 0;
    sum.runs_with_e_over_rho_ge_1 += m.max_e_over_rho >= 1.0;
    sum.envelope_widenings += m.envelope_widenings;
    sum.runs_with_envelope_widening += m.envelope_widenings > 0;
    sum.worst_min_clearance_body = std::min(sum.worst_min_clearance_body, m.min_clearance_body);
    sum.worst_min_clearance_offset = std::min(sum.worst_min_clearance_offset, m.min_clearance_offset);
    sum.worst_max_e_over_rho = std::max(sum.worst_max_e_over_rho, m.max_e_over_rho);
    sum.sim_time += m.sim_time;
    sum.wall_time += r.wall_time;
    sum_ase += m.ase;
    sum_aae += m.aae;
    sum.per_run.push_back({i, results[i].initial_pose, m});
  }
  const double n = std::max(1, options.runs);
  sum.mean_ase = sum_ase / n;
  sum.mean_aae = sum_aae / n;
  sum.mean_true_ase = sum_true_ase / n;
  sum.mean_true_ise = sum_true_ise / n;
  sum.mean_omega_reversals_per_minute /= n;
  return sum;
}

void to_json(Json& j, const MonteCarloSummary& s) {
  j = Json{{"scenario", s.scenario},
           {"runs", s.options.runs},
           {"seed", s.options.seed},
           {"variant", s.variant},
           {"body_safe", s.body_safe},
           {"obstacle_shift", jsonNumber(s.options.obstacle_shift)},
           {"pose_shift", jsonNumber(s.options.pose_shift)},
           {"heading_shift", jsonNumber(s.options.heading_shift)},
           {"obstacle_speed", jsonNumber(s.options.obstacle_speed)},
           {"noise_std_max", jsonNumber(s.options.noise_std_max)},
           {"sample_periods", s.options.sample_periods},
           {"tangential_avoidance", s.tangential_avoidance},
           {"moving_obstacles", s.moving_obstacles},
           {"body_collision_episodes", s.body_collision_episodes},
           {"offset_collision_episodes", s.offset_collision_episodes},
           {"runs_with_stall_over_0_5s", s.runs_with_long_stall},
           {"worst_stall_s", jsonNumber(s.worst_stall)},
           {"runs_with_body_collision", s.runs_with_body_collision},
           {"runs_with_offset_collision", s.runs_with_offset_collision},
           {"runs_with_diamond_violation", s.runs_with_diamond_violation},
           {"runs_with_nan", s.runs_with_nan},
           {"runs_with_e_over_rho_ge_1", s.runs_with_e_over_rho_ge_1},
           {"envelope_widenings", s.envelope_widenings},
           {"runs_with_envelope_widening", s.runs_with_envelope_widening},
           {"worst_min_clearance_body", jsonNumber(s.worst_min_clearance_body)},
           {"worst_min_clearance_offset", jsonNumber(s.worst_min_clearance_offset)},
           {"worst_max_e_over_rho", jsonNumber(s.worst_max_e_over_rho)},
           {"mean_ase", jsonNumber(s.mean_ase)},
           {"mean_aae", jsonNumber(s.mean_aae)},
           {"mean_true_ase", jsonNumber(s.mean_true_ase)},
           {"worst_true_ase", jsonNumber(s.worst_true_ase)},
           {"mean_true_ise", jsonNumber(s.mean_true_ise)},
           {"worst_true_ise", jsonNumber(s.worst_true_ise)},
           {"worst_orbit_turns", jsonNumber(s.worst_orbit_turns)},
           {"worst_escape_toggles", s.worst_escape_toggles},
           {"worst_avoidance_toggles", s.worst_avoidance_toggles},
           {"worst_side_flips", s.worst_side_flips},
           {"worst_max_delta_v", jsonNumber(s.worst_max_delta_v)},
           {"worst_max_delta_omega", jsonNumber(s.worst_max_delta_omega)},
           {"mean_omega_reversals_per_minute", jsonNumber(s.mean_omega_reversals_per_minute)},
           {"worst_omega_reversals_per_minute", jsonNumber(s.worst_omega_reversals_per_minute)},
           {"diamond_violations", s.diamond_violations},
           {"nan_steps", s.nan_steps},
           {"sim_time_s", jsonNumber(s.sim_time)},
           {"wall_time_s", jsonNumber(s.wall_time)},
           {"realtime_factor", jsonNumber(s.wall_time > 0.0 ? s.sim_time / s.wall_time : 0.0)},
           {"per_run", s.per_run}};
}

std::string runMonteCarlo(const Scenario& base, const MonteCarloOptions& options) {
  return dumpJson(summarizeMonteCarlo(base, options));
}

}  // namespace sim
}  // namespace amigobot_tracking
