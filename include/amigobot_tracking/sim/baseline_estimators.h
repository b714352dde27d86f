// Baseline target-velocity estimators, to compare with the paper's estimator (3)-(4):
// finite differences through a first-order low-pass filter, and a constant-velocity
// Kalman filter. Both take position samples (t, p) and give a velocity estimate.
#pragma once

#include <memory>
#include <string>

#include <Eigen/Core>

namespace amigobot_tracking {
namespace sim {

class TargetVelocityFilter {
 public:
  virtual ~TargetVelocityFilter() = default;
  // Feeds a sample; returns false (and changes nothing) when t is not after the last
  // stamp or a value is not finite. The first sample initialises with zero velocity.
  virtual bool update(double t, const Eigen::Vector2d& position) = 0;
  virtual Eigen::Vector2d velocity() const = 0;
};

// v_raw = (p_k - p_{k-1}) / h, then v += (1 - exp(-h/tau)) (v_raw - v): the exact
// discretisation of a first-order low-pass of time constant tau for a held input.
class FiniteDifferenceFilter : public TargetVelocityFilter {
 public:
  explicit FiniteDifferenceFilter(double time_constant);
  bool update(double t, const Eigen::Vector2d& position) override;
  Eigen::Vector2d velocity() const override { return velocity_; }

 private:
  double tau_;
  bool initialized_ = false;
  double last_t_ = 0.0;
  Eigen::Vector2d last_p_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d velocity_ = Eigen::Vector2d::Zero();
};

// Per axis, state (position, velocity), white-noise acceleration of standard deviation
// accel_std [m/s^2] (process noise Q = q [[h^3/3, h^2/2], [h^2/2, h]], q = accel_std^2),
// position measurement noise measurement_std [m]. Starts at the first sample with a
// velocity variance of initial_velocity_std^2.
class ConstantVelocityKalman : public TargetVelocityFilter {
 public:
  ConstantVelocityKalman(double accel_std, double measurement_std, double initial_velocity_std = 10.0);
  bool update(double t, const Eigen::Vector2d& position) override;
  Eigen::Vector2d velocity() const override { return {x_[0](1), x_[1](1)}; }

 private:
  double q_, r_, p0_;
  bool initialized_ = false;
  double last_t_ = 0.0;
  Eigen::Vector2d x_[2];  // per axis: (position, velocity)
  Eigen::Matrix2d p_[2];  // per axis covariance
};

}  // namespace sim
}  // namespace amigobot_tracking
