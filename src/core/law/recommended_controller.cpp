#include "amigobot_tracking/core/law/recommended_controller.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "amigobot_tracking/core/law/recommended_law.h"

namespace amigobot_tracking {
namespace core {
namespace {

// `from` moved toward `to` by at most `step` (Euclidean); `to` itself when `from` is unset (NaN).
Eigen::Vector2d slewLimited(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double step) {
  if (!from.allFinite()) return to;
  const Eigen::Vector2d change = to - from;
  const double n = change.norm();
  return n <= step ? to : Eigen::Vector2d(from + change * (step / n));
}

}  // namespace

RecommendedController::RecommendedController(const ControllerConfig& config) : BoundedLaw(config) {}

void RecommendedController::forgetLawState() {
  shortfall_ = 0.0;
  feed_forward_ = Eigen::Vector2d::Constant(NAN);
  smoothed_velocity_ = Eigen::Vector2d::Constant(NAN);
  last_command_ = Twist2{};
  noise_variance_ = 0.0;
  committed_.reset();
  since_yield_ = 0.0;
  base_.reset();
  last_sample_stamp_ = NAN;
}

ControllerOutput RecommendedController::step(double t, const PoseSample& robot, const TargetSample& target,
                                             const std::vector<Disk>& obstacles) {
  ControllerOutput out;
  const OpenedStep opened = openStep(t, robot, target, &out);
  if (!opened.error.empty()) return invalid(t, opened.error);
  if (opened.sampled) observeNoise(target, opened.jumped);
  const double h = envelope_.elapsed(t);
  // rho: start rule, then (13') over the elapsed time; its relaxation counts the last step's
  // shortfall (recommended_law.h).
  envelope_.update(t, opened.error_norm, config_, [&](double rho, double dt) {
    out.active.rho_relaxed = shortfall_ > 0.0;
    return recommendedRhoStep(config_, rho, shortfall_, dt, rhoFloor());
  }, &out.active);
  out.rho = envelope_.rho();
  if (!command(opened.pose, obstacles, h, out)) return invalid(t, "desired command is not finite");
  applied(t, out.u);
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

void RecommendedController::observeNoise(const TargetSample& target, bool jumped) {
  const double dt = target.stamp - last_sample_stamp_;
  if (!jumped && dt > 0.0 && feed_forward_.allFinite()) {
    const double innovation2 = (target.position - last_sample_ - feed_forward_ * dt).squaredNorm();
    const double weight = 1.0 - std::exp(-dt / kNoiseWindow);
    noise_variance_ += weight * (0.25 * innovation2 - noise_variance_);
  }
  last_sample_stamp_ = target.stamp;
  last_sample_ = target.position;
}

double RecommendedController::rhoFloor() const {
  return config_.rho_inf + kNoiseReach * std::sqrt(noise_variance_);
}

bool RecommendedController::command(const Pose2& pose, const std::vector<Disk>& obstacles, double h,
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
  const double tau = config_.recommended.field_lookahead;
  if (!smoothed_velocity_.allFinite() || tau <= 0.0) smoothed_velocity_ = feed_forward_;
  else smoothed_velocity_ += (feed_forward_ - smoothed_velocity_) * std::min(1.0, h / tau);
  in.v_smooth = smoothed_velocity_;
  in.rho_floor = out.rho_floor = rhoFloor();
  in.rho = envelope_.rho();
  in.previous = last_command_;
  in.h = h;
  if (config_.recommended.yield_horizon > 0.0) {  // only the yielding look-ahead reads it
    if (!base_) base_.emplace(config_.actuator, kAmigoHalfTrack);
    else if (h > 0.0) base_->step(last_command_, h);
    in.base = &*base_;
  }
  if (committed_) committed_->advance(h);
  in.committed = committed_;
  const RecommendedCommand command = recommendedCommand(config_, diamond_, in, obstacles);
  if (!command.valid) return false;
  // A step where the filter's own command was clear enough keeps the commitment a while: the
  // person is still there, and a fresh choice a step later swung the robot to the other side.
  since_yield_ = command.yielded ? 0.0 : since_yield_ + h;
  if (command.yielded) committed_ = command.manoeuvre;
  else if (since_yield_ > kYieldMemory) committed_.reset();
  out.u = last_command_ = command.u;
  out.u_d = command.u_nominal;
  out.u_r = command.u_nom;
  out.detected_obstacles = command.barrier_rows;
  out.min_clearance = command.min_clearance;
  out.active.saturated = std::hypot(out.u.v - out.u_d.v, out.u.omega - out.u_d.omega) > 0.0;
  out.active.avoiding = command.active_barriers > 0 || command.yielded;
  out.active.yielding = command.yielded;
  out.active.conflict = command.shortfall > 0.0;
  // The fixed-rho baseline never relaxes.
  shortfall_ = config_.adaptive_rho ? command.relaxation : 0.0;
  return true;
}

}  // namespace core
}  // namespace amigobot_tracking
