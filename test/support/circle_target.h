// The target's tf broadcast by an e2e test itself (the circle of circle_reference.yaml), so
// the test can cut it, restore it, or send one sample stamped ahead (issue 25). The circle
// keeps its own clock through a cut: the target reappears where it has moved meanwhile.
#pragma once

#include <atomic>
#include <cmath>
#include <thread>

#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include "amigobot_tracking/core/reference.h"
#include "amigobot_tracking/ros/conversions.h"

namespace e2e {

class CircleTarget {
 public:
  CircleTarget() : circle_({0.0, 0.0}, 1.0, 40.0), start_(ros::Time::now()) {
    thread_ = std::thread([this] {
      ros::WallRate rate(50.0);
      while (!stop_ && ros::ok()) {
        const ros::Time now = ros::Time::now();
        const auto s = circle_.at((now - start_).toSec());
        const double ahead = ahead_.exchange(0.0);
        if (!paused_ || ahead != 0.0) {
          tf_.sendTransform(amigobot_tracking::ros_layer::toTransform(
              "map", "target", {s.position.x(), s.position.y(), std::atan2(s.velocity.y(), s.velocity.x())},
              now + ros::Duration(ahead)));
        }
        if (ahead != 0.0) paused_ = true;
        rate.sleep();
      }
    });
  }
  ~CircleTarget() {
    stop_ = true;
    thread_.join();
  }
  CircleTarget(const CircleTarget&) = delete;
  CircleTarget& operator=(const CircleTarget&) = delete;

  void pause(bool paused) { paused_ = paused; }
  // One last sample stamped `ahead` [s] in the future, then silence (a dying source with a
  // wrong clock).
  void lastSampleAhead(double ahead) { ahead_ = ahead; }

 private:
  amigobot_tracking::core::CircleReference circle_;
  ros::Time start_;
  tf2_ros::TransformBroadcaster tf_;
  std::atomic<bool> stop_{false}, paused_{false};
  std::atomic<double> ahead_{0.0};
  std::thread thread_;
};

}  // namespace e2e
