#include "amigobot_tracking/core/supervision/scan_intake.h"

#include "amigobot_tracking/core/perception/scan_health.h"

namespace amigobot_tracking {
namespace core {

ScanIntake::ScanIntake(const ScanObstacleConfig& scan, const ObstacleTrackerConfig& tracker, double epoch,
                       double future_stamp_tolerance, bool open_space)
    : config_(scan),
      epoch_(epoch),
      open_space_(open_space),
      tracker_(tracker, scan.cluster_tolerance),
      age_(future_stamp_tolerance) {}

std::string ScanIntake::refusal(const ScanGeometry& geometry, double angle_max, const float* ranges,
                                std::size_t count) const {
  std::string why = scanBeamsProblem(geometry, angle_max, ranges, count);
  if (why.empty() && !open_space_) why = blindScanProblem(geometry, ranges, count);
  return why;
}

void ScanIntake::take(const ScanGeometry& geometry, const float* ranges, std::size_t count,
                      const Eigen::Affine2d& sensor_to_global, double stamp, double arrival) {
  if (!scanToObstacles(geometry, ranges, count, sensor_to_global, config_, &disks_next_, nullptr, &clusters_)) return;
  disks_.swap(disks_next_);
  age_.arrived(stamp, arrival);
  tracker_.update(stamp - epoch_, disks_, &clusters_);
}

void ScanIntake::obstacles(bool moving, double now, std::vector<Disk>* out) const {
  if (moving) {
    *out = tracker_.obstaclesAt(now - epoch_);
  } else {
    *out = disks_;
  }
}

}  // namespace core
}  // namespace amigobot_tracking
