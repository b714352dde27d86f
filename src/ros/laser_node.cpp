#include "amigobot_tracking/ros/laser_node.h"

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <sensor_msgs/LaserScan.h>

#include "amigobot_tracking/sensors/laser_model.h"
#include "amigobot_tracking/sensors/laser_protocol.h"

namespace amigobot_tracking {
namespace ros_layer {

LaserNode::LaserNode(ros::NodeHandle nh, ros::NodeHandle pnh)
    : params_(loadLaserParams(pnh)), nh_(nh), pnh_(pnh), updater_(nh, pnh) {
  const double rate = params_.expected_rate > 0.0 ? params_.expected_rate : sensors::laserModel(params_.driver.model).rate;
  rate_ = std::make_unique<RateMonitor>("scans", "scan rate [Hz]", rate, rate, 0.2, 10);
  scan_pub_ = nh_.advertise<sensor_msgs::LaserScan>("scan", 5);
  updater_.setHardwareID(params_.driver.model + " at " + params_.driver.port);
  updater_.add("Laser " + params_.driver.model, this, &LaserNode::diagnose);
  diagnostics_timer_ = nh_.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { updater_.update(); });
  if (sensors::protocolOf(sensors::laserModel(params_.driver.model)).hasMotor()) {
    using Empty = std_srvs::Empty;
    start_motor_srv_ = nh_.advertiseService<Empty::Request, Empty::Response>(
        "start_motor", [this](Empty::Request&, Empty::Response&) { return onMotor(true); });
    stop_motor_srv_ = nh_.advertiseService<Empty::Request, Empty::Response>(
        "stop_motor", [this](Empty::Request&, Empty::Response&) { return onMotor(false); });
  }
  io_ = std::thread([this] { loop(); });
}

LaserNode::~LaserNode() {
  stop_ = true;
  if (io_.joinable()) io_.join();
  diagnostics_timer_.stop();
}

void LaserNode::loop() {
  sensors::LaserDriver driver(params_.driver);
  sensors::LaserScanData scan;
  sensor_msgs::LaserScan msg;
  double last_stamp = 0.0;
  while (!stop_ && ros::ok()) {
    driver.requestMotor(motor_wanted_);
    const bool got = driver.poll(&scan, 0.1);
    bool publish = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      identity_ = driver.identity();
      last_error_ = driver.lastError();
      counters_ = driver.counters();
      connected_ = driver.connected();
      reportLink(got);
      if (got) {
        // A scan is published once and never older than the last one: after a reconnect the
        // device clock restarts, but the stamps come from the host clock.
        if (scan.stamp <= last_stamp || !toLaserScan(scan, params_, &msg)) {
          ++skipped_;
        } else {
          last_stamp = scan.stamp;
          rate_->tick();
          publish = true;
        }
      }
    }
    if (publish) scan_pub_.publish(msg);
  }
  driver.close();
}

// Diagnostics alone are easy to miss (a laser on a wrong port was silent on the console for
// 15 s): a laser that cannot be opened or is lost is an ERROR naming its model, port and the
// reason, at once when the reason changes, then every kLinkLogPeriod while it lasts; an INFO
// when scans flow again.
void LaserNode::reportLink(bool got_scan) {
  const std::string device = "laser " + params_.driver.model + " on " + params_.driver.port;
  if (!connected_ && !last_error_.empty()) {
    if (link_log_.due(last_error_)) {
      ROS_ERROR_STREAM_NAMED("laser", device << " not connected: " << last_error_ << " (reopening with back-off; no scans)");
    }
  } else if (got_scan && !link_log_.last().empty()) {
    ROS_INFO_STREAM_NAMED("laser", device << ": scans again (" << identity_ << ")");
    link_log_.clear();
  }
}

bool LaserNode::onMotor(bool on) {
  motor_wanted_ = on;  // the I/O thread tells the device
  ROS_INFO_STREAM_NAMED("laser", params_.driver.model << " at " << params_.driver.port << ": motor "
                                                      << (on ? "started (start_motor)" : "stopped (stop_motor)"));
  return true;
}

void LaserNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (connected_ && !motor_wanted_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "motor stopped (stop_motor): no scans until start_motor");
  } else if (connected_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "streaming");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "not connected: " + last_error_);
  }
  rate_->report(status, connected_ && motor_wanted_);
  status.add("device", identity_.empty() ? "unknown (never connected)" : identity_);
  status.add("port", params_.driver.port);
  status.add("scans", counters_.scans);
  status.add("damaged scans", counters_.damaged);
  status.add("link failures", counters_.link_failures);
  status.add("stalls", counters_.stalls);
  status.add("opens", counters_.opens);
  status.add("scans not published", skipped_);
  status.add("last error", last_error_);
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
