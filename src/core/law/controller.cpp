#include "amigobot_tracking/core/law/controller.h"

#include "amigobot_tracking/core/law/law_registry.h"

namespace amigobot_tracking {
namespace core {

PerformanceController::PerformanceController(const ControllerConfig& config) : law_(makeLaw(config.law, LawSetup{config})) {}

void PerformanceController::setConfig(const ControllerConfig& config) {
  if (config.law != law_->name()) {
    law_ = makeLaw(config.law, LawSetup{config});
    return;
  }
  law_->setConfig(config);
}

}  // namespace core
}  // namespace amigobot_tracking
