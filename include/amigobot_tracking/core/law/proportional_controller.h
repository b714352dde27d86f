// Baseline for the comparison: classical feedback linearisation at the offset point with a
// proportional gain, the same repulsive term (10) and the same saturation (12):
//     u_r = v_hat + k_p e + k_o u_c,   u_d = G(th)^-1 u_r,   u = sigma(u_d).
// No performance function: the output's rho is 0 ("none").
#pragma once

#include <vector>

#include <memory>
#include <string>

#include "amigobot_tracking/core/law/control_law.h"
#include "amigobot_tracking/core/law/estimator.h"

namespace amigobot_tracking {
namespace core {

class ProportionalController : public ControlLaw {
 public:
  // Robot, avoidance, saturation and estimator parameters are taken from `config` (which
  // must be valid); k_p [1/s] > 0 is the proportional gain.
  ProportionalController(const ControllerConfig& config, double k_p);

  std::unique_ptr<ControlLaw> clone() const override { return std::make_unique<ProportionalController>(*this); }
  std::string name() const override { return "proportional"; }
  // The pose's stamp is not used (no pose-age compensation).
  ControllerOutput step(double t, const PoseSample& robot, const TargetSample& target,
                        const std::vector<Disk>& obstacles) override;
  void reset() override;
  void setConfig(const ControllerConfig& config) override;
  const ControllerConfig& config() const override { return config_; }
  const DiamondSet& diamond() const override { return diamond_; }
  const VelocityEstimator* estimator() const override { return &estimator_; }

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
