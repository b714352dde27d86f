#include "amigobot_tracking/sim/step_size.h"

#include <algorithm>
#include <cmath>

namespace amigobot_tracking {
namespace sim {

double chooseStep(const StepPolicy& policy, const StepSituation& s) {
  const double lo = policy.min_step, hi = std::max(policy.min_step, policy.max_step);
  if (hi <= lo) return lo;
  double h = hi;
  if (s.max_speed > 0.0 && !(s.distance >= h * s.max_speed)) h = std::max(0.0, s.distance) / s.max_speed;
  // Inside a band (10) is stiff (1/margin): longer steps chatter along the band even when
  // sliding tangentially (measured: 4x the control energy of the fine step on paper_5_1).
  if (s.in_band) h = lo;
  const double span = policy.tight_ratio - policy.comfortable_ratio;
  const double room = span > 0.0 ? (policy.tight_ratio - s.error_ratio) / span : 1.0;
  h = std::min(h, lo + std::clamp(room, 0.0, 1.0) * (hi - lo));
  return std::clamp(std::isfinite(h) ? h : lo, lo, hi);
}

}  // namespace sim
}  // namespace amigobot_tracking
