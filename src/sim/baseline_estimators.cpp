#include "amigobot_tracking/sim/baseline_estimators.h"

#include <cmath>

namespace amigobot_tracking {
namespace sim {

FiniteDifferenceFilter::FiniteDifferenceFilter(double time_constant) : tau_(time_constant) {}

bool FiniteDifferenceFilter::update(double t, const Eigen::Vector2d& position) {
  if (!std::isfinite(t) || !position.allFinite()) return false;
  if (!initialized_) {
    initialized_ = true;
    last_t_ = t;
    last_p_ = position;
    return true;
  }
  const double h = t - last_t_;
  if (!(h > 0.0)) return false;
  const Eigen::Vector2d raw = (position - last_p_) / h;
  velocity_ += (1.0 - std::exp(-h / tau_)) * (raw - velocity_);
  last_t_ = t;
  last_p_ = position;
  return true;
}

ConstantVelocityKalman::ConstantVelocityKalman(double accel_std, double measurement_std,
                                               double initial_velocity_std)
    : q_(accel_std * accel_std), r_(measurement_std * measurement_std),
      p0_(initial_velocity_std * initial_velocity_std) {
  for (int i = 0; i < 2; ++i) {
    x_[i].setZero();
    p_[i].setZero();
  }
}

bool ConstantVelocityKalman::update(double t, const Eigen::Vector2d& position) {
  if (!std::isfinite(t) || !position.allFinite()) return false;
  if (!initialized_) {
    initialized_ = true;
    last_t_ = t;
    for (int i = 0; i < 2; ++i) {
      x_[i] << position(i), 0.0;
      p_[i] << r_, 0.0, 0.0, p0_;
    }
    return true;
  }
  const double h = t - last_t_;
  if (!(h > 0.0)) return false;
  last_t_ = t;
  Eigen::Matrix2d f;
  f << 1.0, h, 0.0, 1.0;
  Eigen::Matrix2d q;
  q << h * h * h / 3.0, h * h / 2.0, h * h / 2.0, h;
  q *= q_;
  for (int i = 0; i < 2; ++i) {
    x_[i] = f * x_[i];
    p_[i] = f * p_[i] * f.transpose() + q;
    const double s = p_[i](0, 0) + r_;
    const Eigen::Vector2d gain = p_[i].col(0) / s;
    x_[i] += gain * (position(i) - x_[i](0));
    // Joseph-free update kept symmetric: P = (I - K H) P.
    p_[i] -= gain * p_[i].row(0);
    p_[i] = 0.5 * (p_[i] + p_[i].transpose()).eval();
  }
  return true;
}

}  // namespace sim
}  // namespace amigobot_tracking
