// Mapping that closes loops: a pose graph of keyframes. Each scan is aligned by ICP (MRPT's
// CICP) against the points of the keyframes of the last 10 m of travel (a local submap), from
// the odometry-predicted pose; every graph/keyframe_travel of travel (or 0.35 rad of turn) it
// becomes a keyframe, joined to the previous one by the aligned motion. A new keyframe is then
// matched against the 3 nearest old places within graph/loop_radius (at least
// graph/loop_min_gap keyframes back): an ICP alignment on which at least graph/loop_min_match of
// its points lie within match_distance of the old keyframes' points, that fits clearly worse
// when turned 0.1 rad and corrects no more than the front end can have drifted, is a loop edge
// (Huber-weighted). When shifting it 0.3 m fits as well in one direction only (a corridor), the
// edge fixes the position across that direction and the heading, not along it; when in two
// directions, it is refused. The graph is then optimised (PoseGraph).
// The map is drawn from the optimised keyframe poses. Not thread-safe: one caller.
#pragma once

#include <memory>
#include <vector>

#include "amigobot_tracking/localization/localization_config.h"
#include "amigobot_tracking/localization/occupancy_map.h"
#include "amigobot_tracking/localization/pose_graph.h"
#include "amigobot_tracking/localization/range_scan.h"

namespace mrpt::maps {
class CSimplePointsMap;
}

namespace amigobot_tracking {
namespace localization {

struct PoseEstimate;

class GraphMapper {
 public:
  explicit GraphMapper(const LocalizationConfig& config);
  ~GraphMapper();
  GraphMapper(const GraphMapper&) = delete;
  GraphMapper& operator=(const GraphMapper&) = delete;

  // One scan taken when odometry said odom_base; fills `estimate` (pose, map -> odom, covariance).
  void update(const RangeScan& scan, const core::Pose2& odom_base, PoseEstimate* estimate);
  OccupancyMap map() const;
  // The pose of every scan so far, from its keyframe's optimised pose (loops closed later
  // move earlier scans too).
  std::vector<core::Pose2> trajectory() const;
  int loopClosures() const { return loops_; }
  int keyframes() const { return static_cast<int>(keyframes_.size()); }

 private:
  struct Keyframe {
    RangeScan scan;
    std::vector<Eigen::Vector2d> points;  // base frame, decimated
  };
  struct ScanPose {
    int keyframe;        // the keyframe the scan was aligned after
    core::Pose2 offset;  // its pose in that keyframe's frame
  };
  // The points of keyframes [first, last] in the map frame.
  void collectPoints(int first, int last, mrpt::maps::CSimplePointsMap* out) const;
  // ICP of base-frame points against `reference` from `guess`; goodness in [0, 1].
  core::Pose2 align(const mrpt::maps::CSimplePointsMap& reference, const std::vector<Eigen::Vector2d>& points,
                    const core::Pose2& guess, double first_pairing, Eigen::Matrix3d* covariance, double* goodness) const;
  double matchFraction(const mrpt::maps::CSimplePointsMap& reference, const std::vector<Eigen::Vector2d>& points,
                       const core::Pose2& pose) const;
  void addKeyframe(const RangeScan& scan, const std::vector<Eigen::Vector2d>& points);
  bool closeLoop(int keyframe);
  // ICP of keyframe k against old keyframe `old` and its neighbours; true and the edge when it is a loop.
  bool matchLoop(int k, int old, PoseGraphEdge* edge) const;

  LocalizationConfig config_;
  PoseGraph graph_;
  std::vector<Keyframe> keyframes_;
  std::vector<ScanPose> scans_;
  std::vector<double> path_;  // [m] travel from the first keyframe to each
  core::Pose2 pose_, last_odom_, last_match_odom_;
  Eigen::Matrix3d covariance_ = Eigen::Matrix3d::Zero();
  int loops_ = 0;
};

}  // namespace localization
}  // namespace amigobot_tracking
