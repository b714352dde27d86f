// The robot's own reports, one SIP at a time: battery_voltage (std_msgs/Float64), battery
// (sensor_msgs/BatteryState, NaN where the firmware reports nothing), stall (per wheel),
// bumper and estop, the last three latched and published on change. A field this firmware
// does not report is said once in the log, then published as unknown.
//
// The rule (docs/architecture.md): a topic that reports what a SIP says about the robot's
// body and power is published here; driver.cpp publishes the motion (odom, tf, sonar ranges
// and cloud) and the state the driver commands (motors_state, also on link loss).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "amigobot_tracking/aria/client.h"

namespace amigobot_tracking {
namespace ros_layer {

class DriverStateTopics {
 public:
  DriverStateTopics(ros::NodeHandle& nh, std::string base_frame);
  // One SIP; `config` (if any) tells how many bumpers the robot has. Client I/O thread.
  void publish(const aria::RobotState& state, const std::optional<aria::ConfigPac>& config, const ros::Time& stamp);

 private:
  void publishBattery(const aria::Sip& sip, double voltage, const ros::Time& stamp);
  void sayOnce(bool& said, const std::string& text);

  std::string base_frame_;
  ros::Publisher battery_voltage_pub_, battery_pub_, stall_pub_, bumper_pub_, estop_pub_;
  std::optional<std::pair<bool, bool>> last_stall_;
  std::optional<std::pair<std::vector<bool>, std::vector<bool>>> last_bumpers_;
  std::optional<bool> last_estop_;
  bool said_no_soc_ = false, said_no_charge_ = false;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
