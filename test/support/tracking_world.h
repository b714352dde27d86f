// The scripted world around the tracking nodelet in its rostest (tracking_nodelet.test):
// it integrates cmd_vel into the robot pose (tf map -> base_link), moves a target along a
// circle (tf map -> target), mounts a laser (static base_link -> laser) and publishes its
// scans; plus the waiting and service helpers the cases share.
#pragma once

#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

#include "amigobot_tracking/TrackingState.h"
#include "amigobot_tracking/VirtualObstacle.h"
#include "amigobot_tracking/VirtualObstacleArray.h"
#include "amigobot_tracking/core/robot/unicycle.h"
#include "amigobot_tracking/ros/conversions.h"

namespace tracking_world {

using namespace amigobot_tracking;
using amigobot_tracking::ros_layer::toTransform;

inline constexpr double kTimeout = 30.0;  // [s] wall time for anything to happen on a loaded machine

inline bool waitFor(const std::function<bool()>& condition, double seconds = kTimeout) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::ok() && ros::WallTime::now() < end) {
    if (condition()) return true;
    ros::WallDuration(0.01).sleep();
  }
  return condition();
}

// The scripted world around the nodelet.
class World {
 public:
  World() : pnh_("~") {
    cmd_sub_ = nh_.subscribe("cmd_vel", 100, &World::onCmd, this);
    state_sub_ = nh_.subscribe("tracking/state", 100, &World::onState, this);
    virtual_sub_ = nh_.subscribe("tracking/virtual_obstacles", 10, &World::onVirtual, this);
    scan_pub_ = nh_.advertise<sensor_msgs::LaserScan>("scan", 5);
    virtual_pub_ = nh_.advertise<VirtualObstacle>("tracking/virtual_obstacle", 10, true);
    static_tf_.sendTransform(toTransform("base_link", "laser", {0.1, 0.0, 0.0}, ros::Time::now()));
    robot_timer_ = nh_.createWallTimer(ros::WallDuration(0.02), &World::onRobotTick, this);
    target_timer_ = nh_.createWallTimer(ros::WallDuration(0.05), &World::onTargetTick, this);
    scan_timer_ = nh_.createWallTimer(ros::WallDuration(0.1), &World::onScanTick, this);
  }

  std::atomic<bool> target_on{true};
  std::atomic<bool> scan_broken{false};  // publish scans with angle_increment 0

  struct Cmd {
    ros::WallTime received;
    geometry_msgs::Twist twist;
  };
  std::vector<Cmd> commandsSince(const ros::WallTime& since) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<Cmd> out;
    for (const Cmd& c : commands_) {
      if (c.received >= since) out.push_back(c);
    }
    return out;
  }
  std::vector<TrackingState> statesSince(const ros::Time& since) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<TrackingState> out;
    for (const TrackingState& s : states_) {
      if (s.header.stamp >= since) out.push_back(s);
    }
    return out;
  }
  VirtualObstacleArray virtualObstacles() {
    std::lock_guard<std::mutex> lock(mutex_);
    return virtual_;
  }
  void publishVirtual(const VirtualObstacle& o) { virtual_pub_.publish(o); }

 private:
  void onCmd(const geometry_msgs::Twist::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    commands_.push_back({ros::WallTime::now(), *msg});
    u_ = {msg->linear.x, msg->angular.z};
  }
  void onState(const TrackingState::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    states_.push_back(*msg);
  }
  void onVirtual(const VirtualObstacleArray::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    virtual_ = *msg;
  }
  // The robot follows the last command exactly (an ideal unicycle).
  void onRobotTick(const ros::WallTimerEvent&) {
    core::Pose2 pose;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      pose_ = core::integrateUnicycle(pose_, u_, 0.02);
      pose = pose_;
    }
    tf_.sendTransform(toTransform("map", "base_link", pose, ros::Time::now()));
  }
  // Target on a circle of radius 1 m around the origin, 60 s per turn (0.1 m/s).
  void onTargetTick(const ros::WallTimerEvent&) {
    if (!target_on) return;
    const double phase = 2.0 * M_PI * (ros::WallTime::now() - start_).toSec() / 60.0;
    const core::Pose2 target{std::cos(phase), std::sin(phase), phase + M_PI / 2};
    tf_.sendTransform(toTransform("map", "target", target, ros::Time::now()));
  }
  // 360 beams: a pillar 2 m to the laser's left, REP 117 specials, +inf elsewhere.
  void onScanTick(const ros::WallTimerEvent&) {
    sensor_msgs::LaserScan scan;
    scan.header.stamp = ros::Time::now();
    scan.header.frame_id = "laser";
    scan.angle_min = -M_PI;
    scan.angle_increment = scan_broken ? 0.0f : static_cast<float>(2.0 * M_PI / 360);
    scan.angle_max = scan.angle_min + 359 * scan.angle_increment;
    scan.range_min = 0.05f;
    scan.range_max = 10.0f;
    for (int i = 0; i < 360; ++i) {
      const double a = scan.angle_min + i * scan.angle_increment;
      float r = std::numeric_limits<float>::infinity();
      if (std::abs(a - M_PI / 2) < 0.05) r = 2.0f;
      if (i % 17 == 0) r = std::numeric_limits<float>::quiet_NaN();
      if (i % 23 == 0) r = -std::numeric_limits<float>::infinity();
      scan.ranges.push_back(r);
    }
    scan_pub_.publish(scan);
  }

  ros::NodeHandle nh_, pnh_;
  ros::Subscriber cmd_sub_, state_sub_, virtual_sub_;
  ros::Publisher scan_pub_, virtual_pub_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::StaticTransformBroadcaster static_tf_;
  ros::WallTimer robot_timer_, target_timer_, scan_timer_;
  ros::WallTime start_ = ros::WallTime::now();
  std::mutex mutex_;
  core::Pose2 pose_;
  core::Twist2 u_;
  std::vector<Cmd> commands_;
  std::vector<TrackingState> states_;
  VirtualObstacleArray virtual_;
};

// Calls an idempotent Trigger service. A call can fail in transport on a loaded machine
// even though the server ran it (seen once in 3 runs under 2 busy loops): retry twice.
inline bool trigger(const std::string& service) {
  if (!ros::service::waitForService(service, ros::Duration(kTimeout))) return false;
  for (int attempt = 0; attempt < 3; ++attempt) {
    std_srvs::Trigger srv;
    if (ros::service::call(service, srv)) return srv.response.success;
    ROS_WARN("call to %s failed in transport, retrying", service.c_str());
    ros::WallDuration(0.2).sleep();
  }
  return false;
}

inline bool isZero(const geometry_msgs::Twist& t) { return t.linear.x == 0.0 && t.angular.z == 0.0; }

inline double diamondNorm(const geometry_msgs::Twist& t, double v_max, double w_max) {
  return std::abs(t.linear.x) / v_max + std::abs(t.angular.z) / w_max;
}

inline double param(const std::string& name) {
  double value = std::numeric_limits<double>::quiet_NaN();
  ros::param::get(name, value);
  return value;
}


}  // namespace tracking_world
