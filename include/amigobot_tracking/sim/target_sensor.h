// How the controller sees the target in the offline loop: sampled every sample_period,
// with Gaussian noise, a transport delay and step jumps (SLAM relocalisations). And how it
// sees its own pose (PoseSensor): localisation samples, late and slow like the target's.
#pragma once

#include <cstdint>
#include <deque>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "amigobot_tracking/core/law/controller.h"
#include "amigobot_tracking/core/reference/reference.h"

namespace amigobot_tracking {
namespace sim {

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
  // Every sample is the reference at the time asked, exactly (no period, noise, delay or jump).
  bool ideal() const { return sample_period <= 0.0 && noise_std <= 0.0 && delay <= 0.0 && jumps.empty(); }
};

class TargetSensor {
 public:
  TargetSensor(const TargetSensorConfig& config, const core::Reference& reference);

  // The newest sample delivered by time t (monotonic t). Stamped with its taking time;
  // before the first delivery, the sample taken at time 0.
  const core::TargetSample& at(double t);
  // The next time after t at which a new sample arrives (+inf without sampling period).
  double nextDelivery(double t) const;

 private:
  core::TargetSample take(double t_taken);

  TargetSensorConfig config_;
  const core::Reference& reference_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> noise_;
  std::int64_t index_ = -1;  // index of the last sample taken (periodic sampling)
  core::TargetSample sample_;
};

// The robot's own pose as localisation (SLAM) reports it: the true pose taken every
// sample_period and delivered `delay` later. Both 0: the true pose at every step.
struct PoseSensorConfig {
  double sample_period = 0.0;  // [s] 0: continuous sampling
  double delay = 0.0;          // [s] a pose taken at t reaches the controller at t + delay

  bool active() const { return sample_period > 0.0 || delay > 0.0; }
  // Empty when valid, otherwise "field: reason" (fields named pose_sample_period, pose_delay).
  std::string validate() const;
};

class PoseSensor {
 public:
  explicit PoseSensor(const PoseSensorConfig& config) : config_(config) {}

  // The true trajectory, step by step (monotonic t): the pose at t, then the command held
  // from t on. The pose at any earlier time is the exact unicycle arc between records.
  void record(double t, const core::Pose2& pose);
  void hold(const core::Twist2& u);
  // The newest sample delivered by time t (after record(t, ...)), stamped with its taking
  // time; before the first delivery, the pose at the first record.
  core::PoseSample at(double t);
  // The next time after t at which a new sample arrives (+inf with continuous sampling).
  double nextDelivery(double t) const;

 private:
  struct Record {
    double t;
    core::Pose2 pose;
    core::Twist2 u;
  };
  PoseSensorConfig config_;
  std::deque<Record> history_;
};

}  // namespace sim
}  // namespace amigobot_tracking
