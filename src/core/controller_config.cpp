#include "amigobot_tracking/core/controller_config.h"

#include <cmath>
#include <sstream>

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

}  // namespace core
}  // namespace amigobot_tracking
