// A control law provided by a library above sim (sim_mrpt: MRPT's reactive navigator), run by
// the closed loop like the built-in laws. The sim layer cannot depend on such a library, so
// the setup carries a factory (ClosedLoopSetup::external_law) that the program linking it sets.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "amigobot_tracking/core/controller.h"
#include "amigobot_tracking/core/diamond.h"

namespace amigobot_tracking {
namespace sim {

struct ClosedLoopSetup;

class StepLaw {
 public:
  virtual ~StepLaw() = default;
  // Same contract as PerformanceController::stepStamped: the applied command inside diamond(),
  // e = p_d - p_r at the offset point, rho <= 0 when the law has no performance bound.
  virtual core::ControllerOutput step(double t, const core::PoseSample& robot, const core::TargetSample& target,
                                      const std::vector<core::Disk>& obstacles) = 0;
  virtual const core::DiamondSet& diamond() const = 0;
};

// Builds the law for one run from the run's setup (limits, radii, offset, control period).
using StepLawFactory = std::function<std::unique_ptr<StepLaw>(const ClosedLoopSetup&)>;

}  // namespace sim
}  // namespace amigobot_tracking
