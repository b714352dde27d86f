#include "amigobot_tracking/core/law/bounded_law.h"

#include <utility>

namespace amigobot_tracking {
namespace core {

BoundedLaw::BoundedLaw(const ControllerConfig& config)
    : config_(config), diamond_(config.v_max, config.w_max), estimator_(config.estimator) {}

void BoundedLaw::reset() {
  estimator_ = VelocityEstimator(config_.estimator);
  envelope_.reset();
  replay_.clear();
  forgetLawState();
}

void BoundedLaw::restart(double start_ratio) {
  reset();
  envelope_.restart(start_ratio);
}

void BoundedLaw::setConfig(const ControllerConfig& config) {
  reconfigureEstimator(config_.estimator, config.estimator, &estimator_);
  config_ = config;
  diamond_ = DiamondSet(config.v_max, config.w_max);
  configureLaw();
  envelope_.raiseTo(config.rho_inf);
}

OpenedStep BoundedLaw::openStep(double t, const PoseSample& robot, const TargetSample& target,
                                ControllerOutput* out) {
  return core::openStep(t, robot, target, config_, envelope_.timeWentBack(t), replay_, &estimator_, out);
}

ControllerOutput BoundedLaw::invalid(double t, std::string why) {
  applied(t, Twist2());  // the caller commands zero
  return invalidOutput(t, envelope_.rho(), std::move(why));
}

}  // namespace core
}  // namespace amigobot_tracking
