// A thread that calls `tick` at a fixed wall-clock rate until the object is destroyed (or ROS
// shuts down): the loop of the e2e tests' own publishers (a target's tf, a scan source).
// Declare it as the owner's last member, so it stops before what `tick` uses is destroyed.
#pragma once

#include <atomic>
#include <functional>
#include <thread>
#include <utility>

#include <ros/ros.h>

namespace e2e {

class PeriodicThread {
 public:
  PeriodicThread(double rate_hz, std::function<void()> tick) : tick_(std::move(tick)) {
    thread_ = std::thread([this, rate_hz] {
      ros::WallRate rate(rate_hz);
      while (!stop_ && ros::ok()) {
        tick_();
        rate.sleep();
      }
    });
  }
  ~PeriodicThread() {
    stop_ = true;
    thread_.join();
  }
  PeriodicThread(const PeriodicThread&) = delete;
  PeriodicThread& operator=(const PeriodicThread&) = delete;

 private:
  std::function<void()> tick_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace e2e
