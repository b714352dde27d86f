// Test helper (rostests): every geometry_msgs/Twist on cmd_vel with its wall-clock arrival
// time, for judging what a node commanded and when. Needs a running spinner.
#pragma once

#include <cmath>
#include <mutex>
#include <vector>

#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

namespace amigobot_test {

class CmdVelLog {
 public:
  struct Received {
    double t;  // wall time [s]
    double v, w;
  };

  explicit CmdVelLog(const std::string& topic = "cmd_vel") {
    ros::NodeHandle nh;
    sub_ = nh.subscribe<geometry_msgs::Twist>(topic, 100, [this](const geometry_msgs::Twist::ConstPtr& m) {
      std::lock_guard<std::mutex> lock(mutex_);
      log_.push_back({now(), m->linear.x, m->angular.z});
    });
  }
  static double now() { return ros::WallTime::now().toSec(); }

  std::vector<Received> all() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return log_;
  }
  std::vector<Received> since(double t) const {
    std::vector<Received> out;
    for (const Received& r : all())
      if (r.t >= t) out.push_back(r);
    return out;
  }
  // Waits until a message that arrived since `t` is (v, w); its arrival time, or NaN.
  double waitFor(double v, double w, double t, double timeout = 3.0) const {
    const double end = now() + timeout;
    while (now() < end) {
      for (const Received& r : since(t))
        if (std::abs(r.v - v) < 1e-9 && std::abs(r.w - w) < 1e-9) return r.t;
      ros::WallDuration(0.01).sleep();
    }
    return std::nan("");
  }
  // Waits until a publisher is connected.
  bool waitForPublisher(double timeout) const {
    const double end = now() + timeout;
    while (sub_.getNumPublishers() == 0 && now() < end) ros::WallDuration(0.05).sleep();
    return sub_.getNumPublishers() > 0;
  }

 private:
  ros::Subscriber sub_;
  mutable std::mutex mutex_;
  std::vector<Received> log_;
};

}  // namespace amigobot_test
