#include "amigobot_tracking/core/avoidance.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace amigobot_tracking {
namespace core {

AvoidanceResult repulsiveTerm(const Eigen::Vector2d& p_r, const std::vector<Disk>& obstacles,
                              double robot_radius, double delta, const Eigen::Vector2d& heading_hint,
                              double min_margin) {
  AvoidanceResult result;
  result.min_clearance = std::numeric_limits<double>::infinity();
  for (const Disk& obstacle : obstacles) {
    Eigen::Vector2d away = p_r - obstacle.center;
    double distance = away.norm();
    const double contact = robot_radius + obstacle.radius;
    result.min_clearance = std::min(result.min_clearance, distance - contact);
    if (distance > delta + contact) continue;
    ++result.detected;
    if (distance < 1e-9) {  // on the centre: any direction is as good; back off
      away = -heading_hint.normalized() * 1e-9;
      distance = 1e-9;
    }
    const double margin = std::max(distance - contact, min_margin);
    result.u_c += (1.0 / margin - 1.0 / delta) * away;
  }
  return result;
}

double clearance(const Eigen::Vector2d& center, double radius, const std::vector<Disk>& obstacles) {
  double best = std::numeric_limits<double>::infinity();
  for (const Disk& obstacle : obstacles) {
    best = std::min(best, (center - obstacle.center).norm() - radius - obstacle.radius);
  }
  return best;
}

}  // namespace core
}  // namespace amigobot_tracking
