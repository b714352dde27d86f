// Piecewise-linear reference through waypoints at constant speed (the reference publisher's
// `waypoints` type). Eigen only, like core/reference/reference.h.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/reference/reference.h"

namespace amigobot_tracking {
namespace core {

// Moves from waypoint to waypoint in straight lines at `speed` [m/s]. At the end it stops
// on the last waypoint, or with `loop` drives back to the first one and starts again.
// Throws std::invalid_argument for fewer than 2 waypoints, speed <= 0, or a zero-length path.
class WaypointReference : public Reference {
 public:
  WaypointReference(const std::vector<Eigen::Vector2d>& waypoints, double speed, bool loop);
  ReferenceState at(double t) const override;
  double period() const { return arc_.back() / speed_; }  // [s] one pass (or one lap)

 private:
  std::vector<Eigen::Vector2d> points_;  // with the first point appended when looping
  std::vector<double> arc_;              // cumulative length at each point [m]
  double speed_;
  bool loop_;
};

}  // namespace core
}  // namespace amigobot_tracking
