#include "amigobot_tracking/ros/laser_obstacles.h"

#include <utility>

#include "amigobot_tracking/ros/conversions.h"

namespace amigobot_tracking {
namespace ros_layer {

LaserObstacles::LaserObstacles(tf2_ros::Buffer& tf, std::string global_frame, const core::ScanObstacleConfig& scan,
                               const core::ObstacleTrackerConfig& tracker, ros::Time epoch,
                               double future_stamp_tolerance, const LaserHealthConfig& health)
    : tf_(tf),
      global_frame_(std::move(global_frame)),
      config_(scan),
      epoch_(epoch),
      tracker_(tracker, scan.cluster_tolerance),
      rate_(health.rate),
      open_space_(health.open_space),
      age_(future_stamp_tolerance) {}

LaserObstacles::~LaserObstacles() {
  filter_.reset();  // before the subscriber it reads from
  sub_.reset();
}

void LaserObstacles::subscribe(ros::NodeHandle nh) {
  sub_ = std::make_unique<message_filters::Subscriber<sensor_msgs::LaserScan>>(nh, "scan", 5);
  filter_ = std::make_unique<tf2_ros::MessageFilter<sensor_msgs::LaserScan>>(*sub_, tf_, global_frame_, 10, nh);
  filter_->registerCallback(&LaserObstacles::onScan, this);
  filter_->registerFailureCallback(
      [this](const sensor_msgs::LaserScan::ConstPtr& scan, tf2_ros::filter_failure_reasons::FilterFailureReason why) {
        ROS_WARN_THROTTLE(5.0, "tracking: scan in '%s' dropped: no transform to '%s' at its stamp (%s)",
                          scan->header.frame_id.c_str(), global_frame_.c_str(),
                          why == tf2_ros::filter_failure_reasons::OutTheBack ? "older than the tf buffer"
                          : why == tf2_ros::filter_failure_reasons::EmptyFrameID ? "empty frame_id"
                                                                                  : "tf not available in time");
      });
}

void LaserObstacles::onScan(const sensor_msgs::LaserScan::ConstPtr& scan) {
  std::lock_guard<std::mutex> lock(latest_mutex_);
  latest_ = scan;
  latest_arrival_ = ros::Time::now();
  rate_.arrived(latest_arrival_.toSec(), scan->scan_time);
}

double LaserObstacles::update(const ros::Time& now) {
  sensor_msgs::LaserScan::ConstPtr scan;
  ros::Time arrival;
  std::string rate_problem;
  {
    std::lock_guard<std::mutex> lock(latest_mutex_);
    scan = latest_;
    arrival = latest_arrival_;
    rate_problem = rate_.problem();
  }
  if (scan && scan != processed_) {
    processed_ = scan;
    std::string refusal = core::scanBeamsProblem(toScanGeometry(*scan), scan->angle_max, scan->ranges.data(),
                                                 scan->ranges.size());
    if (refusal.empty() && !open_space_)
      refusal = core::blindScanProblem(toScanGeometry(*scan), scan->ranges.data(), scan->ranges.size());
    if (!refusal.empty()) {
      refuse(refusal, scan->header.frame_id);
    } else {
      refusal_.clear();
      try {
        // The MessageFilter let the scan through only once this transform was available.
        const geometry_msgs::TransformStamped sensor =
            tf_.lookupTransform(global_frame_, scan->header.frame_id, scan->header.stamp);
        core::scanToObstacles(toScanGeometry(*scan), scan->ranges, toAffine2d(sensor.transform), config_,
                              &disks_next_);  // cannot fail: the geometry was checked above
        disks_.swap(disks_next_);  // the previous disks stay until a good scan replaces them
        used_ = scan;
        age_.arrived(scan->header.stamp.toSec(), arrival.toSec());
        tracker_.update((scan->header.stamp - epoch_).toSec(), disks_);
      } catch (const tf2::TransformException& ex) {
        ROS_WARN_THROTTLE(5.0, "tracking: scan dropped: %s", ex.what());
      }
    }
  }
  const core::InputAge age = age_.at(now.toSec());
  if (rate_problem.empty()) {
    rate_log_.clear();
  } else if (rate_log_.due(rate_problem, "scan rate")) {  // the measured figure changes every scan
    ROS_ERROR("tracking: %s", rate_problem.c_str());
  }
  scan_problem_ = age.problem.empty() ? rate_problem : age.problem;
  return age.have ? age.age : -1.0;
}

void LaserObstacles::refuse(const std::string& why, const std::string& frame) {
  // A refused scan does not refresh the scan's age, so with require_scan the robot stops
  // after scan_timeout.
  // A blind laser's beam counts change with every scan: one kind, logged once per period.
  static const std::string blind = "laser sees nothing";
  if (refusal_.due(why, why.compare(0, blind.size(), blind) == 0 ? blind : why))
    ROS_ERROR("tracking: scan refused (frame '%s'): %s", frame.c_str(), why.c_str());
}

void LaserObstacles::obstacles(bool moving, const ros::Time& now, std::vector<core::Disk>* out) const {
  if (moving) {
    *out = tracker_.obstaclesAt((now - epoch_).toSec());
  } else {
    *out = disks_;
  }
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
