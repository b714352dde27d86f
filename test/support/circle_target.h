// The target of circle_reference.yaml (the unit circle, period 40 s) published by an e2e test
// itself (target_publisher.h): the test can cut it, restore it, or send one sample stamped
// ahead (issue 25). Its clock starts when it is built.
#pragma once

#include <cmath>

#include <ros/ros.h>

#include "amigobot_tracking/core/reference/reference.h"
#include "target_publisher.h"

namespace e2e {

class CircleTarget : public TargetPublisher {
 public:
  CircleTarget() : TargetPublisher(circle(ros::Time::now().toSec())) {}

 private:
  static std::function<amigobot_tracking::core::Pose2(double)> circle(double start) {
    return [circle = amigobot_tracking::core::CircleReference({0.0, 0.0}, 1.0, 40.0), start](double t) {
      const auto s = circle.at(t - start);
      return amigobot_tracking::core::Pose2{s.position.x(), s.position.y(), std::atan2(s.velocity.y(), s.velocity.x())};
    };
  }
};

}  // namespace e2e
