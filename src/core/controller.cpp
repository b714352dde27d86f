#include "amigobot_tracking/core/controller.h"

#include <cmath>
#include <cstdint>
#include <utility>

#include "amigobot_tracking/core/avoidance.h"
#include "amigobot_tracking/core/band_implicit.h"
#include "amigobot_tracking/core/offset_point.h"
#include "amigobot_tracking/core/recommended_law.h"
#include "amigobot_tracking/core/unicycle.h"

namespace amigobot_tracking {
namespace core {
namespace {

PerformanceGains gainsOf(const ControllerConfig& config) {
  return {config.lambda, config.rho_inf, config.k_r, config.max_rho_rate};
}

// setImplicitHorizon: replaces the explicit term of the nearest obstacle the offset point
// can reach within h by its backward-Euler value (band_implicit.h), for the command held from
// `start`. `others` is the rest of u_r; the other obstacles keep their explicit terms.
// start_heading and command_heading: (cos, sin) of start.theta and of the command's heading.
void applyImplicitBand(const ControllerConfig& config, const DiamondSet& diamond, const Pose2& start,
                       const Eigen::Vector2d& start_heading, double command_theta,
                       const Eigen::Vector2d& command_heading, const Eigen::Vector2d& others,
                       const std::vector<Disk>& obstacles, double h, ControllerOutput& out) {
  const double radius = config.effectiveRadius();
  const Eigen::Vector2d p_start = start.position() + config.offset * start_heading;  // offsetPoint(start)
  const Disk* nearest = nullptr;
  double nearest_clearance = 0.0;  // from where the held command starts
  for (const Disk& o : obstacles) {
    const double c = (p_start - o.center).norm() - radius - o.radius;
    if (!nearest || c < nearest_clearance) {
      nearest = &o;
      nearest_clearance = c;
    }
  }
  if (!nearest) return;
  // Obstacle j's explicit term, as repulsiveTerm added it at the step's p_r.
  const double clearance_now = (out.p_r - nearest->center).norm() - radius - nearest->radius;
  Eigen::Vector2d explicit_term = Eigen::Vector2d::Zero();
  const bool detected = clearance_now <= config.delta;
  if (detected) {
    explicit_term = (1.0 / std::max(clearance_now, config.min_margin) - 1.0 / config.delta) *
                    (out.p_r - nearest->center);
  }
  const Eigen::Vector2d rest = others + config.k_o * (out.u_c - explicit_term);
  // A held command moves the offset point at the constant speed |(v, r w)|: at most the
  // diamond's bound, and at most |rest| while obstacle j adds nothing (the diamond only
  // shrinks u_r). Out of the band's reach within h, the zero term is the implicit one too.
  const double reach = h * std::min(maxOffsetSpeed(diamond, config.offset), rest.norm());
  if (nearest_clearance - reach > config.delta) return;
  BandImplicitProblem problem;
  problem.pose = start;
  problem.offset = config.offset;
  problem.rest = rest;
  problem.k_o = config.k_o;
  problem.obstacle = *nearest;
  problem.robot_radius = radius;
  problem.delta = config.delta;
  problem.min_margin = config.min_margin;
  problem.h = h;
  problem.command_theta = command_theta;
  problem.start_heading = start_heading;
  problem.command_heading = command_heading;
  const BandImplicitResult implicit = solveBandImplicit(problem, diamond);
  if (!implicit.solved) return;
  out.u_c += implicit.u_c - explicit_term;
  const bool implicit_detected = !implicit.u_c.isZero(0.0);
  if (implicit_detected && !detected) ++out.detected_obstacles;
  if (!implicit_detected && detected) --out.detected_obstacles;
  out.active.avoiding = out.detected_obstacles > 0;
}

// `from` moved toward `to` by at most `step` (Euclidean); `to` itself when `from` is unset (NaN).
Eigen::Vector2d slewLimited(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double step) {
  if (!from.allFinite()) return to;
  const Eigen::Vector2d change = to - from;
  const double n = change.norm();
  return n <= step ? to : Eigen::Vector2d(from + change * (step / n));
}

}  // namespace

PerformanceController::PerformanceController(const ControllerConfig& config)
    : config_(config),
      diamond_(config.v_max, config.w_max),
      gains_(gainsOf(config)),
      estimator_(config.estimator) {}

void PerformanceController::reset() {
  estimator_ = VelocityEstimator(config_.estimator);
  started_ = false;
  rho_ = 0.0;
  start_ratio_ = 0.0;
  conflict_ = 0.0;
  shortfall_ = 0.0;
  feed_forward_ = Eigen::Vector2d::Constant(NAN);
  smoothed_velocity_ = Eigen::Vector2d::Constant(NAN);
  last_command_ = Twist2{};
  noise_variance_ = 0.0;
  last_sample_stamp_ = NAN;
  passing_side_ = 0;
  commands_.clear();
}

void PerformanceController::restart(double start_ratio) {
  reset();
  start_ratio_ = start_ratio;
}

void PerformanceController::setConfig(const ControllerConfig& config) {
  if (!(config.estimator == config_.estimator)) {
    // New estimator gains: restart it from its current estimate (its bounds restart wide).
    const VelocityEstimator kept = estimator_;
    estimator_ = VelocityEstimator(config.estimator);
    if (kept.initialized()) estimator_.reset(kept.lastStamp(), kept.position(), kept.velocity());
  }
  config_ = config;
  diamond_ = DiamondSet(config.v_max, config.w_max);
  gains_ = gainsOf(config);
  // (13) keeps rho >= rho_inf; a raised rho_inf below the current rho would make
  // lambda (rho - rho_inf) in (9) push the robot away from the target.
  if (started_) rho_ = std::max(rho_, config.rho_inf);
}

ControllerOutput PerformanceController::invalid(double t, std::string why) {
  remember(t, Twist2());  // the caller commands zero
  ControllerOutput out;
  out.t = t;
  out.rho = rho_;
  out.error = std::move(why);
  return out;
}

void PerformanceController::remember(double t, const Twist2& u) {
  if (!std::isfinite(t) || (!commands_.empty() && t < commands_.back().first)) return;
  if (!commands_.empty() && t == commands_.back().first) commands_.pop_back();  // same instant: the newer one
  commands_.emplace_back(t, u);
  while (commands_.size() > 1 && commands_[1].first <= t - config_.max_prediction) commands_.pop_front();
}

Pose2 PerformanceController::compensatedPose(double t, const PoseSample& robot) const {
  const double from = std::max(robot.stamp, t - config_.max_prediction);
  Pose2 pose = robot.pose;
  for (size_t i = 0; i < commands_.size(); ++i) {
    const double start = std::max(commands_[i].first, from);
    const double end = i + 1 < commands_.size() ? std::min(commands_[i + 1].first, t) : t;
    if (end > start) pose = integrateUnicycle(pose, commands_[i].second, end - start);
  }
  return pose;
}

ControllerOutput PerformanceController::step(double t, const Pose2& pose, const TargetSample& target,
                                             const std::vector<Disk>& obstacles) {
  return stepStamped(t, PoseSample{t, pose}, target, obstacles);
}

ControllerOutput PerformanceController::stepStamped(double t, const PoseSample& robot, const TargetSample& target,
                                                    const std::vector<Disk>& obstacles) {
  if (!std::isfinite(t)) return invalid(t, "time is not finite");
  if (!robot.pose.isFinite() || !std::isfinite(robot.stamp)) return invalid(t, "robot pose is not finite");
  if (!std::isfinite(target.stamp) || !target.position.allFinite()) return invalid(t, "target is not finite");
  if (started_ && t < last_t_) return invalid(t, "time went backwards");

  if (!estimator_.initialized() || target.stamp > estimator_.lastStamp()) {
    const std::uint64_t jumps = estimator_.jumps();
    estimator_.update(target.stamp, target.position);
    if (config_.recommended()) observeNoise(target, estimator_.jumps() != jumps);
  }

  // Measurement ages, extrapolated over at most max_prediction seconds.
  auto age = [&](double stamp) { return std::clamp(t - stamp, 0.0, config_.max_prediction); };
  const Pose2 pose = config_.compensate_pose_age ? compensatedPose(t, robot) : robot.pose;

  ControllerOutput out;
  out.valid = true;
  out.t = t;
  // cos and sin of the heading once: (5), the heading hint of (10) and G^-1 of (11) share them.
  const Eigen::Vector2d heading(std::cos(pose.theta), std::sin(pose.theta));
  out.p_r = pose.position() + config_.offset * heading;  // (5), as offsetPoint()
  out.p_d = target.position;
  if (config_.predict_target) out.p_d += estimator_.velocity() * age(target.stamp);
  out.e = out.p_d - out.p_r;
  out.v_hat = target.has_velocity ? target.velocity : estimator_.velocity();
  const double error_norm = out.e.norm();

  const double h = started_ ? t - last_t_ : 0.0;
  // rho: start rule, then (13) over the elapsed time with the last step's conflict.
  if (!started_) {
    started_ = true;
    rho_ = config_.rho_0;
    if (start_ratio_ > 0.0) rho_ = std::max(rho_, error_norm / start_ratio_);
    start_ratio_ = 0.0;
  } else if (t > last_t_ && config_.recommended()) {
    // (13'): the relaxation counts the last step's shortfall (recommended_law.h).
    rho_ = recommendedRhoStep(config_, rho_, shortfall_, t - last_t_, rhoFloor());
    out.active.rho_relaxed = shortfall_ > 0.0;
  } else if (t > last_t_) {
    // The conflict is the last step's: over a stall it is stale, and near contact (1/margin)
    // it is large, so the relaxation is held for at most max_relaxation_interval.
    rho_ = rhoStep(gains_, rho_, conflict_, t - last_t_, config_.max_relaxation_interval);
    out.active.rho_relaxed = conflict_ < 0.0;
  }
  last_t_ = t;
  if (error_norm >= config_.max_error_ratio * rho_) {
    rho_ = error_norm / config_.max_error_ratio;
    out.active.envelope_widened = true;
    ++envelope_widenings_;
  }
  out.rho = rho_;
  if (config_.recommended()) {
    if (!commandRecommended(pose, obstacles, h, out)) return invalid(t, "desired command is not finite");
    remember(t, out.u);
    return out;
  }

  const double ratio = error_norm / rho_;
  const double t_ratio = transformT(ratio);
  const Eigen::Vector2d e_hat = error_norm > 1e-12 ? Eigen::Vector2d(out.e / error_norm) : Eigen::Vector2d::Zero();

  const double radius = config_.effectiveRadius();
  const AvoidanceResult avoidance =
      config_.moving_obstacles
          ? movingRepulsiveTerm(out.p_r, obstacles, radius, config_.delta, config_.obstacle_horizon, heading,
                                config_.min_margin)
          : repulsiveTerm(out.p_r, obstacles, radius, config_.delta, heading, config_.min_margin);
  out.u_c = avoidance.u_c;
  bool escape_full = false;
  if (config_.tangential_avoidance) {
    const TangentialResult tangential = tangentialTerm(out.p_r, obstacles, radius, config_.delta, e_hat,
                                                       passing_side_, config_.tangential_hysteresis,
                                                       config_.min_margin);
    passing_side_ = tangential.side;
    out.passing_side = tangential.side;
    out.u_t = config_.k_t * tangential.u_t;
    escape_full = tangential.full_strength;
  }
  // The tracking part of (9).
  const Eigen::Vector2d attraction =
      config_.k_d * t_ratio * e_hat + out.v_hat + config_.lambda * (rho_ - config_.rho_inf) * out.e / rho_;
  // The escape redirects the attraction the barrier cancels; it needs no more than k_t times
  // that. Uncapped it grows like u_c (1/margin) and, after the diamond's radial scaling, takes
  // the radial barrier's share: 3 contacts with crossing obstacles on crossing_obstacles.yaml.
  const double escape_cap = config_.k_t * attraction.norm() / config_.k_o;
  if (escape_full) {
    out.u_t *= escape_cap / config_.k_t;  // a group of disks: the whole cap (u_t was k_t times a unit vector)
  } else if (out.u_t.norm() > escape_cap) {
    out.u_t *= escape_cap / out.u_t.norm();
  }
  out.detected_obstacles = avoidance.detected;
  out.min_clearance = avoidance.min_clearance;
  out.active.avoiding = avoidance.detected > 0;
  if (implicit_horizon_ > 0.0 && !config_.moving_obstacles) {
    applyImplicitBand(config_, diamond_, implicit_start_given_ ? implicit_start_ : pose,
                      implicit_start_given_ ? implicit_start_heading_ : heading, pose.theta, heading,
                      attraction + config_.k_o * out.u_t, obstacles, implicit_horizon_, out);
  }

  // (9): u_r = k_d T e_hat + v_hat + lambda (rho - rho_inf) e / rho + k_o u_c.
  out.u_r = attraction + config_.k_o * (out.u_c + out.u_t);
  out.u_d = offsetVelocityToTwist(out.u_r, heading, config_.offset);  // (11)
  const auto saturated = diamond_.saturate(out.u_d);                     // (12)
  if (!saturated) return invalid(t, "desired command is not finite");
  out.u = *saturated;
  remember(t, out.u);

  const double alignment = e_hat.dot(out.u_c);
  const double clipping = std::hypot(out.u.v - out.u_d.v, out.u.omega - out.u_d.omega);
  out.active.saturated = clipping > 0.0;
  out.active.conflict = alignment < 0.0;
  // The fixed-rho baseline never relaxes: (13) without its adaptive term.
  conflict_ = config_.adaptive_rho ? t_ratio * alignment - clipping : 0.0;
  return out;
}

// Measurement noise at the scale of rho_inf makes |e| jump past rho at a sample, which no
// continuous rho law can prevent (3 cm of noise against rho_inf = 0.1 m: 1-6 guard widenings in
// 12 noisy runs of a class). The innovation of a sample against the last one carried by the
// feed-forward is the difference of two noises, E|n_k - n_k-1|^2 = 4 sigma^2 in the plane (the
// true motion adds (v - ff) dt, small while the feed-forward follows the target). Its running
// mean over kNoiseWindow gives sigma; samples the estimator calls jumps are left out.
namespace {
constexpr double kNoiseWindow = 2.0;  // [s] averaging time of the innovation
constexpr double kNoiseReach = 5.0;   // |n| > 5 sigma: P = exp(-12.5) = 4e-6 per sample in the plane
}  // namespace

void PerformanceController::observeNoise(const TargetSample& target, bool jumped) {
  const double dt = target.stamp - last_sample_stamp_;
  if (!jumped && dt > 0.0 && feed_forward_.allFinite()) {
    const double innovation2 = (target.position - last_sample_ - feed_forward_ * dt).squaredNorm();
    const double weight = 1.0 - std::exp(-dt / kNoiseWindow);
    noise_variance_ += weight * (0.25 * innovation2 - noise_variance_);
  }
  last_sample_stamp_ = target.stamp;
  last_sample_ = target.position;
}

double PerformanceController::rhoFloor() const {
  return config_.rho_inf + kNoiseReach * std::sqrt(noise_variance_);
}

bool PerformanceController::commandRecommended(const Pose2& pose, const std::vector<Disk>& obstacles, double h,
                                               ControllerOutput& out) {
  // The estimator differentiates the target's samples: 3 cm of noise at 10 Hz gives a v_hat
  // off by 0.5 m/s from one sample to the next, and fed forward that swung the command between
  // the diamond's corners (|dv| 0.6 m/s in one step, in 9 of 12 noisy gap runs). No target the
  // robot can follow changes its velocity that fast: the feed-forward follows v_hat at most
  // a_max h per step (estimator.max_acceleration), so a real acceleration up to a_max passes
  // unchanged and the noise is cut to a walk of a_max h steps.
  const double a_max = config_.estimator.max_acceleration;  // 0: no bound, v_hat itself
  feed_forward_ = a_max > 0.0 ? slewLimited(feed_forward_, out.v_hat, a_max * h) : out.v_hat;
  RecommendedInput in;
  in.pose = pose;
  in.p_r = out.p_r;
  in.e = out.e;
  in.v_hat = feed_forward_;
  // The field's look-ahead multiplies a velocity by seconds: v_f's walk under noise (a_max h a
  // step) would move the goal by decimetres round a parked target. Averaged over the
  // look-ahead itself, the goal's offset is about the target's displacement over that time,
  // whose noise is the sample noise (a few cm), not tau times a velocity's.
  const double tau = config_.field_lookahead;
  if (!smoothed_velocity_.allFinite() || tau <= 0.0) smoothed_velocity_ = feed_forward_;
  else smoothed_velocity_ += (feed_forward_ - smoothed_velocity_) * std::min(1.0, h / tau);
  in.v_smooth = smoothed_velocity_;
  in.rho_floor = out.rho_floor = rhoFloor();
  in.rho = rho_;
  in.previous = last_command_;
  in.h = h;
  const RecommendedCommand command = recommendedCommand(config_, diamond_, in, obstacles);
  if (!command.valid) return false;
  out.u = last_command_ = command.u;
  out.u_d = command.u_nominal;
  out.u_r = command.u_nom;
  out.detected_obstacles = command.barrier_rows;
  out.min_clearance = command.min_clearance;
  out.active.saturated = std::hypot(out.u.v - out.u_d.v, out.u.omega - out.u_d.omega) > 0.0;
  out.active.avoiding = command.active_barriers > 0;
  out.active.conflict = command.shortfall > 0.0;
  // The fixed-rho baseline never relaxes.
  shortfall_ = config_.adaptive_rho ? command.relaxation : 0.0;
  return true;
}

}  // namespace core
}  // namespace amigobot_tracking
