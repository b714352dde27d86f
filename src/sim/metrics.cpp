#include "amigobot_tracking/sim/metrics.h"

#include <algorithm>
#include <cmath>

namespace amigobot_tracking {
namespace sim {

void MetricsAccumulator::add(const MetricSample& s) {
  ++m_.steps;
  const double e_norm = s.e.norm();
  const bool finite = s.valid && std::isfinite(e_norm) && s.u.isFinite() && std::isfinite(s.h) &&
                      !std::isnan(s.rho) && !std::isnan(s.clearance_offset) && !std::isnan(s.clearance_body) &&
                      s.velocity_error.allFinite() && s.e_true.allFinite();
  if (!finite) {
    ++m_.nan_count;
    return;  // a NaN must not poison the averages; it is reported by its count
  }
  const double h = std::max(0.0, s.h);
  m_.sim_time += h;
  sum_e2_ += h * e_norm * e_norm;
  sum_e_ += h * e_norm;
  m_.tec += h * (s.u.v * s.u.v + s.u.omega * s.u.omega);
  sum_v2_ += h * s.velocity_error.squaredNorm();
  if (s.rho > 0.0) {
    m_.max_e_over_rho = std::max(m_.max_e_over_rho, e_norm / s.rho);
    m_.max_rho = std::max(m_.max_rho, s.rho);
  }
  m_.min_clearance_offset = std::min(m_.min_clearance_offset, s.clearance_offset);
  m_.min_clearance_body = std::min(m_.min_clearance_body, s.clearance_body);
  const bool offset_contact = s.clearance_offset < 0.0, body_contact = s.clearance_body < 0.0;
  if (offset_contact && !in_offset_contact_) ++m_.offset_collisions;
  if (body_contact && !in_body_contact_) ++m_.body_collisions;
  in_offset_contact_ = offset_contact;
  in_body_contact_ = body_contact;
  if (offset_contact) m_.offset_contact_time += h;
  if (body_contact) m_.body_contact_time += h;
  if (s.diamond_norm > 1.0 + kDiamondTolerance) ++m_.diamond_violations;
  if (s.saturated) ++m_.saturated_steps;
  if (s.envelope_widened) ++m_.envelope_widenings;
  if (s.estimator_settled) {
    m_.estimator_max_error_settled = std::max(m_.estimator_max_error_settled, s.velocity_error.norm());
  }
  m_.final_error = e_norm;
  const double true_norm = s.e_true.norm();
  sum_true_e2_ += h * true_norm * true_norm;
  sum_true_e_ += h * true_norm;
  m_.max_true_error = std::max(m_.max_true_error, true_norm);
  const double excess = true_norm - bestStandoff(s);
  addOrbits(s);
  addStall(s, excess);
  if (s.conflict) ++m_.conflict_steps;
  if (s.escaping) ++m_.escape_steps;
  if (s.passing_side * last_side_ < 0) ++m_.side_flips;
  last_side_ = s.passing_side;
  if (std::abs(s.u.omega) > kReversalDeadband) {
    const int sign = s.u.omega > 0.0 ? 1 : -1;
    if (sign * last_omega_sign_ < 0) ++m_.omega_reversals;
    last_omega_sign_ = sign;
  }
  if (has_last_) {
    m_.escape_toggles += s.escaping != last_escaping_;
    m_.avoidance_toggles += s.avoiding != last_avoiding_;
    m_.max_delta_v = std::max(m_.max_delta_v, std::abs(s.u.v - last_u_.v));
    m_.max_delta_omega = std::max(m_.max_delta_omega, std::abs(s.u.omega - last_u_.omega));
  }
  has_last_ = true;
  last_escaping_ = s.escaping;
  last_avoiding_ = s.avoiding;
  last_u_ = s.u;
}

double MetricsAccumulator::bestStandoff(const MetricSample& s) {
  if (!s.obstacles) return 0.0;
  const Eigen::Vector2d p_d = s.p_r + s.e_true;
  double standoff = 0.0;  // the deepest zone the target is in (a lower bound where zones overlap)
  for (const core::Disk& o : *s.obstacles)
    standoff = std::max(standoff, s.zone_radius + o.radius - (p_d - o.center).norm());
  return standoff;
}

void MetricsAccumulator::addStall(const MetricSample& s, double excess) {
  // The window ending now: drop samples while the next one still starts it.
  recent_.push_back({s.t, {s.p_r, excess}});
  while (recent_.size() > 1 && recent_[1].first <= s.t - kStallWindow + 1e-9) recent_.pop_front();
  const double span = s.t - recent_.front().first;
  const Eigen::Vector2d& p_then = recent_.front().second.first;
  const double excess_then = recent_.front().second.second;
  const double needed = kStallSpeed * span;
  const Eigen::Vector2d toward = s.e_true.norm() > 1e-12 ? Eigen::Vector2d(s.e_true.normalized()) : Eigen::Vector2d::Zero();
  // Moving counts as progress too (a detour round a disk), except round and round one disk.
  const bool moved = (s.p_r - p_then).norm() >= needed && !circling_;
  const bool progress = excess_then - excess >= needed || (s.p_r - p_then).dot(toward) >= needed || moved;
  const bool stalled = span >= kStallWindow - 1e-9 && excess > kStallError && !progress;
  if (!stalled) {
    stall_start_ = -1.0;
    return;
  }
  if (stall_start_ < 0.0) {
    stall_start_ = s.t;
    m_.stall_time += kStallWindow;
  } else {
    m_.stall_time += s.t - last_stall_t_;
  }
  last_stall_t_ = s.t;
  m_.longest_stall = std::max(m_.longest_stall, s.t - stall_start_ + kStallWindow);
}

void MetricsAccumulator::addOrbits(const MetricSample& s) {
  if (!s.obstacles) return;
  const std::vector<core::Disk>& disks = *s.obstacles;
  orbit_angle_.resize(disks.size(), 0.0);
  orbit_last_.resize(disks.size(), Eigen::Vector2d::Zero());
  circling_ = false;
  for (size_t j = 0; j < disks.size(); ++j) {
    const Eigen::Vector2d d = s.p_r - disks[j].center;
    if (d.norm() > s.zone_radius + disks[j].radius + kOrbitReach || d.isZero(0.0)) {
      orbit_angle_[j] = 0.0;  // the visit ended
      orbit_last_[j].setZero();
      continue;
    }
    const Eigen::Vector2d& last = orbit_last_[j];
    if (!last.isZero(0.0)) orbit_angle_[j] += std::atan2(last.x() * d.y() - last.y() * d.x(), last.dot(d));
    orbit_last_[j] = d;
    m_.max_orbit_turns = std::max(m_.max_orbit_turns, std::abs(orbit_angle_[j]) / (2.0 * M_PI));
    circling_ = circling_ || std::abs(orbit_angle_[j]) > M_PI;
  }
}

RunMetrics MetricsAccumulator::result() const {
  RunMetrics r = m_;
  r.ise = sum_e2_;
  r.iae = sum_e_;
  r.true_ise = sum_true_e2_;
  r.true_iae = sum_true_e_;
  if (r.sim_time > 0.0) {
    r.ase = sum_e2_ / r.sim_time;
    r.aae = sum_e_ / r.sim_time;
    r.estimator_rms_error = std::sqrt(sum_v2_ / r.sim_time);
    r.true_ase = sum_true_e2_ / r.sim_time;
    r.true_aae = sum_true_e_ / r.sim_time;
    r.omega_reversals_per_minute = static_cast<double>(r.omega_reversals) * 60.0 / r.sim_time;
  }
  return r;
}

}  // namespace sim
}  // namespace amigobot_tracking
