#include "amigobot_tracking/core/metrics.h"

#include <algorithm>
#include <cmath>

namespace amigobot_tracking {
namespace core {

void MetricsAccumulator::add(const MetricSample& s) {
  ++m_.steps;
  const double e_norm = s.e.norm();
  const bool finite = s.valid && std::isfinite(e_norm) && s.u.isFinite() && std::isfinite(s.h) &&
                      !std::isnan(s.rho) && !std::isnan(s.clearance_offset) && !std::isnan(s.clearance_body) &&
                      s.velocity_error.allFinite();
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
}

RunMetrics MetricsAccumulator::result() const {
  RunMetrics r = m_;
  if (r.sim_time > 0.0) {
    r.ase = sum_e2_ / r.sim_time;
    r.aae = sum_e_ / r.sim_time;
    r.estimator_rms_error = std::sqrt(sum_v2_ / r.sim_time);
  }
  return r;
}

}  // namespace core
}  // namespace amigobot_tracking
