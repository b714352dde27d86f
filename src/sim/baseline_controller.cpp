#include "amigobot_tracking/sim/baseline_controller.h"

#include <cmath>

#include "amigobot_tracking/core/avoidance.h"
#include "amigobot_tracking/core/offset_point.h"

namespace amigobot_tracking {
namespace sim {

ProportionalController::ProportionalController(const core::ControllerConfig& config, double k_p)
    : config_(config), k_p_(k_p), diamond_(config.v_max, config.w_max), estimator_(config.estimator) {}

core::ControllerOutput ProportionalController::step(double t, const core::Pose2& pose, const core::TargetSample& target,
                                              const std::vector<core::Disk>& obstacles) {
  core::ControllerOutput out;
  out.t = t;
  if (!std::isfinite(t) || !pose.isFinite() || !std::isfinite(target.stamp) || !target.position.allFinite() ||
      (started_ && t < last_t_)) {
    out.error = "inputs not usable (non-finite, or time went backwards)";
    return out;
  }
  started_ = true;
  last_t_ = t;
  if (!estimator_.initialized() || target.stamp > estimator_.lastStamp()) {
    estimator_.update(target.stamp, target.position);
  }
  out.valid = true;
  out.p_r = core::offsetPoint(pose, config_.offset);
  out.p_d = target.position;
  out.e = out.p_d - out.p_r;
  out.v_hat = target.has_velocity ? target.velocity : estimator_.velocity();
  const Eigen::Vector2d heading(std::cos(pose.theta), std::sin(pose.theta));
  const core::AvoidanceResult avoidance =
      core::repulsiveTerm(out.p_r, obstacles, config_.effectiveRadius(), config_.delta, heading, config_.min_margin);
  out.u_c = avoidance.u_c;
  out.detected_obstacles = avoidance.detected;
  out.min_clearance = avoidance.min_clearance;
  out.active.avoiding = avoidance.detected > 0;
  out.u_r = out.v_hat + k_p_ * out.e + config_.k_o * out.u_c;
  out.u_d = core::offsetVelocityToTwist(out.u_r, pose.theta, config_.offset);
  const auto saturated = diamond_.saturate(out.u_d);
  if (!saturated) {
    out.valid = false;
    out.error = "desired command is not finite";
    out.u = core::Twist2();
    return out;
  }
  out.u = *saturated;
  out.active.saturated = out.u.v != out.u_d.v || out.u.omega != out.u_d.omega;
  out.active.conflict = out.e.dot(out.u_c) < 0.0;
  return out;
}

}  // namespace sim
}  // namespace amigobot_tracking
