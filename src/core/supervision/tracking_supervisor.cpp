#include "amigobot_tracking/core/supervision/tracking_supervisor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace amigobot_tracking {
namespace core {
namespace {

// `age` within `timeout`; NaN is not.
bool fresh(double age, double timeout) { return age <= timeout; }

}  // namespace

bool TrackingSupervisor::enable(bool ramp) {
  if (enabled_) return false;
  enabled_ = true;
  lost_ = false;
  ramping_ = ramp;
  last_command_ = {};
  return true;
}

Twist2 TrackingSupervisor::disable(double t) {
  enabled_ = false;
  return stop(t, State::kDisabled, "disabled");
}

std::string TrackingSupervisor::staleReason(double t, const SupervisorInputs& in) const {
  if (!std::isfinite(t)) return "time is not finite";
  if (!in.have_pose) return "no robot pose " + config_.pose_link + (in.pose_problem.empty() ? "" : ": " + in.pose_problem);
  if (!in.pose_problem.empty()) return "robot pose " + config_.pose_link + ": " + in.pose_problem;
  if (!fresh(in.pose_age, config_.pose_timeout)) return "robot pose is stale (" + std::to_string(in.pose_age) + " s)";
  if (!in.have_target) return "no target " + config_.target_link + (in.target_problem.empty() ? "" : ": " + in.target_problem);
  if (!in.target_problem.empty()) return "target " + config_.target_link + ": " + in.target_problem;
  if (!fresh(in.target_age, config_.pose_timeout)) return "target is stale (" + std::to_string(in.target_age) + " s)";
  if (config_.require_scan && !in.scan_problem.empty()) return "scan: " + in.scan_problem;
  if (config_.require_scan && !scanFresh(in.scan_age)) {
    return in.scan_age < 0.0 ? "no scan yet" : "scan is stale (" + std::to_string(in.scan_age) + " s)";
  }
  if (!in.body_intrusion.empty()) return "body intrusion: " + in.body_intrusion;
  return "";
}

std::string TrackingSupervisor::localizationReason(double t, const SupervisorInputs& in) {
  if (in.have_pose && in.pose_position.allFinite() && std::isfinite(t)) {
    if (have_position_ && config_.pose_jump_limit > 0.0) {
      const double moved = (in.pose_position - last_position_).norm();
      const double explained = config_.max_speed * std::max(0.0, t - last_position_time_);
      if (moved - explained > config_.pose_jump_limit) {
        char why[120];
        std::snprintf(why, sizeof(why), "pose jumped %.2f m in one cycle (> tracking bound %.2f m)", moved,
                      config_.pose_jump_limit);
        jump_ = why;
        jumped_ = true;
        good_since_ = t;
      }
    }
    have_position_ = true;
    last_position_ = in.pose_position;
    last_position_time_ = t;
  }
  if (!in.localization_problem.empty()) {
    good_since_ = t;  // the settling time counts from good localisation
    return "localisation: " + in.localization_problem;
  }
  if (jumped_) {
    if (!(t - good_since_ >= config_.jump_settle)) return "localisation: " + jump_;
    jumped_ = false;
  }
  return "";
}

TrackingSupervisor::Decision TrackingSupervisor::begin(double t, const SupervisorInputs& in) {
  Decision d;
  const std::string localization = localizationReason(t, in);  // every cycle: jumps are tracked while off
  if (!enabled_) {
    state_ = State::kDisabled;
    status_ = "disabled";
    return d;
  }
  std::string stale = staleReason(t, in);
  if (stale.empty()) stale = localization;
  if (!stale.empty()) {
    lost_ = true;
    d.publish = true;
    d.u = stop(t, State::kInputsStale, std::move(stale));
    return d;
  }
  d.step = true;
  d.restart = lost_;
  lost_ = false;
  return d;
}

Twist2 TrackingSupervisor::finish(double t, const ControllerOutput& out, const DiamondSet& diamond) {
  if (!std::isfinite(t)) return stop(t, State::kStepInvalid, "controller: time is not finite");
  if (!out.valid) {
    lost_ = true;  // e.g. time went backwards (bag loop): restart when usable
    return stop(t, State::kStepInvalid, "controller: " + out.error);
  }
  if (!out.u.isFinite() || !diamond.contains(out.u, 1e-9)) {  // never expected: belt and braces
    return stop(t, State::kCommandRefused, "command outside the diamond");
  }
  state_ = State::kTracking;
  status_ = "tracking";
  return ramp(t, out.u);
}

Twist2 TrackingSupervisor::stop(double t, State state, std::string why) {
  state_ = state;
  status_ = std::move(why);
  last_command_ = {};
  have_command_time_ = std::isfinite(t);
  last_command_time_ = have_command_time_ ? t : 0.0;
  ramping_ = true;
  return {};
}

Twist2 TrackingSupervisor::ramp(double t, const Twist2& u) {
  Twist2 sent = u;
  if (ramping_) {
    // Time since the last command, at most one period: a late cycle does not earn a bigger
    // step than the period allows, and one that catches up right after earns less.
    const double period = config_.control_period;
    const double dt = have_command_time_ ? std::clamp(t - last_command_time_, 0.0, period) : period;
    const RampStep step = rampTowards(u, last_command_, config_.ramp, dt);
    sent = step.u;
    ramping_ = step.limited;
  }
  last_command_ = sent;
  have_command_time_ = true;
  last_command_time_ = t;
  return sent;
}

}  // namespace core
}  // namespace amigobot_tracking
