// A law with an estimator and a performance envelope: the state and the housekeeping the
// paper's law (paper_controller.h) and the recommended law (recommended_controller.h) share.
// It holds the configuration, the diamond, the target velocity estimator (3)-(4), rho's start
// rule and guard (performance_envelope.h) and the pose-age replay; a law adds its own rho
// dynamics ((13) or (13')), its command and the state they keep.
#pragma once

#include <cstdint>
#include <string>

#include "amigobot_tracking/core/law/control_law.h"
#include "amigobot_tracking/core/law/performance_envelope.h"

namespace amigobot_tracking {
namespace core {

class BoundedLaw : public ControlLaw {
 public:
  // Forgets the shared state, then the law's own (forgetLawState).
  void reset() override;
  void restart(double start_ratio) override;
  // The estimator restarts from its estimate with the new gains; then the law's own
  // (configureLaw); a raised rho_inf lifts a started rho ((13) and (13') keep rho >= rho_inf:
  // below it lambda (rho - rho_inf) would push the robot away from the target).
  void setConfig(const ControllerConfig& config) override;
  const ControllerConfig& config() const override { return config_; }
  const DiamondSet& diamond() const override { return diamond_; }
  bool started() const override { return envelope_.started(); }
  double rho() const override { return envelope_.rho(); }
  std::uint64_t envelopeWidenings() const override { return envelope_.widenings(); }
  const VelocityEstimator* estimator() const override { return &estimator_; }

 protected:
  explicit BoundedLaw(const ControllerConfig& config);

  // The law's own state, forgotten on reset().
  virtual void forgetLawState() = 0;
  // What the law derives from config_, after setConfig() changed it.
  virtual void configureLaw() {}

  // openStep (performance_envelope.h) on this law's state.
  OpenedStep openStep(double t, const PoseSample& robot, const TargetSample& target, ControllerOutput* out);
  // Remembers the command u applied from t (pose-age replay).
  void applied(double t, const Twist2& u) { replay_.remember(t, u, config_.max_prediction); }
  // The output of an unusable step: zero command (remembered as applied), rho kept.
  ControllerOutput invalid(double t, std::string why);

  ControllerConfig config_;
  DiamondSet diamond_;
  VelocityEstimator estimator_;
  PerformanceEnvelope envelope_;

 private:
  CommandReplay replay_;
};

}  // namespace core
}  // namespace amigobot_tracking
