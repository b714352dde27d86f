#include "amigobot_tracking/aria/odometry.h"

#include <cmath>

#include "amigobot_tracking/core/robot/unicycle.h"

namespace amigobot_tracking {
namespace aria {

int positionDelta(std::uint16_t now, std::uint16_t last) {
  int d = static_cast<int>(now & 0x7FFF) - static_cast<int>(last & 0x7FFF);
  if (d > 0x1000) d -= 0x8000;
  if (d < -0x1000) d += 0x8000;
  return d;
}

int angleDelta(int now, int last, int units_per_turn) {
  int d = (now - last) % units_per_turn;
  if (d > units_per_turn / 2) d -= units_per_turn;
  if (d <= -units_per_turn / 2) d += units_per_turn;
  return d;
}

core::Twist2 sipTwist(const Sip& sip, const RobotParams& p) {
  const double left = sip.left_vel * p.vel_conv_factor;    // mm/s
  const double right = sip.right_vel * p.vel_conv_factor;  // mm/s
  core::Twist2 t;
  t.v = 0.5 * (left + right) * 1e-3;
  t.omega = sip.rot_vel ? *sip.rot_vel * 0.1 * M_PI / 180.0 : 0.5 * (right - left) * p.diff_conv_factor;
  return t;
}

const OdometryState& SipOdometry::update(const Sip& sip) {
  state_.twist = sipTwist(sip, params_);
  if (!have_last_) {
    have_last_ = true;
    last_ = sip;
    return state_;
  }
  const double dx = positionDelta(sip.x, last_.x) * params_.dist_conv_factor * 1e-3;  // m, robot frame
  const double dy = positionDelta(sip.y, last_.y) * params_.dist_conv_factor * 1e-3;
  const double dth = angleDelta(sip.theta, last_.theta, params_.angle_units_per_turn) * params_.angle_conv_factor;
  const double th_last = last_.theta * params_.angle_conv_factor;
  last_ = sip;
  // The firmware's displacement is the chord of the arc; its component along the mid-arc
  // heading is the signed chord length c, and the arc length is c / sinc(dth/2). The
  // lateral component (quantisation noise for a non-holonomic robot) is dropped.
  const double chord = dx * std::cos(th_last + 0.5 * dth) + dy * std::sin(th_last + 0.5 * dth);
  const double half = 0.5 * dth;
  const double sinc = std::abs(half) < 1e-9 ? 1.0 : std::sin(half) / half;
  const double arc = chord / sinc;
  // integrateUnicycle with h = 1 applies (arc, dth) exactly along the arc.
  state_.pose = core::integrateUnicycle(state_.pose, {arc, dth}, 1.0);
  return state_;
}

}  // namespace aria
}  // namespace amigobot_tracking
