#include "amigobot_tracking/core/perception/obstacle_motion.h"

#include <cmath>
#include <sstream>

namespace amigobot_tracking {
namespace core {
namespace {

constexpr std::size_t kMaxLegs = 10000;

// The displacement after walking tau [s] into the legs (tau within [0, period]), and the
// velocity of the leg that tau falls in (zero past the end).
Eigen::Vector2d walk(const std::vector<MotionLeg>& legs, double tau, Eigen::Vector2d* velocity) {
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();
  if (velocity) velocity->setZero();
  for (const MotionLeg& leg : legs) {
    if (tau < leg.duration) {
      if (velocity) *velocity = leg.velocity;
      return shift + leg.velocity * tau;
    }
    shift += leg.velocity * leg.duration;
    tau -= leg.duration;
  }
  return shift;
}

}  // namespace

double ObstacleMotion::period() const {
  double total = 0.0;
  for (const MotionLeg& leg : legs) total += leg.duration;
  return total;
}

Eigen::Vector2d ObstacleMotion::positionAt(double t) const {
  double tau = t - start_time;
  if (!(tau > 0.0) || legs.empty()) return start;
  const double T = period();
  if (repeat && T > 0.0) tau = std::fmod(tau, T);
  return start + walk(legs, tau, nullptr);
}

Eigen::Vector2d ObstacleMotion::velocityAt(double t) const {
  double tau = t - start_time;
  if (tau < 0.0 || legs.empty()) return Eigen::Vector2d::Zero();
  const double T = period();
  if (repeat && T > 0.0) tau = std::fmod(tau, T);
  Eigen::Vector2d v;
  walk(legs, tau, &v);
  return v;
}

Eigen::Vector2d ObstacleMotion::resumeVelocityAt(double t) const {
  double tau = t - start_time;
  if (!(tau > 0.0) || legs.empty() || velocityAt(t).norm() > 0.0) return Eigen::Vector2d::Zero();
  const double T = period();
  const bool wrapped = repeat && T > 0.0 && tau >= T;  // the legs of the cycle before count too
  if (repeat && T > 0.0) tau = std::fmod(tau, T);
  Eigen::Vector2d last = Eigen::Vector2d::Zero();
  double begin = 0.0;
  for (const MotionLeg& leg : legs) {
    if (begin >= tau) break;
    if (leg.velocity.norm() > 0.0) last = leg.velocity;
    begin += leg.duration;
  }
  if (last.norm() == 0.0 && wrapped) {
    for (const MotionLeg& leg : legs)
      if (leg.velocity.norm() > 0.0) last = leg.velocity;
  }
  return last;
}

std::string ObstacleMotion::validate() const {
  std::ostringstream why;
  if (!start.allFinite()) return "start: not finite";
  if (!std::isfinite(start_time)) return "start_time: not finite";
  if (legs.size() > kMaxLegs) {
    why << "legs: " << legs.size() << " legs, at most " << kMaxLegs;
    return why.str();
  }
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < legs.size(); ++i) {
    const MotionLeg& leg = legs[i];
    if (!(std::isfinite(leg.duration) && leg.duration > 0.0)) {
      why << "legs[" << i << "].duration: " << leg.duration << " is not a finite duration > 0";
      return why.str();
    }
    if (!leg.velocity.allFinite()) {
      why << "legs[" << i << "].velocity: not finite";
      return why.str();
    }
    shift += leg.velocity * leg.duration;
  }
  if (repeat && shift.norm() > 1e-6) {
    why << "repeat: the legs end " << shift.norm() << " m from the start; a repeating motion must return to it";
    return why.str();
  }
  return "";
}

}  // namespace core
}  // namespace amigobot_tracking
