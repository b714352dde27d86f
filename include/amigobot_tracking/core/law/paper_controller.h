// The paper's law, eqs. (3)-(13): the estimator, the repulsion (10) (with the extensions
// tangential_avoidance and moving_obstacles), the saturation (12) and the adaptive rho (13).
// Its "fixed_rho" configuration (the registry's fixed_rho law) drops (13)'s relaxation term:
// rho follows the prescribed decay only.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "amigobot_tracking/core/law/bounded_law.h"
#include "amigobot_tracking/core/law/prescribed_performance.h"

namespace amigobot_tracking {
namespace core {

class PaperController : public BoundedLaw {
 public:
  // fixed_rho: the baseline without adaptation (config.adaptive_rho is then ignored).
  explicit PaperController(const ControllerConfig& config, bool fixed_rho = false);

  std::unique_ptr<ControlLaw> clone() const override { return std::make_unique<PaperController>(*this); }
  std::string name() const override { return fixed_rho_ ? "fixed_rho" : "paper"; }
  ControllerOutput step(double t, const PoseSample& robot, const TargetSample& target,
                        const std::vector<Disk>& obstacles) override;
  // h > 0 evaluates the repulsive term of the nearest obstacle the offset point can reach
  // within h backward-Euler, at the clearance it has at the end of the step (band_implicit.h),
  // so long steps neither chatter across the detection band nor enter the disk. 0: the
  // paper's explicit (10). Ignored with moving_obstacles.
  void holdNextCommand(const CommandHold& hold) override { hold_ = hold; }

 private:
  void forgetLawState() override;
  void configureLaw() override;

  bool fixed_rho_;
  PerformanceGains gains_;
  double conflict_ = 0.0;  // second argument of the min in (13), from the last step
  int passing_side_ = 0;   // latched side of the tangential term (0 = released)
  CommandHold hold_;
};

}  // namespace core
}  // namespace amigobot_tracking
