#include "amigobot_tracking/ros/driver_state_topics.h"

#include <cmath>
#include <limits>

#include <amigobot_tracking/Bumpers.h>
#include <amigobot_tracking/WheelStall.h>
#include <sensor_msgs/BatteryState.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float64.h>

namespace amigobot_tracking {
namespace ros_layer {
namespace {

constexpr std::uint16_t kFlagStopButton = 0x0020;  // SIP FLAGS bit 5 (AmigOS; AmigoSH leaves it 0)

// ARIA's charge states: 0 not charging, 1 bulk, 2 overcharge, 3 float (full).
std::uint8_t supplyStatus(std::uint8_t charge_state) {
  using sensor_msgs::BatteryState;
  switch (charge_state) {
    case 0: return BatteryState::POWER_SUPPLY_STATUS_DISCHARGING;
    case 1:
    case 2: return BatteryState::POWER_SUPPLY_STATUS_CHARGING;
    case 3: return BatteryState::POWER_SUPPLY_STATUS_FULL;
    default: return BatteryState::POWER_SUPPLY_STATUS_UNKNOWN;
  }
}

// Bumper bits: front in the high byte, rear in the low byte, bumper k at bit k + 1.
std::vector<bool> bumperBits(std::uint8_t byte, int count) {
  std::vector<bool> bits;
  for (int k = 0; k < std::min(count, 7); ++k) bits.push_back((byte >> (k + 1)) & 1);
  return bits;
}

}  // namespace

DriverStateTopics::DriverStateTopics(ros::NodeHandle& nh, std::string base_frame) : base_frame_(std::move(base_frame)) {
  battery_voltage_pub_ = nh.advertise<std_msgs::Float64>("battery_voltage", 1);
  battery_pub_ = nh.advertise<sensor_msgs::BatteryState>("battery", 1);
  stall_pub_ = nh.advertise<amigobot_tracking::WheelStall>("stall", 1, true);
  bumper_pub_ = nh.advertise<amigobot_tracking::Bumpers>("bumper", 1, true);
  estop_pub_ = nh.advertise<std_msgs::Bool>("estop", 1, true);
}

void DriverStateTopics::sayOnce(bool& said, const std::string& text) {
  if (said) return;
  said = true;
  ROS_INFO_STREAM_NAMED("aria", text);
}

void DriverStateTopics::publishBattery(const aria::Sip& sip, double voltage, const ros::Time& stamp) {
  std_msgs::Float64 volts;
  volts.data = voltage;
  battery_voltage_pub_.publish(volts);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  sensor_msgs::BatteryState b;
  b.header.stamp = stamp;
  b.header.frame_id = base_frame_;
  b.voltage = static_cast<float>(voltage);
  b.temperature = sip.temperature && *sip.temperature != -127 ? *sip.temperature : nan;  // -127: no sensor
  b.current = b.charge = b.capacity = b.design_capacity = nan;
  b.percentage = sip.state_of_charge ? 0.01f * *sip.state_of_charge : nan;
  if (!sip.state_of_charge) sayOnce(said_no_soc_, "the firmware reports no state of charge: battery.percentage is NaN");
  if (sip.charge_state) {
    b.power_supply_status = supplyStatus(*sip.charge_state);
  } else {
    sayOnce(said_no_charge_, "the firmware reports no charge state: battery.power_supply_status is UNKNOWN");
    b.power_supply_status = sensor_msgs::BatteryState::POWER_SUPPLY_STATUS_UNKNOWN;
  }
  b.power_supply_health = sensor_msgs::BatteryState::POWER_SUPPLY_HEALTH_UNKNOWN;
  b.power_supply_technology = sensor_msgs::BatteryState::POWER_SUPPLY_TECHNOLOGY_UNKNOWN;  // lead-acid: no constant
  b.present = true;
  battery_pub_.publish(b);
}

void DriverStateTopics::publish(const aria::RobotState& state, const std::optional<aria::ConfigPac>& config,
                                const ros::Time& stamp) {
  publishBattery(state.sip, state.battery_voltage, stamp);
  const std::pair<bool, bool> stall{state.left_stall, state.right_stall};
  if (last_stall_ != stall) {
    amigobot_tracking::WheelStall m;
    m.header.stamp = stamp;
    m.header.frame_id = base_frame_;
    m.left = stall.first;
    m.right = stall.second;
    stall_pub_.publish(m);
    last_stall_ = stall;
  }
  const int front = config && config->front_bumps ? *config->front_bumps : 0;
  const int rear = config && config->rear_bumps ? *config->rear_bumps : 0;
  const auto bumpers = std::make_pair(bumperBits(static_cast<std::uint8_t>(state.sip.stall_bumpers >> 8), front),
                                      bumperBits(static_cast<std::uint8_t>(state.sip.stall_bumpers & 0xFF), rear));
  if (last_bumpers_ != bumpers) {
    amigobot_tracking::Bumpers m;
    m.header.stamp = stamp;
    m.header.frame_id = base_frame_;
    m.front.assign(bumpers.first.begin(), bumpers.first.end());
    m.rear.assign(bumpers.second.begin(), bumpers.second.end());
    bumper_pub_.publish(m);
    last_bumpers_ = bumpers;
  }
  const bool estop = (state.sip.flags & kFlagStopButton) != 0;
  if (last_estop_ != estop) {
    std_msgs::Bool m;
    m.data = estop;
    estop_pub_.publish(m);
    last_estop_ = estop;
  }
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
