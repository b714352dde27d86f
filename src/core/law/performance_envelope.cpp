#include "amigobot_tracking/core/law/performance_envelope.h"

#include <algorithm>
#include <cmath>

#include "amigobot_tracking/core/robot/unicycle.h"

namespace amigobot_tracking {
namespace core {

void CommandReplay::remember(double t, const Twist2& u, double max_prediction) {
  if (!std::isfinite(t) || (!commands_.empty() && t < commands_.back().first)) return;
  if (!commands_.empty() && t == commands_.back().first) commands_.pop_back();  // same instant: the newer one
  commands_.emplace_back(t, u);
  while (commands_.size() > 1 && commands_[1].first <= t - max_prediction) commands_.pop_front();
}

Pose2 CommandReplay::replay(double t, const PoseSample& robot, double max_prediction) const {
  const double from = std::max(robot.stamp, t - max_prediction);
  Pose2 pose = robot.pose;
  for (size_t i = 0; i < commands_.size(); ++i) {
    const double start = std::max(commands_[i].first, from);
    const double end = i + 1 < commands_.size() ? std::min(commands_[i + 1].first, t) : t;
    if (end > start) pose = integrateUnicycle(pose, commands_[i].second, end - start);
  }
  return pose;
}

OpenedStep openStep(double t, const PoseSample& robot, const TargetSample& target, const ControllerConfig& config,
                    bool time_went_back, const CommandReplay& replay, VelocityEstimator* estimator,
                    ControllerOutput* out) {
  OpenedStep s;
  if (!std::isfinite(t)) s.error = "time is not finite";
  else if (!robot.pose.isFinite() || !std::isfinite(robot.stamp)) s.error = "robot pose is not finite";
  else if (!std::isfinite(target.stamp) || !target.position.allFinite()) s.error = "target is not finite";
  else if (time_went_back) s.error = "time went backwards";
  if (!s.error.empty()) return s;

  if (!estimator->initialized() || target.stamp > estimator->lastStamp()) {
    const std::uint64_t jumps = estimator->jumps();
    estimator->update(target.stamp, target.position);
    s.sampled = true;
    s.jumped = estimator->jumps() != jumps;
  }
  // Measurement ages, extrapolated over at most max_prediction seconds.
  auto age = [&](double stamp) { return std::clamp(t - stamp, 0.0, config.max_prediction); };
  s.pose = config.compensate_pose_age ? replay.replay(t, robot, config.max_prediction) : robot.pose;
  out->valid = true;
  out->t = t;
  // cos and sin of the heading once: (5), the heading hint of (10) and G^-1 of (11) share them.
  s.heading = Eigen::Vector2d(std::cos(s.pose.theta), std::sin(s.pose.theta));
  out->p_r = s.pose.position() + config.offset * s.heading;  // (5), as offsetPoint()
  out->p_d = target.position;
  if (config.predict_target) out->p_d += estimator->velocity() * age(target.stamp);
  out->e = out->p_d - out->p_r;
  out->v_hat = target.has_velocity ? target.velocity : estimator->velocity();
  s.error_norm = out->e.norm();
  return s;
}

ControllerOutput invalidOutput(double t, double rho, std::string why) {
  ControllerOutput out;
  out.t = t;
  out.rho = rho;
  out.error = std::move(why);
  return out;
}

void reconfigureEstimator(const EstimatorConfig& old_config, const EstimatorConfig& new_config,
                          VelocityEstimator* estimator) {
  if (new_config == old_config) return;
  const VelocityEstimator kept = *estimator;
  *estimator = VelocityEstimator(new_config);
  if (kept.initialized()) estimator->reset(kept.lastStamp(), kept.position(), kept.velocity());
}

}  // namespace core
}  // namespace amigobot_tracking
