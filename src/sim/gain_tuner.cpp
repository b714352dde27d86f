#include "amigobot_tracking/sim/gain_tuner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "amigobot_tracking/core/law/controller_config.h"
#include "amigobot_tracking/core/support/field_table.h"
#include "amigobot_tracking/sim/scenario.h"

namespace amigobot_tracking {
namespace sim {
namespace {

[[noreturn]] void fail(const std::string& file, int line, const std::string& why) {
  throw std::runtime_error(file + ":" + std::to_string(line) + ": " + why);
}

double number(const std::string& file, int line, const std::string& key, const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(value) || value < 0.0)
    fail(file, line, key + ": expected a number >= 0, got '" + text + "'");
  return value;
}

void setOption(const std::string& file, int line, const std::string& key, const std::string& text,
               MonteCarloOptions* o) {
  if (key == "obstacle_shift") {
    o->obstacle_shift = number(file, line, key, text);
  } else if (key == "pose_shift") {
    o->pose_shift = number(file, line, key, text);
  } else if (key == "heading_shift") {
    o->heading_shift = number(file, line, key, text);
  } else if (key == "noise") {
    o->noise_std_max = number(file, line, key, text);
  } else if (key == "obstacle_speed") {
    o->obstacle_speed = number(file, line, key, text);
  } else if (key == "sample_periods") {
    o->sample_periods.clear();
    std::stringstream list(text);
    for (std::string item; std::getline(list, item, ',');) {
      const double period = number(file, line, key, item);
      if (period <= 0.0) fail(file, line, key + ": a period must be > 0, got '" + item + "'");
      o->sample_periods.push_back(period);
    }
  } else {
    fail(file, line, "unknown key '" + key +
                         "' (known: obstacle_shift, pose_shift, heading_shift, noise, sample_periods, obstacle_speed)");
  }
}

// The controller's current value of a tuned gain.
double gainOf(const core::ControllerConfig& c, const std::string& key) {
  const core::Field<core::ControllerConfig>* f = core::findField(core::controllerFields(), key);
  return std::get<double>(f->get(c));
}

struct Loaded {
  Scenario scenario;
  MonteCarloOptions variants;
};

Evaluation evaluate(const std::vector<Loaded>& suite, const std::map<std::string, double>& gains,
                    const TunerOptions& options, const std::vector<double>& reference_ase) {
  Evaluation e;
  e.gains = gains;
  e.feasible = true;
  double sum = 0.0;
  for (const Loaded& entry : suite) {
    Scenario s = entry.scenario;
    for (const auto& [key, value] : gains) {
      const std::string why = core::setField(core::controllerFields(), key, core::formatValue(value), &s.setup.controller);
      if (!why.empty()) throw std::runtime_error(s.file + ": tuned gain " + why);
    }
    MonteCarloOptions mc = entry.variants;
    mc.runs = options.runs;
    mc.seed = options.seed;
    mc.jobs = options.jobs;
    mc.progress = false;
    std::string violation;
    MonteCarloSummary m;
    try {
      checkScenario(s);
      m = summarizeMonteCarlo(s, mc);
    } catch (const std::exception& err) {
      violation = err.what();  // e.g. the start is outside rho(0) with these gains
    }
    if (violation.empty()) {
      const std::uint64_t contacts = m.body_collision_episodes + m.offset_collision_episodes;
      if (contacts > 0) violation = std::to_string(contacts) + " contacts";
      else if (m.diamond_violations > 0) violation = std::to_string(m.diamond_violations) + " diamond violations";
      else if (m.envelope_widenings > 0) violation = std::to_string(m.envelope_widenings) + " widenings";
      else if (m.runs_with_nan > 0) violation = std::to_string(m.runs_with_nan) + " runs with NaN";
      else if (m.worst_orbit_turns >= 1.0) violation = "an orbit of " + std::to_string(m.worst_orbit_turns) + " turns";
      else if (m.worst_side_flips > 4) violation = std::to_string(m.worst_side_flips) + " side flips";
    }
    if (!violation.empty() && e.feasible) {
      e.feasible = false;
      e.violation = s.name + ": " + violation;
    }
    e.mean_true_ase.push_back(m.mean_true_ase);  // 0 when the batch could not run
    const std::size_t i = e.mean_true_ase.size() - 1;
    const double ref = reference_ase.empty() ? e.mean_true_ase[i] : reference_ase[i];
    sum += e.mean_true_ase[i] / std::max(ref, 1e-9);
  }
  e.objective = sum / static_cast<double>(suite.size());
  return e;
}

// Strictly better: feasible beats infeasible, then the lower objective.
bool better(const Evaluation& a, const Evaluation& b) {
  if (a.feasible != b.feasible) return a.feasible;
  return a.objective < b.objective - 1e-9;
}

std::string describe(const std::map<std::string, double>& gains) {
  std::string out;
  char buf[64];
  for (const auto& [key, value] : gains) {
    std::snprintf(buf, sizeof buf, "%s%s=%.4g", out.empty() ? "" : " ", key.c_str(), value);
    out += buf;
  }
  return out;
}

}  // namespace

TuningSuite parseTuningSuite(const std::string& text, const std::string& file) {
  TuningSuite suite;
  suite.file = file;
  const std::filesystem::path base = std::filesystem::path(file).parent_path();
  std::stringstream lines(text);
  int number_of_line = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number_of_line;
    line = line.substr(0, line.find('#'));
    std::stringstream words(line);
    std::string word;
    if (!(words >> word)) continue;
    TuningEntry entry;
    entry.line = number_of_line;
    entry.scenario = std::filesystem::path(word).is_absolute() ? word : (base / word).string();
    while (words >> word) {
      const std::size_t eq = word.find('=');
      if (eq == std::string::npos || eq == 0) fail(file, number_of_line, "expected key=value, got '" + word + "'");
      setOption(file, number_of_line, word.substr(0, eq), word.substr(eq + 1), &entry.variants);
    }
    suite.entries.push_back(entry);
  }
  if (suite.entries.empty()) throw std::runtime_error(file + ": no scenario in the suite");
  return suite;
}

TuningSuite loadTuningSuite(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read the suite file");
  std::stringstream text;
  text << in.rdbuf();
  return parseTuningSuite(text.str(), path);
}

std::vector<TunedGain> recommendedLawGains() {
  return {{"k_d", 0.05, 0.6}, {"lambda", 0.1, 2.0}, {"k_r", 0.1, 2.0}, {"barrier_rate", 0.5, 8.0},
          {"field_margin", 0.03, 0.4}};
}

TuningResult tuneGains(const TuningSuite& suite, const TunerOptions& options) {
  if (!(options.step > 1.0)) throw std::runtime_error("tune: step must be > 1");
  if (options.max_evaluations < 1) throw std::runtime_error("tune: max_evaluations must be >= 1");
  for (const TunedGain& g : options.gains) {
    const core::Field<core::ControllerConfig>* f = core::findField(core::controllerFields(), g.key);
    if (!f || f->type != core::FieldType::kReal) throw std::runtime_error("tune: '" + g.key + "' is no real controller gain");
    if (!(g.min > 0.0 && g.min < g.max)) throw std::runtime_error("tune: " + g.key + ": needs 0 < min < max");
  }
  const auto started = std::chrono::steady_clock::now();
  std::vector<Loaded> loaded;
  for (const TuningEntry& entry : suite.entries) {
    try {
      loaded.push_back({loadScenario(entry.scenario, options.overrides), entry.variants});
    } catch (const std::exception& e) {
      throw std::runtime_error(suite.file + ":" + std::to_string(entry.line) + ": " + e.what());
    }
  }
  std::map<std::string, double> x;  // the start: the first scenario's gains, clamped to the ranges
  for (const TunedGain& g : options.gains)
    x[g.key] = std::clamp(gainOf(loaded.front().scenario.setup.controller, g.key), g.min, g.max);

  TuningResult result;
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
  auto report = [&](const Evaluation& e) {
    if (!options.progress) return;
    const double per = elapsed() / result.evaluations;
    std::fprintf(stderr, "tune: %d/%d %s: objective %.4f %s; best %.4f; about %.0f s left\n", result.evaluations,
                 options.max_evaluations, describe(e.gains).c_str(), e.objective,
                 e.feasible ? "feasible" : ("infeasible (" + e.violation + ")").c_str(), result.best.objective,
                 per * (options.max_evaluations - result.evaluations));
  };
  result.start = evaluate(loaded, x, options, {});
  std::vector<double> reference = result.start.mean_true_ase;
  result.start.objective = 1.0;
  result.best = result.start;
  result.evaluations = 1;
  report(result.start);
  double step = options.step;
  while (result.evaluations < options.max_evaluations && step > 1.01) {
    bool improved = false;
    for (const TunedGain& g : options.gains) {
      for (const double factor : {step, 1.0 / step}) {
        if (result.evaluations >= options.max_evaluations) break;
        std::map<std::string, double> candidate = result.best.gains;
        const double value = std::clamp(candidate[g.key] * factor, g.min, g.max);
        if (std::abs(value - candidate[g.key]) < 1e-12) continue;  // at its bound
        candidate[g.key] = value;
        Evaluation e = evaluate(loaded, candidate, options, reference);
        ++result.evaluations;
        if (better(e, result.best)) {
          result.best = e;
          improved = true;
        }
        report(e);
        if (improved) break;  // keep going in this gain's good direction from the new point
      }
    }
    if (!improved) step = std::sqrt(step);
  }
  result.wall_time = elapsed();
  return result;
}

std::string tunedGainsYaml(const TuningResult& result, const TuningSuite& suite, const TunerOptions& options) {
  std::ostringstream out;
  char buf[256];
  out << "# Controller gains from `amigobot_sim --tune " << suite.file << "` (sim/gain_tuner.h): a pattern search\n";
  std::snprintf(buf, sizeof buf, "# over %zu scenarios x %d Monte Carlo variants (seed %llu), %d candidates in %.0f s.\n",
                suite.entries.size(), options.runs, static_cast<unsigned long long>(options.seed), result.evaluations,
                result.wall_time);
  out << buf;
  std::snprintf(buf, sizeof buf, "# Objective, mean true ASE relative to the start (lower is better): 1 -> %.4f.\n",
                result.best.objective);
  out << buf;
  out << "# Hard constraints (0 contacts, 0 diamond violations, 0 widenings, 0 NaN, < 1 orbit turn, <= 4 side flips): "
      << (result.best.feasible ? "met" : "NOT met: " + result.best.violation) << ".\n";
  if (!result.start.feasible) out << "# The start broke them: " << result.start.violation << ".\n";
  out << "# Load after config/controller_experiment.yaml, in the tracking nodelet's namespace.\n";
  for (const auto& [key, value] : result.best.gains) {
    const core::Field<core::ControllerConfig>* f = core::findField(core::controllerFields(), key);
    const std::string row = key + ": " + core::formatValue(value);
    // The meaning is appended whole: a row's meaning can outgrow buf (a cut line ran into the next key).
    std::snprintf(buf, sizeof buf, "%-28s # double, %s, tuned (start %.4g): ", row.c_str(), f->unit.c_str(),
                  result.start.gains.at(key));
    out << buf << f->meaning << "\n";
  }
  return out.str();
}

}  // namespace sim
}  // namespace amigobot_tracking
