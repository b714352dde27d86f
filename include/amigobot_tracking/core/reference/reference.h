// Reference trajectories p_d(t) with their exact velocity, for the simulator, the
// reference publisher and tests.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace amigobot_tracking {
namespace core {

struct ReferenceState {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m]
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  // [m/s]
};

class Reference {
 public:
  virtual ~Reference() = default;
  virtual ReferenceState at(double t) const = 0;
  // at(t0) and at(t1) together (the closed loop's step start and command time); a reference
  // may share work between two close instants (the rose: one sin/cos pair, rotated).
  virtual void atPair(double t0, double t1, ReferenceState* s0, ReferenceState* s1) const {
    *s0 = at(t0);
    *s1 = at(t1);
  }
};

// Rose curve of the paper's Section 5.2: x = A cos(k w t) cos(w t), y = A cos(k w t) sin(w t)
// with w = 1 / time_scale [rad/s]. For odd k its period is pi / w (the radius changes sign
// when the angle gains pi: the same point), so 2 pi / w is two laps.
class RoseReference : public Reference {
 public:
  RoseReference(double amplitude, double k, double time_scale);
  ReferenceState at(double t) const override;
  void atPair(double t0, double t1, ReferenceState* s0, ReferenceState* s1) const override;

 private:
  // The state from (cos, sin) of the phase w t and of the petal phase k w t.
  ReferenceState state(double c, double s, double ck, double sk) const;
  double amplitude_, k_, rate_;
};

// Circle of given centre and radius, counter-clockwise, one turn per period [s],
// starting at centre + (radius, 0).
class CircleReference : public Reference {
 public:
  CircleReference(const Eigen::Vector2d& center, double radius, double period);
  ReferenceState at(double t) const override;

 private:
  Eigen::Vector2d center_;
  double radius_, rate_;
};

// Natural cubic spline through waypoints (2 or more), parametrised by time with knots
// spaced by chord length over `duration`; holds the last point after the end.
// Not MATLAB's cscvn, which the paper used: cscvn spaces its knots centripetally (by the
// square root of the chord) and closes a curve whose ends coincide periodically. Here the
// knot parameter is time, and chord-length knots keep the target's speed about constant
// along the path (centripetal ones make it slower on long segments, faster on short ones);
// the shipped layouts (obstacles on the path at given times) were placed on this curve.
// Two waypoints, and evenly spaced ones, give the same curve either way.
class SplineReference : public Reference {
 public:
  SplineReference(const std::vector<Eigen::Vector2d>& waypoints, double duration);
  ReferenceState at(double t) const override;

 private:
  std::vector<double> knots_;
  std::vector<Eigen::Vector2d> points_;
  std::vector<Eigen::Vector2d> second_;  // second derivatives at the knots
};

}  // namespace core
}  // namespace amigobot_tracking
