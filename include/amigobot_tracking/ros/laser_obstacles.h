// Laser scans -> obstacle disks in the global frame for the tracking node: the ROS wiring of
// core/supervision/scan_intake.h (which scans are used, their disks, the tracker, their age).
// `scan` arrives through a tf2 MessageFilter (a scan is used only once its transform is known);
// the callback only stores the latest scan under this class's mutex, and the control cycle
// hands it to the intake with the sensor's pose at its stamp, and logs refusals.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <message_filters/subscriber.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/message_filter.h>

#include "amigobot_tracking/core/perception/obstacle_tracker.h"
#include "amigobot_tracking/core/perception/scan_health.h"
#include "amigobot_tracking/core/perception/scan_obstacles.h"
#include "amigobot_tracking/core/supervision/scan_intake.h"
#include "amigobot_tracking/ros/refusal_log.h"

namespace amigobot_tracking {
namespace ros_layer {

// Is the laser still seeing (core/perception/scan_health.h)?
struct LaserHealthConfig {
  bool open_space = false;  // a scan with no return is an empty room, not a blind laser
  core::ScanRateConfig rate;
};

class LaserObstacles {
 public:
  // Times [s] given to the tracker count from `epoch`.
  LaserObstacles(tf2_ros::Buffer& tf, std::string global_frame, const core::ScanObstacleConfig& scan,
                 const core::ObstacleTrackerConfig& tracker, ros::Time epoch, double future_stamp_tolerance = 0.1,
                 const LaserHealthConfig& health = LaserHealthConfig());
  LaserObstacles(const LaserObstacles&) = delete;
  LaserObstacles& operator=(const LaserObstacles&) = delete;
  ~LaserObstacles();

  // Subscribes to `scan` in nh's namespace (through the MessageFilter).
  void subscribe(ros::NodeHandle nh);
  // Stores the scan (the filter's callback; public for the benchmark).
  void onScan(const sensor_msgs::LaserScan::ConstPtr& scan);

  // In the control cycle: turns a new scan into disks; returns the age [s] at `now` of the
  // last scan turned into disks, -1 when none was yet. A bad scan keeps the previous disks
  // and does not count as fresh: it must not hide a blind laser; a scan that sees nothing
  // is refused so too, unless open_space. The age is taken on this node's clock
  // (core/supervision/input_age.h): +inf for a scan stamped 0 or in the future.
  double update(const ros::Time& now);
  // Why the scans cannot be trusted now (their stamp, or too few of them: the rate), or "".
  const std::string& scanProblem() const { return scan_problem_; }
  // Why the last scan looked at was refused, naming the field (core::scanBeamsProblem), or
  // "" when it was used.
  const std::string& refusal() const { return refusal_.last(); }
  // *out = the laser obstacles at `now`: the last scan's disks, or with `moving` the
  // tracked disks with their velocities.
  void obstacles(bool moving, const ros::Time& now, std::vector<core::Disk>* out) const;
  const std::vector<core::Disk>& disks() const { return intake_.disks(); }  // last used scan's

 private:
  tf2_ros::Buffer& tf_;
  const std::string global_frame_;
  core::ScanIntake intake_;  // the control cycle's

  std::mutex latest_mutex_;
  sensor_msgs::LaserScan::ConstPtr latest_;  // written by onScan only
  ros::Time latest_arrival_;                 // when it arrived, on this node's clock
  core::ScanRateJudge rate_;                 // every arrival counts, also those update() skips

  // The control cycle's (the caller serialises update and obstacles).
  sensor_msgs::LaserScan::ConstPtr processed_;  // last scan looked at
  std::string scan_problem_;
  RefusalLog refusal_, rate_log_;

  void refuse(const std::string& why, const std::string& frame);

  std::unique_ptr<message_filters::Subscriber<sensor_msgs::LaserScan>> sub_;
  std::unique_ptr<tf2_ros::MessageFilter<sensor_msgs::LaserScan>> filter_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
