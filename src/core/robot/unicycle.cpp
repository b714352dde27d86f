#include "amigobot_tracking/core/robot/unicycle.h"

#include <cmath>

#include "amigobot_tracking/core/support/small_angle.h"

namespace amigobot_tracking {
namespace core {

Pose2 integrateUnicycle(const Pose2& pose, const Twist2& u, double h) {
  return integrateUnicycle(pose, Eigen::Vector2d(std::cos(pose.theta), std::sin(pose.theta)), u, h);
}

Pose2 integrateUnicycle(const Pose2& pose, const Eigen::Vector2d& heading, const Twist2& u, double h) {
  // The exact arc as run * (R(theta) (sinc, cosc)): the turn by series (small_angle.h) and no
  // cancellation of sin(theta + dtheta) - sin(theta).
  const double dtheta = u.omega * h;
  const double run = u.v * h;
  double sinc, cosc;
  sincCosc(dtheta, &sinc, &cosc);
  const double c = heading.x(), s = heading.y();
  Pose2 next;
  next.x = pose.x + run * (c * sinc - s * cosc);
  next.y = pose.y + run * (s * sinc + c * cosc);
  next.theta = wrapAngle(pose.theta + dtheta);
  return next;
}

}  // namespace core
}  // namespace amigobot_tracking
