// Baseline for the comparison: classical feedback linearisation at the offset point with a
// proportional gain, the same repulsive term (10) and the same saturation (12):
//     u_r = v_hat + k_p e + k_o u_c,   u_d = G(th)^-1 u_r,   u = sigma(u_d).
// No performance function: the output's rho is 0 ("none").
#pragma once

#include <vector>

#include "amigobot_tracking/core/controller.h"

namespace amigobot_tracking {
namespace core {

class ProportionalController {
 public:
  // Robot, avoidance, saturation and estimator parameters are taken from `config` (which
  // must be valid); k_p [1/s] > 0 is the proportional gain.
  ProportionalController(const ControllerConfig& config, double k_p);

  // Same contract as PerformanceController::step.
  ControllerOutput step(double t, const Pose2& pose, const TargetSample& target,
                        const std::vector<Disk>& obstacles);

  const DiamondSet& diamond() const { return diamond_; }
  const VelocityEstimator& estimator() const { return estimator_; }

 private:
  ControllerConfig config_;
  double k_p_;
  DiamondSet diamond_;
  VelocityEstimator estimator_;
  bool started_ = false;
  double last_t_ = 0.0;
};

}  // namespace core
}  // namespace amigobot_tracking
