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
  // Headway over the window ending now: drop samples while the next one still starts it.
  recent_.emplace_back(s.t, s.p_r);
  while (recent_.size() > 1 && recent_[1].first <= s.t - kStallWindow + 1e-9) recent_.pop_front();
  const double span = s.t - recent_.front().first;
  const bool stalled = span >= kStallWindow - 1e-9 && true_norm > kStallError &&
                       (s.p_r - recent_.front().second).norm() < kStallSpeed * span;
  if (!stalled) {
    stall_start_ = -1.0;
  } else {
    if (stall_start_ < 0.0) stall_start_ = s.t;
    m_.longest_stall = std::max(m_.longest_stall, s.t - stall_start_ + kStallWindow);
  }
  if (s.conflict) ++m_.conflict_steps;
  if (s.escaping) ++m_.escape_steps;
  if (s.passing_side * last_side_ < 0) ++m_.side_flips;
  last_side_ = s.passing_side;
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
  }
  return r;
}

}  // namespace sim
}  // namespace amigobot_tracking
