// Distance from every cell of an occupancy map to its nearest occupied cell (exact Euclidean
// transform), and the two figures the localisation draws from it for scan points placed at a
// pose: the fraction of points on the map (within match_distance of an obstacle) and a
// smooth likelihood-field score used to rank the candidates of a global search.
#pragma once

#include <vector>

#include "amigobot_tracking/core/support/types.h"
#include "amigobot_tracking/localization/occupancy_map.h"

namespace amigobot_tracking {
namespace localization {

class DistanceField {
 public:
  // `cap` [m]: distances are clamped to it (and off-map points are `cap` away).
  DistanceField(const OccupancyMap& map, double cap);

  double distance(double x, double y) const;  // [m] map-frame point
  // Fraction of base-frame points that, at `pose`, lie within match_distance of an obstacle.
  double matchFraction(const std::vector<Eigen::Vector2d>& points, const core::Pose2& pose, double match_distance) const;
  // Mean of exp(-d^2 / (2 sigma^2)) over the points at `pose`, in [0, 1].
  double score(const std::vector<Eigen::Vector2d>& points, const core::Pose2& pose, double sigma) const;
  const OccupancyMap& map() const { return map_; }

 private:
  OccupancyMap map_;  // geometry and cells
  double cap_;
  std::vector<float> distance_;  // [m] per cell
};

}  // namespace localization
}  // namespace amigobot_tracking
