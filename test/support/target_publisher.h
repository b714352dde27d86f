// The target's tf broadcast by an e2e test itself, along a path the test gives (the pose in
// "map" at a ROS time), at 50 Hz and stamped now, so the test can cut it, restore it, or send
// one sample stamped ahead. The path keeps its own clock through a cut: the target reappears
// where it has moved meanwhile.
#pragma once

#include <atomic>
#include <functional>
#include <utility>

#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

#include "amigobot_tracking/core/support/types.h"
#include "amigobot_tracking/ros/conversions.h"
#include "periodic_thread.h"

namespace e2e {

class TargetPublisher {
 public:
  // path(t): the target's pose at ROS time t [s]; called from the publisher's thread.
  explicit TargetPublisher(std::function<amigobot_tracking::core::Pose2(double)> path)
      : path_(std::move(path)), thread_(50.0, [this] { publish(); }) {}

  void pause(bool paused) { paused_ = paused; }
  // One last sample stamped `ahead` [s] in the future, then silence (a dying source with a
  // wrong clock).
  void lastSampleAhead(double ahead) { ahead_ = ahead; }

 private:
  void publish() {
    const ros::Time now = ros::Time::now();
    const double ahead = ahead_.exchange(0.0);
    if (!paused_ || ahead != 0.0)
      tf_.sendTransform(
          amigobot_tracking::ros_layer::toTransform("map", "target", path_(now.toSec()), now + ros::Duration(ahead)));
    if (ahead != 0.0) paused_ = true;
  }

  std::function<amigobot_tracking::core::Pose2(double)> path_;
  tf2_ros::TransformBroadcaster tf_;
  std::atomic<bool> paused_{false};
  std::atomic<double> ahead_{0.0};
  PeriodicThread thread_;  // last: stops first
};

}  // namespace e2e
