// Pieces the laws with a performance bound share (BoundedLaw, bounded_law.h, holds them):
//  - PerformanceEnvelope: rho's start rule and the envelope guard (controller.h's header
//    comment), around the law's own rho dynamics ((13) or (13')).
//  - CommandReplay: pose-age compensation (compensate_pose_age), the pose moved from its
//    stamp along the commands applied since.
//  - openStep: the input checks, the estimator's update and the error e every step starts with.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <utility>

#include <Eigen/Core>

#include "amigobot_tracking/core/law/control_law.h"
#include "amigobot_tracking/core/law/estimator.h"

namespace amigobot_tracking {
namespace core {

class PerformanceEnvelope {
 public:
  // Forget rho and the start (the widening count is kept: it is a run's statistic).
  void reset() {
    started_ = false;
    rho_ = 0.0;
    start_ratio_ = 0.0;
  }
  void restart(double start_ratio) {
    reset();
    start_ratio_ = start_ratio;
  }
  bool started() const { return started_; }
  double rho() const { return rho_; }
  std::uint64_t widenings() const { return widenings_; }
  bool timeWentBack(double t) const { return started_ && t < last_t_; }
  // Seconds since the last step; 0 before the first.
  double elapsed(double t) const { return started_ ? t - last_t_ : 0.0; }
  // (13) keeps rho >= rho_inf: a raised rho_inf lifts a started rho.
  void raiseTo(double rho_inf) {
    if (started_) rho_ = std::max(rho_, rho_inf);
  }
  // The start rule on the first step, else `advance(rho, dt)` (the law's rho dynamics) over the
  // elapsed time; then the guard widens rho so |e|/rho <= max_error_ratio (flagged in `active`).
  template <class Advance>
  void update(double t, double error_norm, const ControllerConfig& config, Advance advance,
              ActiveConstraints* active) {
    if (!started_) {
      started_ = true;
      rho_ = config.rho_0;
      if (start_ratio_ > 0.0) rho_ = std::max(rho_, error_norm / start_ratio_);
      start_ratio_ = 0.0;
    } else if (t > last_t_) {
      rho_ = advance(rho_, t - last_t_);
    }
    last_t_ = t;
    if (error_norm >= config.max_error_ratio * rho_) {
      rho_ = error_norm / config.max_error_ratio;
      active->envelope_widened = true;
      ++widenings_;
    }
  }

 private:
  bool started_ = false;
  double last_t_ = 0.0;
  double rho_ = 0.0;
  double start_ratio_ = 0.0;  // > 0: the next start uses restart()'s rule
  std::uint64_t widenings_ = 0;
};

class CommandReplay {
 public:
  void clear() { commands_.clear(); }
  // u is applied from t on (kept over the last max_prediction seconds).
  void remember(double t, const Twist2& u, double max_prediction);
  // The pose moved from its stamp to t along the commands applied meanwhile (at most
  // max_prediction seconds of them): exact for the unicycle, what odometry would give.
  Pose2 replay(double t, const PoseSample& robot, double max_prediction) const;

 private:
  // Applied commands, each held from its time to the next one's (zero before the first).
  std::deque<std::pair<double, Twist2>> commands_;
};

// What openStep found besides `out`.
struct OpenedStep {
  std::string error;     // non-empty: the inputs are unusable (out is not filled)
  bool sampled = false;  // the target sample was new and updated the estimator
  bool jumped = false;   // ... and the estimator called it a jump
  Pose2 pose;            // the pose used (age-compensated when configured)
  Eigen::Vector2d heading = Eigen::Vector2d::UnitX();  // (cos, sin) of pose.theta
  double error_norm = 0.0;
};

// The start of every step of a law with a performance bound: checks the inputs, updates the
// estimator with a new sample, and fills out.valid, t, p_r (5), p_d, e and v_hat.
OpenedStep openStep(double t, const PoseSample& robot, const TargetSample& target, const ControllerConfig& config,
                    bool time_went_back, const CommandReplay& replay, VelocityEstimator* estimator,
                    ControllerOutput* out);

// The output of an unusable step: zero command, valid = false, rho kept.
ControllerOutput invalidOutput(double t, double rho, std::string why);

// New estimator gains: the estimator restarts from its current estimate (its bounds restart wide).
void reconfigureEstimator(const EstimatorConfig& old_config, const EstimatorConfig& new_config,
                          VelocityEstimator* estimator);

}  // namespace core
}  // namespace amigobot_tracking
