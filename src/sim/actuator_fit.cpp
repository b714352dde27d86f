#include "amigobot_tracking/sim/actuator_fit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "amigobot_tracking/core/support/input_file.h"

namespace amigobot_tracking {
namespace sim {
namespace {

constexpr double kLatencyStep = 0.002;  // [s] fine latency grid
constexpr double kCoarseLatencyStep = 0.01;  // [s]
constexpr double kLatencyMax = 0.5;     // [s]

// The parameters searched, as (pointer into the limits, lower, upper, logarithmic).
struct Knob {
  double core::ActuatorLimits::*field;
  double low, high;
  bool log;
};

// Mean squared error of v and b w between the model's replay and the odometry.
double replayError(const ActuatorRecording& r, const core::ActuatorLimits& limits, double phase) {
  core::ActuatorModel model(limits, r.half_track);
  // The model's ticks fall at start + k cycle; the recording's clock starts `phase` after one.
  const double start = std::min(r.commands.front().t, r.odometry.front().t) - phase;
  double now = start;
  size_t next_command = 0;
  core::Twist2 command;
  double sum = 0.0;
  for (const TimedTwist& o : r.odometry) {
    while (next_command < r.commands.size() && r.commands[next_command].t <= o.t) {
      model.step(command, r.commands[next_command].t - now);
      now = r.commands[next_command].t;
      command = r.commands[next_command++].u;
    }
    model.step(command, o.t - now);
    now = o.t;
    const double dv = model.velocity().v - o.u.v, dw = r.half_track * (model.velocity().omega - o.u.omega);
    sum += dv * dv + dw * dw;
  }
  return sum / static_cast<double>(r.odometry.size());
}

// Golden-section search of f on [low, high] (in log space when asked).
double goldenSection(const std::function<double(double)>& f, double low, double high, bool log) {
  auto to = [&](double x) { return log ? std::exp(x) : x; };
  double a = log ? std::log(low) : low, b = log ? std::log(high) : high;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = f(to(c)), fd = f(to(d));
  for (int i = 0; i < 30; ++i) {  // the bracket shrinks to 1e-6 of itself
    if (fc < fd) {
      b = d, d = c, fd = fc;
      c = b - g * (b - a), fc = f(to(c));
    } else {
      a = c, c = d, fc = fd;
      d = a + g * (b - a), fd = f(to(d));
    }
  }
  return to(0.5 * (a + b));
}

void checkStream(const std::vector<TimedTwist>& s, const char* name, size_t least) {
  if (s.size() < least)
    throw std::invalid_argument(std::string("identify: ") + name + ": " + std::to_string(s.size()) +
                                " samples, need at least " + std::to_string(least));
  for (size_t i = 0; i < s.size(); ++i) {
    if (!std::isfinite(s[i].t) || !s[i].u.isFinite())
      throw std::invalid_argument(std::string("identify: ") + name + ": sample " + std::to_string(i) + " is not finite");
    if (i > 0 && s[i].t < s[i - 1].t)
      throw std::invalid_argument(std::string("identify: ") + name + ": time goes back at sample " + std::to_string(i));
  }
}

}  // namespace

ActuatorFit fitActuator(const ActuatorRecording& r) {
  checkStream(r.commands, "commands", 2);
  checkStream(r.odometry, "odometry", 20);
  if (!(r.half_track > 0.0 && std::isfinite(r.half_track))) throw std::invalid_argument("identify: half_track must be > 0");
  ActuatorFit fit;
  core::ActuatorLimits& l = fit.dynamics.limits;
  fit.dynamics.ideal = false;
  fit.dynamics.half_track = r.half_track;
  // The cycle: the odometry's median period (one report per firmware cycle).
  std::vector<double> periods;
  for (size_t i = 1; i < r.odometry.size(); ++i) periods.push_back(r.odometry[i].t - r.odometry[i - 1].t);
  std::nth_element(periods.begin(), periods.begin() + periods.size() / 2, periods.end());
  l.cycle = std::max(0.0, periods[periods.size() / 2]);
  for (const TimedTwist& o : r.odometry)
    fit.largest_wheel_speed = std::max(fit.largest_wheel_speed, std::abs(o.u.v) + r.half_track * std::abs(o.u.omega));
  double largest_command = 0.0;
  for (const TimedTwist& c : r.commands)
    largest_command = std::max(largest_command, std::abs(c.u.v) + r.half_track * std::abs(c.u.omega));
  // The limit shows only where the commands asked for more than the wheels gave.
  fit.wheel_limit_seen = largest_command > 1.05 * fit.largest_wheel_speed;
  if (fit.wheel_limit_seen) l.max_velocity = fit.largest_wheel_speed;
  else fit.notes.push_back("the run never reached the wheel-speed limit: max_velocity kept at the default");
  l.max_rot_velocity = 1e3;  // the body ceiling is not told apart from the wheel limit here

  std::vector<Knob> knobs = {{&core::ActuatorLimits::trans_accel, 0.02, 20.0, true},
                             {&core::ActuatorLimits::trans_decel, 0.02, 20.0, true},
                             {&core::ActuatorLimits::rot_accel, 0.05, 50.0, true},
                             {&core::ActuatorLimits::rot_decel, 0.05, 50.0, true}};
  if (fit.wheel_limit_seen)
    knobs.push_back({&core::ActuatorLimits::max_velocity, 0.5 * fit.largest_wheel_speed, 1.5 * fit.largest_wheel_speed, false});
  // The firmware reports once per cycle, at its ticks: the odometry's stamps give the phase
  // (a constant reporting delay then shows in the latency).
  const double first = std::min(r.commands.front().t, r.odometry.front().t);
  const double phase = l.cycle > 0.0 ? first - (r.odometry.front().t - std::ceil((r.odometry.front().t - first) / l.cycle) * l.cycle) : 0.0;
  // The rates for a given latency: coordinate descent, a golden-section search per rate.
  auto fitRates = [&](core::ActuatorLimits* limits, int rounds) {
    for (int round = 0; round < rounds; ++round)
      for (const Knob& k : knobs)
        limits->*k.field = goldenSection(
            [&](double x) {
              core::ActuatorLimits trial = *limits;
              trial.*k.field = x;
              return replayError(r, trial, phase);
            },
            k.low, k.high, k.log);
    return replayError(r, *limits, phase);
  };
  // The latency: the error is flat between ticks and the rates trade against it (a slower
  // ramp looks like a later one), so every latency of a coarse grid gets its own rates, then
  // a fine grid round the best.
  double best = std::numeric_limits<double>::infinity();
  core::ActuatorLimits best_limits = l;
  auto tryLatency = [&](const core::ActuatorLimits& from, double latency, int rounds) {
    core::ActuatorLimits trial = from;
    trial.latency = latency;
    const double e = fitRates(&trial, rounds);
    if (e < best) best = e, best_limits = trial;
  };
  for (double latency = 0.0; latency <= kLatencyMax + 1e-9; latency += kCoarseLatencyStep) tryLatency(l, latency, 2);
  const core::ActuatorLimits coarse = best_limits;
  for (double latency = std::max(0.0, coarse.latency - kCoarseLatencyStep);
       latency <= coarse.latency + kCoarseLatencyStep + 1e-9; latency += kLatencyStep)
    tryLatency(coarse, latency, 2);
  l = best_limits;
  l.max_rot_velocity = core::ActuatorLimits{}.max_rot_velocity;
  fit.rms_error = std::sqrt(replayError(r, l, phase));
  return fit;
}

ActuatorRecording readActuatorCsv(const std::string& path) {
  std::istringstream in(core::readInputFile(path, 256u << 20));
  ActuatorRecording r;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream words(line);
    std::string kind;
    TimedTwist s;
    if (!(words >> kind >> s.t >> s.u.v >> s.u.omega) || (kind != "cmd" && kind != "odom"))
      throw std::runtime_error(path + ":" + std::to_string(number) + ": expected cmd|odom,t,v,w");
    (kind == "cmd" ? r.commands : r.odometry).push_back(s);
  }
  return r;
}

}  // namespace sim
}  // namespace amigobot_tracking
