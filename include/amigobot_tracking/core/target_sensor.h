// How the controller sees the target in the offline loop: sampled every sample_period,
// with Gaussian noise, a transport delay and step jumps (SLAM relocalisations).
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/controller.h"
#include "amigobot_tracking/core/reference.h"

namespace amigobot_tracking {
namespace core {

// From time t on, every measurement is shifted by offset (offsets of passed jumps add up).
struct TargetJump {
  double t = 0.0;                                    // [s]
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();  // [m]
};

struct TargetSensorConfig {
  double sample_period = 0.0;  // [s] 0: a sample at every control step
  double noise_std = 0.0;      // [m] standard deviation of the noise on each axis
  double delay = 0.0;          // [s] a sample taken at t reaches the controller at t + delay
  std::vector<TargetJump> jumps;
  std::uint64_t seed = 1;      // noise generator seed: runs are reproducible

  // Empty when valid, otherwise "field: reason".
  std::string validate() const;
};

class TargetSensor {
 public:
  TargetSensor(const TargetSensorConfig& config, const Reference& reference);

  // The newest sample delivered by time t (monotonic t). Stamped with its taking time;
  // before the first delivery, the sample taken at time 0.
  const TargetSample& at(double t);
  // The next time after t at which a new sample arrives (+inf without sampling period).
  double nextDelivery(double t) const;

 private:
  TargetSample take(double t_taken);

  TargetSensorConfig config_;
  const Reference& reference_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> noise_;
  std::int64_t index_ = -1;  // index of the last sample taken (periodic sampling)
  TargetSample sample_;
};

}  // namespace core
}  // namespace amigobot_tracking
