// The localisation rostests' robot in the synthetic room (synthetic_room.h), on real ROS:
// a thread that publishes, every scan period, tf odom -> base_footprint (odometry), the
// static base_footprint -> laser mount, and the LaserScan ray cast from the true pose.
// The test moves the truth (drive, teleport) and can pause the scans.
#pragma once

#include <atomic>
#include <mutex>
#include <random>
#include <thread>

#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

#include "synthetic_room.h"

namespace amigobot_test {

class SyntheticRobot {
 public:
  // The robot starts at `truth` (map frame); odometry's frame sits at `map_to_odom`.
  SyntheticRobot(const Pose2& truth, const Pose2& map_to_odom, double rate = 10.0)
      : truth_(truth), odom_(loc::compose(loc::inverse(map_to_odom), truth)), rate_(rate) {
    ros::NodeHandle nh;
    scan_pub_ = nh.advertise<sensor_msgs::LaserScan>("scan", 5);
    geometry_msgs::TransformStamped mount = transform("base_footprint", "laser", emptyScan(2).mount);
    mount.header.stamp = ros::Time::now();
    static_tf_.sendTransform(mount);
    thread_ = std::thread([this] { loop(); });
  }
  ~SyntheticRobot() {
    stop_ = true;
    thread_.join();
  }

  // Moves by `step` (robot frame) per scan, truth and odometry alike.
  void drive(const Pose2& step) {
    std::lock_guard<std::mutex> lock(mutex_);
    step_ = step;
  }
  // Kidnapping: the truth jumps, odometry notices nothing.
  void teleport(const Pose2& truth) {
    std::lock_guard<std::mutex> lock(mutex_);
    truth_ = truth;
  }
  void scans(bool on) { scans_on_ = on; }
  Pose2 truth() {
    std::lock_guard<std::mutex> lock(mutex_);
    return truth_;
  }

  static geometry_msgs::TransformStamped transform(const std::string& parent, const std::string& child, const Pose2& p) {
    geometry_msgs::TransformStamped t;
    t.header.frame_id = parent;
    t.child_frame_id = child;
    t.transform.translation.x = p.x;
    t.transform.translation.y = p.y;
    t.transform.rotation.z = std::sin(0.5 * p.theta);
    t.transform.rotation.w = std::cos(0.5 * p.theta);
    return t;
  }

 private:
  void loop() {
    std::mt19937 random(5);
    ros::WallRate rate(rate_);
    while (!stop_ && ros::ok()) {
      Pose2 truth, odom;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        truth_ = loc::compose(truth_, step_);
        odom_ = loc::compose(odom_, step_);
        truth = truth_;
        odom = odom_;
      }
      const ros::Time stamp = ros::Time::now();
      geometry_msgs::TransformStamped t = transform("odom", "base_footprint", odom);
      t.header.stamp = stamp;
      tf_.sendTransform(t);
      if (scans_on_) {
        const int beams = 360;
        const loc::RangeScan scan = scanAt(truth, beams, &random);
        sensor_msgs::LaserScan msg;
        msg.header.stamp = stamp;
        msg.header.frame_id = "laser";
        msg.angle_min = static_cast<float>(scan.angle_min);
        msg.angle_increment = static_cast<float>(scan.angle_increment);
        msg.angle_max = static_cast<float>(scan.angle_min + scan.angle_increment * (beams - 1));
        msg.range_min = static_cast<float>(scan.range_min);
        msg.range_max = static_cast<float>(scan.range_max);
        msg.scan_time = static_cast<float>(1.0 / rate_);
        msg.ranges = scan.ranges;
        scan_pub_.publish(msg);
      }
      rate.sleep();
    }
  }

  std::mutex mutex_;
  Pose2 truth_, odom_, step_;
  double rate_;
  ros::Publisher scan_pub_;
  tf2_ros::TransformBroadcaster tf_;
  tf2_ros::StaticTransformBroadcaster static_tf_;
  std::atomic<bool> stop_{false}, scans_on_{true};
  std::thread thread_;
};

}  // namespace amigobot_test
