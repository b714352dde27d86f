// Feedback linearisation at an offset point p_r = p + r (cos th, sin th), eqs. (5)-(8):
// p_r' = G(th) (v, w)^T, so (v, w)^T = G(th)^-1 u_r turns a planar velocity u_r of the
// offset point into unicycle inputs.
#pragma once

#include <Eigen/Core>

#include "amigobot_tracking/core/support/types.h"

namespace amigobot_tracking {
namespace core {

Eigen::Vector2d offsetPoint(const Pose2& pose, double offset);
// G(th) = [[cos th, -r sin th], [sin th, r cos th]].
Eigen::Matrix2d offsetJacobian(double theta, double offset);
// G(th)^-1 = [[cos th, sin th], [-sin th / r, cos th / r]] (r > 0).
Eigen::Matrix2d offsetJacobianInverse(double theta, double offset);
// (v, w) = G^-1 u_r.
Twist2 offsetVelocityToTwist(const Eigen::Vector2d& u_r, double theta, double offset);
// The same with heading = (cos th, sin th) already at hand (one sincos per control step).
inline Twist2 offsetVelocityToTwist(const Eigen::Vector2d& u_r, const Eigen::Vector2d& heading, double offset) {
  return {heading.x() * u_r.x() + heading.y() * u_r.y(), (-heading.y() * u_r.x() + heading.x() * u_r.y()) / offset};
}
// u_r = G (v, w).
Eigen::Vector2d twistToOffsetVelocity(const Twist2& u, double theta, double offset);

}  // namespace core
}  // namespace amigobot_tracking
