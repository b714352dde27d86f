#include "amigobot_tracking/core/supervision/resume_ramp.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace amigobot_tracking {
namespace core {
namespace {

// Largest s in [0, 1] for one component: |s d| within `step` of p, or between 0 and p.
double componentScale(double desired, double previous, double step) {
  if (desired == 0.0) return 1.0;
  const bool same_side = previous == 0.0 || (desired > 0.0) == (previous > 0.0);
  // Same side: up to |p| + step. Across zero: only what is left of step after reaching 0.
  const double reach = same_side ? std::abs(previous) + step : std::max(0.0, step - std::abs(previous));
  return std::min(1.0, reach / std::abs(desired));
}

}  // namespace

std::string RampLimits::validate() const {
  std::ostringstream err;
  if (!(std::isfinite(v_accel) && v_accel > 0.0)) {
    err << "v_accel must be a finite number > 0, got " << v_accel;
  } else if (!(std::isfinite(w_accel) && w_accel > 0.0)) {
    err << "w_accel must be a finite number > 0, got " << w_accel;
  }
  return err.str();
}

RampStep rampTowards(const Twist2& desired, const Twist2& previous, const RampLimits& limits, double dt) {
  RampStep r;
  if (!desired.isFinite() || !previous.isFinite() || !std::isfinite(dt) || dt < 0.0) {
    r.limited = true;
    return r;
  }
  double s = std::min(componentScale(desired.v, previous.v, limits.v_accel * dt),
                      componentScale(desired.omega, previous.omega, limits.w_accel * dt));
  if (s > 1.0 - 1e-9) s = 1.0;  // rounding of the reach must not stretch the ramp by a period
  r.u = {s * desired.v, s * desired.omega};
  r.limited = s < 1.0;
  return r;
}

}  // namespace core
}  // namespace amigobot_tracking
