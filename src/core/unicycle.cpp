#include "amigobot_tracking/core/unicycle.h"

#include <cmath>

namespace amigobot_tracking {
namespace core {

Pose2 integrateUnicycle(const Pose2& pose, const Twist2& u, double h) {
  const double dtheta = u.omega * h;
  Pose2 next;
  if (std::abs(dtheta) < 1e-9) {
    // Second-order expansion of the arc: exact to rounding for tiny turns.
    const double mid = pose.theta + 0.5 * dtheta;
    next.x = pose.x + u.v * h * std::cos(mid);
    next.y = pose.y + u.v * h * std::sin(mid);
  } else {
    const double radius = u.v / u.omega;
    next.x = pose.x + radius * (std::sin(pose.theta + dtheta) - std::sin(pose.theta));
    next.y = pose.y - radius * (std::cos(pose.theta + dtheta) - std::cos(pose.theta));
  }
  next.theta = wrapAngle(pose.theta + dtheta);
  return next;
}

}  // namespace core
}  // namespace amigobot_tracking
