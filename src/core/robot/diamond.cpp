#include "amigobot_tracking/core/robot/diamond.h"

#include <algorithm>
#include <cmath>

namespace amigobot_tracking {
namespace core {

bool Pose2::isFinite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(theta); }

bool Twist2::isFinite() const { return std::isfinite(v) && std::isfinite(omega); }

double wrapAngle(double angle) {
  if (angle > -M_PI && angle <= M_PI) return angle;  // what remainder() gives here, without its cost
  const double wrapped = std::remainder(angle, 2.0 * M_PI);  // in [-pi, pi]
  return wrapped <= -M_PI ? wrapped + 2.0 * M_PI : wrapped;
}

WheelSpeeds toWheelSpeeds(const Twist2& u, double half_track) {
  return {u.v - half_track * u.omega, u.v + half_track * u.omega};
}

Twist2 fromWheelSpeeds(const WheelSpeeds& wheels, double half_track) {
  return {0.5 * (wheels.left + wheels.right), 0.5 * (wheels.right - wheels.left) / half_track};
}

DiamondSet::DiamondSet(double v_max, double w_max) : v_max_(v_max), w_max_(w_max) {}

DiamondSet DiamondSet::fromWheelLimit(double wheel_speed_max, double half_track) {
  return DiamondSet(wheel_speed_max, wheel_speed_max / half_track);
}

double DiamondSet::normalizedNorm(const Twist2& u) const {
  return std::abs(u.v) / v_max_ + std::abs(u.omega) / w_max_;
}

bool DiamondSet::contains(const Twist2& u, double tolerance) const {
  return u.isFinite() && normalizedNorm(u) <= 1.0 + tolerance;
}

std::optional<Twist2> DiamondSet::saturate(const Twist2& u) const {
  if (!u.isFinite()) return std::nullopt;
  const double n = normalizedNorm(u);
  if (!std::isfinite(n)) {
    // Finite but huge components overflow the norm: scale by an exact power of two first.
    return saturate({std::ldexp(u.v, -600), std::ldexp(u.omega, -600)});
  }
  if (n <= 1.0) return u;
  Twist2 out{u.v / n, u.omega / n};
  // Rounding can leave the scaled point a few ulps outside: pull it onto the inside.
  while (normalizedNorm(out) > 1.0) {
    out.v = std::nextafter(out.v, 0.0);
    out.omega = std::nextafter(out.omega, 0.0);
  }
  return out;
}

}  // namespace core
}  // namespace amigobot_tracking
