#include "amigobot_tracking/core/robot/offset_point.h"

#include <cmath>

namespace amigobot_tracking {
namespace core {

Eigen::Vector2d offsetPoint(const Pose2& pose, double offset) {
  return {pose.x + offset * std::cos(pose.theta), pose.y + offset * std::sin(pose.theta)};
}

Eigen::Matrix2d offsetJacobian(double theta, double offset) {
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d g;
  g << c, -offset * s, s, offset * c;
  return g;
}

Eigen::Matrix2d offsetJacobianInverse(double theta, double offset) {
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d g_inv;
  g_inv << c, s, -s / offset, c / offset;
  return g_inv;
}

Twist2 offsetVelocityToTwist(const Eigen::Vector2d& u_r, double theta, double offset) {
  return offsetVelocityToTwist(u_r, Eigen::Vector2d(std::cos(theta), std::sin(theta)), offset);
}

Eigen::Vector2d twistToOffsetVelocity(const Twist2& u, double theta, double offset) {
  return offsetJacobian(theta, offset) * Eigen::Vector2d(u.v, u.omega);
}

}  // namespace core
}  // namespace amigobot_tracking
