#include "amigobot_tracking/core/law/proportional_controller.h"

#include <cmath>

#include "amigobot_tracking/core/law/avoidance.h"
#include "amigobot_tracking/core/robot/offset_point.h"
#include "amigobot_tracking/core/law/performance_envelope.h"

namespace amigobot_tracking {
namespace core {

ProportionalController::ProportionalController(const ControllerConfig& config, double k_p)
    : config_(config), k_p_(k_p), diamond_(config.v_max, config.w_max), estimator_(config.estimator) {}

void ProportionalController::reset() {
  estimator_ = VelocityEstimator(config_.estimator);
  started_ = false;
}

void ProportionalController::setConfig(const ControllerConfig& config) {
  reconfigureEstimator(config_.estimator, config.estimator, &estimator_);
  config_ = config;
  diamond_ = DiamondSet(config.v_max, config.w_max);
}

ControllerOutput ProportionalController::step(double t, const PoseSample& robot, const TargetSample& target,
                                              const std::vector<Disk>& obstacles) {
  const Pose2& pose = robot.pose;
  ControllerOutput out;
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
  out.p_r = offsetPoint(pose, config_.offset);
  out.p_d = target.position;
  out.e = out.p_d - out.p_r;
  out.v_hat = target.has_velocity ? target.velocity : estimator_.velocity();
  const Eigen::Vector2d heading(std::cos(pose.theta), std::sin(pose.theta));
  const AvoidanceResult avoidance =
      repulsiveTerm(out.p_r, obstacles, config_.effectiveRadius(), config_.delta, heading, config_.min_margin);
  out.u_c = avoidance.u_c;
  out.detected_obstacles = avoidance.detected;
  out.min_clearance = avoidance.min_clearance;
  out.active.avoiding = avoidance.detected > 0;
  out.u_r = out.v_hat + k_p_ * out.e + config_.k_o * out.u_c;
  out.u_d = offsetVelocityToTwist(out.u_r, pose.theta, config_.offset);
  const auto saturated = diamond_.saturate(out.u_d);
  if (!saturated) {
    out.valid = false;
    out.error = "desired command is not finite";
    out.u = Twist2();
    return out;
  }
  out.u = *saturated;
  out.active.saturated = out.u.v != out.u_d.v || out.u.omega != out.u_d.omega;
  out.active.conflict = out.e.dot(out.u_c) < 0.0;
  return out;
}

}  // namespace core
}  // namespace amigobot_tracking
