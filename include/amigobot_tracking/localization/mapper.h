// Mapping: ICP-SLAM over MRPT's CMetricMapBuilderICP (a point map to match scans against and
// an occupancy grid to publish and save), fed with each scan and the odometry increment since
// the previous one. The map frame is where the robot was at the first scan, moved by
// config.initial_pose. Not thread-safe: one caller (map() may be called between updates).
#pragma once

#include <memory>

#include <mrpt/core/Clock.h>

#include "amigobot_tracking/localization/localization_config.h"
#include "amigobot_tracking/localization/occupancy_map.h"
#include "amigobot_tracking/localization/range_scan.h"

namespace mrpt::slam {
class CMetricMapBuilderICP;
}

namespace amigobot_tracking {
namespace localization {

struct MappingEstimate {
  core::Pose2 pose;         // map -> base
  core::Pose2 map_to_odom;  // the correction published as tf
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  // [m^2, rad^2] of (x, y, yaw)
  int scans = 0;            // scans processed
};

class Mapper {
 public:
  explicit Mapper(const LocalizationConfig& config);
  ~Mapper();
  Mapper(const Mapper&) = delete;
  Mapper& operator=(const Mapper&) = delete;

  // One scan taken when odometry said odom_base.
  const MappingEstimate& update(const RangeScan& scan, const core::Pose2& odom_base);
  const MappingEstimate& estimate() const { return estimate_; }
  // The grid so far, trinary (occupied >= 60 %, free <= 40 %, else unknown); empty before
  // the first scan.
  OccupancyMap map() const;

 private:
  LocalizationConfig config_;
  std::unique_ptr<mrpt::slam::CMetricMapBuilderICP> builder_;
  MappingEstimate estimate_;
  core::Pose2 last_odom_;
  mrpt::Clock::time_point clock_origin_;  // MRPT's clock at initialize()
  double first_stamp_ = 0.0, elapsed_ = 0.0;  // [s] the first scan's stamp, the last one's since
};

}  // namespace localization
}  // namespace amigobot_tracking
