// What the tracking node keeps of its laser, without ROS: whether a scan may be used, the
// last usable scan's disks in the global frame, the tracker that follows them across scans
// (moving_obstacles), and how old the last used scan is (supervision: it judges freshness).
// The ROS side (ros/laser_obstacles.h) only subscribes, looks up the sensor's pose at the
// scan's stamp and logs refusals.
//
// Rules: a scan whose beams are unusable (scanBeamsProblem) or that sees nothing at all
// (blindScanProblem; unless open_space: an empty room) is refused: the previous disks stay and
// its stamp does not count as fresh, so a blind laser cannot hide behind a steady stream of
// scans. Times are plain seconds on the node's clock; the tracker counts from `epoch`.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "amigobot_tracking/core/perception/obstacle_tracker.h"
#include "amigobot_tracking/core/perception/scan_obstacles.h"
#include "amigobot_tracking/core/supervision/input_age.h"

namespace amigobot_tracking {
namespace core {

class ScanIntake {
 public:
  ScanIntake(const ScanObstacleConfig& scan, const ObstacleTrackerConfig& tracker, double epoch,
             double future_stamp_tolerance = 0.1, bool open_space = false);

  // Why this scan cannot be used, naming the field, or "" when it can (then take() it).
  std::string refusal(const ScanGeometry& geometry, double angle_max, const float* ranges, std::size_t count) const;
  // A usable scan, stamped `stamp`, that arrived at `arrival`, seen from `sensor_to_global`:
  // its disks replace the previous ones, the tracker and the age take it.
  void take(const ScanGeometry& geometry, const float* ranges, std::size_t count,
            const Eigen::Affine2d& sensor_to_global, double stamp, double arrival);

  // The last used scan's age at `now` (InputAge: +inf for a stamp of 0 or in the future).
  InputAge age(double now) const { return age_.at(now); }
  // The laser obstacles at `now`: the last used scan's disks, or with `moving` the tracked
  // disks with their velocities, moved to `now`.
  void obstacles(bool moving, double now, std::vector<Disk>* out) const;
  const std::vector<Disk>& disks() const { return disks_; }

 private:
  const ScanObstacleConfig config_;
  const double epoch_;
  const bool open_space_;
  ObstacleTracker tracker_;
  InputAgeTracker age_;
  std::vector<Disk> disks_, disks_next_;  // disks_next_: scratch for the next scan
  std::vector<ScanCluster> clusters_;     // the last used scan's clusters over disks_, for the tracker
};

}  // namespace core
}  // namespace amigobot_tracking
