// The controller the tracking loop runs: the law named by ControllerConfig::law, built from
// the law registry (law_registry.h) and driven through the ControlLaw interface. The laws:
// paper_controller.h (the paper's (3)-(13), and fixed_rho), recommended_controller.h.
//
// Start and envelope rule (laws with a rho bound): T(|e|/rho) is undefined for |e| >= rho.
// When the target starts farther than max_error_ratio * rho_0, rho(0) is set to
// |e(0)| / max_error_ratio (the robot goes, and rho then decays at the prescribed rate);
// whenever a discrete step leaves |e| >= max_error_ratio * rho, rho is widened the same way.
// Both events are reported in the output flags, so tests can check they did not happen where
// the theory says so (performance_envelope.h).
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/law/control_law.h"
#include "amigobot_tracking/core/law/controller_config.h"
#include "amigobot_tracking/core/robot/diamond.h"
#include "amigobot_tracking/core/law/estimator.h"
#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

class PerformanceController {
 public:
  // The config must be valid (validate() empty); the constructor does not check it.
  explicit PerformanceController(const ControllerConfig& config = ControllerConfig());
  PerformanceController(const PerformanceController& other) : law_(other.law_->clone()) {}
  PerformanceController& operator=(const PerformanceController& other) {
    law_ = other.law_->clone();
    return *this;
  }

  // One control step at time t [s] (monotonic). The target sample updates the estimator
  // when its stamp is newer than the last one. Non-finite pose or target, or time going
  // backwards, gives valid = false and a zero command.
  ControllerOutput step(double t, const Pose2& pose, const TargetSample& target,
                        const std::vector<Disk>& obstacles) {
    return law_->step(t, PoseSample{t, pose}, target, obstacles);
  }
  // The same with the pose's own stamp (used when compensate_pose_age is on).
  ControllerOutput stepStamped(double t, const PoseSample& robot, const TargetSample& target,
                               const std::vector<Disk>& obstacles) {
    return law_->step(t, robot, target, obstacles);
  }

  // Forget all state: the next step starts afresh (estimator, rho, start rule).
  void reset() { law_->reset(); }
  // reset(), and the next step starts rho at max(rho_0, |e| / start_ratio) instead of rho_0
  // (ControlLaw::restart). Only that step; rho then follows (13).
  void restart(double start_ratio) { law_->restart(start_ratio); }
  // Offline simulation only: the next command will be held for h [s] (ControlLaw::holdNextCommand;
  // the paper's law evaluates its nearest band backward-Euler). 0: what the robot uses.
  void setImplicitHorizon(double h) {
    CommandHold hold;
    hold.h = h;
    law_->holdNextCommand(hold);
  }
  // The same when the command will be held from `start` (heading (cos, sin) of start.theta), not
  // from the pose of the step (the simulator's midpoint evaluation).
  void setImplicitHorizon(double h, const Pose2& start, const Eigen::Vector2d& start_heading) {
    law_->holdNextCommand(CommandHold{h, true, start, start_heading});
  }
  void setImplicitHorizon(double h, const Pose2& start) {
    setImplicitHorizon(h, start, Eigen::Vector2d(std::cos(start.theta), std::sin(start.theta)));
  }
  // Swap the parameters between steps, keeping the state (rho is re-clamped to its rules).
  // Another `law` builds that law afresh.
  void setConfig(const ControllerConfig& config);

  const ControlLaw& law() const { return *law_; }
  const ControllerConfig& config() const { return law_->config(); }
  const VelocityEstimator& estimator() const { return *law_->estimator(); }
  const DiamondSet& diamond() const { return law_->diamond(); }
  bool started() const { return law_->started(); }
  double rho() const { return law_->rho(); }
  std::uint64_t envelopeWidenings() const { return law_->envelopeWidenings(); }

 private:
  std::unique_ptr<ControlLaw> law_;
};

}  // namespace core
}  // namespace amigobot_tracking
