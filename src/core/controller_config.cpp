#include "amigobot_tracking/core/controller_config.h"

#include <cmath>
#include <sstream>

#include "amigobot_tracking/core/band_implicit.h"
#include "amigobot_tracking/core/diamond.h"

namespace amigobot_tracking {
namespace core {
namespace {

// Appends "name must be > 0, got value" when value is not positive and finite.
bool requirePositive(std::ostringstream& err, const char* name, double value) {
  if (std::isfinite(value) && value > 0.0) return true;
  err << name << " must be a finite number > 0, got " << value;
  return false;
}

}  // namespace

std::string ControllerConfig::validate() const {
  std::ostringstream err;
  const bool positives = requirePositive(err, "radius (robot_radius R)", robot_radius) &&
                         requirePositive(err, "offset (r)", offset) &&
                         requirePositive(err, "v_max", v_max) && requirePositive(err, "w_max", w_max) &&
                         requirePositive(err, "k_d", k_d) && requirePositive(err, "k_o", k_o) &&
                         requirePositive(err, "k_r", k_r) && requirePositive(err, "lambda", lambda) &&
                         requirePositive(err, "rho_inf", rho_inf) && requirePositive(err, "delta", delta) &&
                         requirePositive(err, "min_margin", min_margin);
  if (!positives) return err.str();
  if (!std::isfinite(rho_0) || rho_0 <= rho_inf) {
    err << "rho_0 must be > rho_inf = " << rho_inf << ", got " << rho_0;
  } else if (!(max_error_ratio > 0.0 && max_error_ratio < 1.0)) {
    err << "max_error_ratio must be in (0, 1), got " << max_error_ratio;
  } else if (!(max_error_ratio > sustainedConflictRatio(k_r, k_o))) {
    err << "max_error_ratio must be above " << sustainedConflictRatio(k_r, k_o)
        << ", the |e|/rho of a sustained conflict for k_r = " << k_r << " and k_o = " << k_o
        << " (xi atanh xi = k_o / k_r; raise max_error_ratio or k_r), got " << max_error_ratio;
  } else if (!(std::isfinite(max_relaxation_interval) && max_relaxation_interval > 0.0)) {
    err << "max_relaxation_interval must be a finite number > 0, got " << max_relaxation_interval;
  } else if (min_margin >= delta) {
    err << "min_margin must be < delta = " << delta << ", got " << min_margin;
  } else if (!(std::isfinite(k_t) && k_t >= 0.0)) {
    err << "k_t must be a finite number >= 0, got " << k_t;
  } else if (!(tangential_hysteresis >= 0.0 && tangential_hysteresis < 1.0)) {
    err << "tangential_hysteresis must be in [0, 1), got " << tangential_hysteresis;
  } else if (!(std::isfinite(obstacle_horizon) && obstacle_horizon >= 0.0)) {
    err << "obstacle_horizon must be a finite number >= 0, got " << obstacle_horizon;
  } else if (!(std::isfinite(max_prediction) && max_prediction >= 0.0)) {
    err << "max_prediction must be a finite number >= 0, got " << max_prediction;
  } else {
    return estimator.validate();
  }
  return err.str();
}

double sustainedConflictRatio(double k_r, double k_o) {
  const double target = k_o / k_r;
  double lo = 0.0, hi = 1.0;  // xi atanh xi increases from 0 to +inf on [0, 1)
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid * std::atanh(mid) < target) lo = mid; else hi = mid;
  }
  return hi;
}

std::string bandReachError(const ControllerConfig& config, double control_period) {
  const double reach = maxOffsetSpeed(DiamondSet(config.v_max, config.w_max), config.offset) * control_period;
  if (reach < config.delta) return "";
  std::ostringstream err;
  err << "delta = " << config.delta << " m is crossed in one control period: the offset point moves up to "
      << reach << " m in " << control_period << " s (v_max = " << config.v_max << " m/s, w_max = " << config.w_max
      << " rad/s, offset = " << config.offset << " m); raise delta above " << reach
      << " m, lower v_max/w_max or raise control_rate";
  return err.str();
}

}  // namespace core
}  // namespace amigobot_tracking
