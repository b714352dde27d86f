// Plain value types shared by the whole core. SI units, REP 103 axes.
#pragma once

#include <Eigen/Core>

namespace amigobot_tracking {
namespace core {

// Planar pose of the robot centre: position [m] and heading theta [rad].
struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;

  Eigen::Vector2d position() const { return {x, y}; }
  bool isFinite() const;
};

// Unicycle input: forward speed v [m/s] and turn rate omega [rad/s].
struct Twist2 {
  double v = 0.0;
  double omega = 0.0;

  bool isFinite() const;
};

// A disk obstacle in the global frame: centre [m], radius [m] and, when known, its
// velocity [m/s] (zero for static obstacles). A disk standing now that was seen walking (a
// person who stopped) keeps the velocity it last walked at in resume_velocity [m/s]: where it
// may go next, at any moment. Zero while it walks and for a disk never seen moving.
struct Disk {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double radius = 0.0;
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
  Eigen::Vector2d resume_velocity = Eigen::Vector2d::Zero();
};

// Wraps an angle to (-pi, pi].
double wrapAngle(double angle);

}  // namespace core
}  // namespace amigobot_tracking
