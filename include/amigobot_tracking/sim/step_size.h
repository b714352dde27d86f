// Variable time step of the offline closed loop: long steps where nothing is close,
// the fine step wherever the result could depend on it.
//
// The offset point moves at most max(v_max, r w_max) and the body at most v_max inside
// the diamond, so a step no longer than (distance to the nearest detection band or body
// contact) / (that speed + the fastest obstacle's speed) cannot jump through the band of
// width delta: near obstacles the loop falls back to the fine step. The step also shrinks
// linearly from max_step at |e|/rho <= comfortable_ratio to min_step at tight_ratio, so the
// performance bound is resolved finely whenever it is close to active. Inside a detection
// band, where (10) is stiff (1/margin), only the fine step is used. (That is the explicit
// integrator's situation; band_implicit and second_order, closed_loop.h, treat the band
// implicitly and pass only |e|/rho.)
#pragma once

namespace amigobot_tracking {
namespace sim {

struct StepPolicy {
  double min_step = 1e-3;          // [s] the fine step (near obstacles, tight envelope)
  double max_step = 1e-3;          // [s] the longest step; == min_step: fixed step
  double comfortable_ratio = 0.5;  // |e|/rho at or below which max_step is allowed
  double tight_ratio = 0.9;        // |e|/rho at or above which only min_step is
};

struct StepSituation {
  double distance = 0.0;     // [m] to the nearest detection band not yet entered, or to body
                             // contact (+inf: none)
  double max_speed = 0.0;    // [m/s] bound on the closing speed
  double error_ratio = 0.0;  // |e|/rho (0 when the law has no rho)
  bool in_band = false;      // the offset point is inside a detection band
};

// In [min_step, max_step]; pure.
double chooseStep(const StepPolicy& policy, const StepSituation& situation);

}  // namespace sim
}  // namespace amigobot_tracking
