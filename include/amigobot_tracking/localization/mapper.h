// Mapping, one of two methods (config.mapping_method):
// - icp: ICP-SLAM over MRPT's CMetricMapBuilderICP (a point map to match scans against and an
//   occupancy grid to publish and save), fed with each scan and the odometry increment since
//   the previous one; it never closes a loop;
// - graph: GraphMapper's pose graph of keyframes, which closes loops.
// The map frame is where the robot was at the first scan, moved by config.initial_pose.
// Not thread-safe: one caller (map() may be called between updates).
#pragma once

#include <memory>
#include <vector>

#include <mrpt/core/Clock.h>

#include "amigobot_tracking/localization/localization_config.h"
#include "amigobot_tracking/localization/occupancy_map.h"
#include "amigobot_tracking/localization/pose_estimate.h"
#include "amigobot_tracking/localization/range_scan.h"

namespace mrpt::slam {
class CMetricMapBuilderICP;
}

namespace amigobot_tracking {
namespace localization {

class GraphMapper;


class Mapper {
 public:
  explicit Mapper(const LocalizationConfig& config);
  ~Mapper();
  Mapper(const Mapper&) = delete;
  Mapper& operator=(const Mapper&) = delete;

  // One scan taken when odometry said odom_base.
  const PoseEstimate& update(const RangeScan& scan, const core::Pose2& odom_base);
  const PoseEstimate& estimate() const { return estimate_; }
  // The grid so far, trinary (occupied >= 60 %, free <= 40 %, else unknown); empty before
  // the first scan.
  OccupancyMap map() const;
  // The pose of every scan so far: icp, as estimated at the time; graph, as optimised now.
  std::vector<core::Pose2> trajectory() const;
  int loopClosures() const;  // always 0 for icp

 private:
  LocalizationConfig config_;
  std::unique_ptr<mrpt::slam::CMetricMapBuilderICP> builder_;  // icp
  std::unique_ptr<GraphMapper> graph_;                         // graph
  std::vector<core::Pose2> trajectory_;                        // icp
  PoseEstimate estimate_;
  core::Pose2 last_odom_;
  mrpt::Clock::time_point clock_origin_;  // MRPT's clock at initialize()
  double first_stamp_ = 0.0, elapsed_ = 0.0;  // [s] the first scan's stamp, the last one's since
};

}  // namespace localization
}  // namespace amigobot_tracking
