#include "amigobot_tracking/core/reference/waypoint_reference.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace amigobot_tracking {
namespace core {

WaypointReference::WaypointReference(const std::vector<Eigen::Vector2d>& waypoints, double speed, bool loop)
    : points_(waypoints), speed_(speed), loop_(loop) {
  if (points_.size() < 2) throw std::invalid_argument("waypoints needs at least 2 points");
  if (!(std::isfinite(speed) && speed > 0.0)) throw std::invalid_argument("waypoint speed must be > 0");
  if (loop_) points_.push_back(points_.front());
  arc_.assign(points_.size(), 0.0);
  for (std::size_t i = 1; i < points_.size(); ++i) {
    if (!points_[i].allFinite()) throw std::invalid_argument("waypoints must be finite");
    arc_[i] = arc_[i - 1] + (points_[i] - points_[i - 1]).norm();
  }
  if (!(arc_.back() > 0.0)) throw std::invalid_argument("waypoints are all the same point");
}

ReferenceState WaypointReference::at(double t) const {
  ReferenceState s;
  double distance = std::max(t, 0.0) * speed_;
  if (loop_) {
    distance = std::fmod(distance, arc_.back());
  } else if (distance >= arc_.back()) {
    s.position = points_.back();
    return s;
  }
  const std::size_t i =
      std::min<std::size_t>(std::upper_bound(arc_.begin(), arc_.end(), distance) - arc_.begin() - 1, arc_.size() - 2);
  const double length = arc_[i + 1] - arc_[i];
  if (length <= 0.0) {  // repeated waypoint
    s.position = points_[i];
    return s;
  }
  const Eigen::Vector2d direction = (points_[i + 1] - points_[i]) / length;
  s.position = points_[i] + (distance - arc_[i]) * direction;
  s.velocity = speed_ * direction;
  return s;
}

}  // namespace core
}  // namespace amigobot_tracking
