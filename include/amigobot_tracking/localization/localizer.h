// Localisation on a known occupancy map: each scan is aligned by ICP (MRPT's CICP) against
// the map's occupied cells from the odometry-predicted pose, when the robot has moved enough
// since the last match (min_travel / min_rotation) or has not settled since a new pose; in
// between, odometry alone carries the pose. The state is the correction map -> odom, so the
// odometry between scans needs no model. relocalize() searches the whole free space
// (candidate poses ranked by the map's likelihood field, the best refined by ICP) for a
// kidnapped robot. Not thread-safe: one caller.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/localization/distance_field.h"
#include "amigobot_tracking/localization/localization_config.h"
#include "amigobot_tracking/localization/pose_estimate.h"
#include "amigobot_tracking/localization/range_scan.h"

namespace mrpt::maps {
class CSimplePointsMap;
}

namespace amigobot_tracking {
namespace localization {



class Localizer {
 public:
  // Throws std::invalid_argument for an empty map or a map without occupied cells.
  Localizer(const LocalizationConfig& config, const OccupancyMap& map);
  ~Localizer();
  Localizer(const Localizer&) = delete;
  Localizer& operator=(const Localizer&) = delete;

  // The robot is at map_base while odometry says odom_base (initial pose, /initialpose).
  void setPose(const core::Pose2& map_base, const core::Pose2& odom_base);
  // One scan taken when odometry said odom_base.
  const PoseEstimate& update(const RangeScan& scan, const core::Pose2& odom_base);
  // Global search; on success the pose is set (one jump) and the next scans refine it.
  GlobalSearch relocalize(const RangeScan& scan, const core::Pose2& odom_base);

  const PoseEstimate& estimate() const { return estimate_; }
  const OccupancyMap& map() const { return field_.map(); }

 private:
  // ICP of base-frame points from `guess`; fills covariance and goodness.
  core::Pose2 align(const std::vector<Eigen::Vector2d>& points, const core::Pose2& guess, Eigen::Matrix3d* covariance,
                    double* goodness) const;

  LocalizationConfig config_;
  DistanceField field_;
  std::unique_ptr<mrpt::maps::CSimplePointsMap> map_points_;  // occupied cell centres
  PoseEstimate estimate_;
  core::Pose2 last_match_odom_;
  Eigen::Matrix3d match_covariance_;  // of the last match
  bool settled_ = false;             // the last match moved the pose by less than a cell
};

}  // namespace localization
}  // namespace amigobot_tracking
