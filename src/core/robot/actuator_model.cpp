#include "amigobot_tracking/core/robot/actuator_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "amigobot_tracking/core/robot/unicycle.h"

namespace amigobot_tracking {
namespace core {
namespace {

constexpr double kTimeEps = 1e-9;  // [s] events this close count as simultaneous

// Moves x toward `target` for `duration` seconds: at `up` while |x| grows, at `down` while it
// shrinks (a reversal passes through zero). Adds the integral of x over the time to *area.
double rampAxis(double x, double target, double up, double down, double duration, double* area) {
  while (duration > 0.0) {
    if (x == target) {
      *area += x * duration;
      return x;
    }
    const bool reversing = x * target < 0.0;
    const double goal = reversing ? 0.0 : target;
    const double rate = (reversing || std::abs(target) < std::abs(x)) ? down : up;
    const double to_goal = std::abs(goal - x) / rate;  // 0 for an infinite rate
    if (to_goal >= duration) {
      const double end = x + (goal > x ? rate : -rate) * duration;
      *area += 0.5 * (x + end) * duration;
      return end;
    }
    *area += 0.5 * (x + goal) * to_goal;
    duration -= to_goal;
    x = goal;
  }
  return x;
}

// Scales (v, w) by one factor into |v| + b |w| <= limit.
Twist2 intoWheelLimit(Twist2 u, double limit, double half_track) {
  const double wheel = std::abs(u.v) + half_track * std::abs(u.omega);
  if (wheel > limit) {
    const double s = limit / wheel;
    u.v *= s;
    u.omega *= s;
  }
  return u;
}

}  // namespace

std::string validateActuatorLimits(const ActuatorLimits& l, double half_track) {
  std::ostringstream err;
  auto rate = [&](const char* name, double value) {
    if (!(value > 0.0)) err << (err.tellp() > 0 ? "; " : "") << name << ": must be > 0 (inf = no limit), got " << value;
  };
  auto time = [&](const char* name, double value) {
    if (!(value >= 0.0 && std::isfinite(value)))
      err << (err.tellp() > 0 ? "; " : "") << name << ": must be >= 0 and finite [s], got " << value;
  };
  rate("trans_accel", l.trans_accel);
  rate("trans_decel", l.trans_decel);
  rate("rot_accel", l.rot_accel);
  rate("rot_decel", l.rot_decel);
  rate("max_velocity", l.max_velocity);
  rate("max_rot_velocity", l.max_rot_velocity);
  time("cycle", l.cycle);
  time("latency", l.latency);
  if (!(half_track > 0.0 && std::isfinite(half_track)))
    err << (err.tellp() > 0 ? "; " : "") << "half_track: must be > 0 and finite [m], got " << half_track;
  return err.str();
}

Twist2 clipToLimits(const Twist2& command, const ActuatorLimits& limits, double half_track) {
  Twist2 u{std::clamp(command.v, -limits.max_velocity, limits.max_velocity),
           std::clamp(command.omega, -limits.max_rot_velocity, limits.max_rot_velocity)};
  return intoWheelLimit(u, limits.max_velocity, half_track);
}

ActuatorModel::ActuatorModel(const ActuatorLimits& limits, double half_track) : half_track_(half_track) {
  setLimits(limits);
}

void ActuatorModel::setLimits(const ActuatorLimits& limits) {
  const std::string error = validateActuatorLimits(limits, half_track_);
  if (!error.empty()) throw std::invalid_argument("actuator model: " + error);
  limits_ = limits;
}

void ActuatorModel::sample(double at) {
  // The newest command that has waited out the latency wins; older ones are dropped.
  for (size_t i = arrivals_.size(); i-- > 0;) {
    if (arrivals_[i].time + limits_.latency <= at + kTimeEps) {
      setpoint_ = clipToLimits(arrivals_[i].command, limits_, half_track_);
      arrivals_.erase(arrivals_.begin(), arrivals_.begin() + static_cast<long>(i));
      return;
    }
  }
}

double ActuatorModel::nextEvent(double after) const {
  if (limits_.cycle > 0.0) return static_cast<double>(next_tick_) * limits_.cycle;
  double next = std::numeric_limits<double>::infinity();
  for (const Arrival& a : arrivals_)
    if (a.time + limits_.latency > after + kTimeEps) next = std::min(next, a.time + limits_.latency);
  return next;
}

void ActuatorModel::ramp(double duration, Twist2* area) {
  velocity_.v = rampAxis(velocity_.v, setpoint_.v, limits_.trans_accel, limits_.trans_decel, duration, &area->v);
  velocity_.omega =
      rampAxis(velocity_.omega, setpoint_.omega, limits_.rot_accel, limits_.rot_decel, duration, &area->omega);
  // Both setpoints lie inside the wheel limit, but the two ramps' path between them may not.
  velocity_ = intoWheelLimit(velocity_, limits_.max_velocity, half_track_);
}

Twist2 ActuatorModel::step(const Twist2& command, double dt) {
  if (!(dt >= 0.0 && std::isfinite(dt)))
    throw std::invalid_argument("actuator model: step: dt must be >= 0 and finite, got " + std::to_string(dt));
  if (!command.isFinite()) throw std::invalid_argument("actuator model: step: a non-finite command");
  if (arrivals_.empty() || arrivals_.back().command.v != command.v || arrivals_.back().command.omega != command.omega)
    arrivals_.push_back({time_, command});
  const double end = time_ + dt;
  Twist2 area;
  double t = time_;
  for (;;) {
    if (limits_.cycle > 0.0) {
      // Ticks by index: no drift over a long run.
      while (static_cast<double>(next_tick_) * limits_.cycle <= t + kTimeEps) {
        sample(static_cast<double>(next_tick_) * limits_.cycle);
        ++next_tick_;
      }
    } else {
      sample(t);
    }
    const double next = std::min(end, nextEvent(t));
    if (next > t) ramp(next - t, &area);
    t = std::max(t, next);
    if (t >= end - kTimeEps) break;
  }
  time_ = end;
  if (dt <= 0.0) return velocity_;
  return {area.v / dt, area.omega / dt};
}

Pose2 driveBody(ActuatorModel* model, const Pose2& pose, const Twist2& command, double duration, double substep) {
  const auto pieces = static_cast<long>(std::max(1.0, std::ceil(duration / substep - 1e-9)));
  const double h = duration / static_cast<double>(pieces);
  Pose2 p = pose;
  for (long i = 0; i < pieces; ++i) p = integrateUnicycle(p, model->step(command, h), h);
  return p;
}

}  // namespace core
}  // namespace amigobot_tracking
