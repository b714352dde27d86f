// Baseline for the comparison: classical feedback linearisation at the offset point with a
// proportional gain, the same repulsive term (10) and the same saturation (12):
//     u_r = v_hat + k_p e + k_o u_c,   u_d = G(th)^-1 u_r,   u = sigma(u_d).
// No performance function: the output's rho is 0 ("none").
#pragma once

#include <vector>

#include "amigobot_tracking/core/controller.h"

namespace amigobot_tracking {
namespace sim {

class ProportionalController {
 public:
  // Robot, avoidance, saturation and estimator parameters are taken from `config` (which
  // must be valid); k_p [1/s] > 0 is the proportional gain.
  ProportionalController(const core::ControllerConfig& config, double k_p);

  // Same contract as PerformanceController::step.
  core::ControllerOutput step(double t, const core::Pose2& pose, const core::TargetSample& target,
                        const std::vector<core::Disk>& obstacles);

  const core::DiamondSet& diamond() const { return diamond_; }
  const core::VelocityEstimator& estimator() const { return estimator_; }

 private:
  core::ControllerConfig config_;
  double k_p_;
  core::DiamondSet diamond_;
  core::VelocityEstimator estimator_;
  bool started_ = false;
  double last_t_ = 0.0;
};

}  // namespace sim
}  // namespace amigobot_tracking
