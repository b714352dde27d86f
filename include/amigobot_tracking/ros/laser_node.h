// ROS wrapper of the laser driver (sensors::LaserDriver): publishes `scan`
// (sensor_msgs/LaserScan, laser_scan.h) and /diagnostics (scan rate through FrequencyStatus,
// device identity, counters, last error). The device I/O runs on its own thread; the
// destructor stops it and closes the device. Shared by the nodelet amigobot_tracking/Laser
// and the node laser_node. An RPLIDAR's motor: the services start_motor and stop_motor
// (std_srvs/Empty, as rplidar_ros).
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>
#include <std_srvs/Empty.h>

#include "amigobot_tracking/ros/laser_scan.h"
#include "amigobot_tracking/ros/rate_monitor.h"
#include "amigobot_tracking/ros/refusal_log.h"

namespace amigobot_tracking {
namespace ros_layer {

class LaserNode {
 public:
  static constexpr double kLinkLogPeriod = 10.0;  // [s] the same failure again on the console

  // Throws std::runtime_error naming a bad parameter; then nothing is started.
  LaserNode(ros::NodeHandle nh, ros::NodeHandle pnh);
  ~LaserNode();
  LaserNode(const LaserNode&) = delete;
  LaserNode& operator=(const LaserNode&) = delete;

 private:
  void loop();  // I/O thread
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);
  void reportLink(bool got_scan);  // the console's lines about the device (mutex_ held)
  bool onMotor(bool on);

  LaserParams params_;
  ros::NodeHandle nh_, pnh_;
  ros::Publisher scan_pub_;
  ros::ServiceServer start_motor_srv_, stop_motor_srv_;  // rplidar only
  std::atomic<bool> motor_wanted_{true};
  diagnostic_updater::Updater updater_;
  std::unique_ptr<RateMonitor> rate_;
  ros::Timer diagnostics_timer_;
  std::mutex mutex_;  // guards the copies below and rate_
  std::string identity_, last_error_;
  sensors::LaserDriverCounters counters_;
  bool connected_ = false;
  RefusalLog link_log_{kLinkLogPeriod};  // the reason last logged, "" while streaming
  std::uint64_t skipped_ = 0;  // scans the crop emptied
  std::atomic<bool> stop_{false};
  std::thread io_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
