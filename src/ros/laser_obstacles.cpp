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
      intake_(scan, tracker, epoch.toSec(), future_stamp_tolerance, health.open_space),
      rate_(health.rate) {}

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
    const std::string refusal =
        intake_.refusal(toScanGeometry(*scan), scan->angle_max, scan->ranges.data(), scan->ranges.size());
    if (!refusal.empty()) {
      refuse(refusal, scan->header.frame_id);
    } else {
      refusal_.clear();
      try {
        // The MessageFilter let the scan through only once this transform was available.
        const geometry_msgs::TransformStamped sensor =
            tf_.lookupTransform(global_frame_, scan->header.frame_id, scan->header.stamp);
        intake_.take(toScanGeometry(*scan), scan->ranges.data(), scan->ranges.size(), toAffine2d(sensor.transform),
                     scan->header.stamp.toSec(), arrival.toSec());
      } catch (const tf2::TransformException& ex) {
        ROS_WARN_THROTTLE(5.0, "tracking: scan dropped: %s", ex.what());
      }
    }
  }
  const core::InputAge age = intake_.age(now.toSec());
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
  intake_.obstacles(moving, now.toSec(), out);
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
