#include "amigobot_tracking/sim/target_sensor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "amigobot_tracking/core/robot/unicycle.h"

namespace amigobot_tracking {
namespace sim {

std::string TargetSensorConfig::validate() const {
  std::ostringstream err;
  if (!std::isfinite(sample_period) || sample_period < 0.0)
    err << "sample_period must be >= 0 (0 = every step), got " << sample_period;
  else if (!std::isfinite(noise_std) || noise_std < 0.0)
    err << "noise_std must be >= 0, got " << noise_std;
  else if (!std::isfinite(delay) || delay < 0.0)
    err << "delay must be >= 0, got " << delay;
  else
    for (const TargetJump& jump : jumps)
      if (!std::isfinite(jump.t) || !jump.offset.allFinite()) {
        err << "jumps: every jump needs a finite t and offset";
        break;
      }
  return err.str();
}

TargetSensor::TargetSensor(const TargetSensorConfig& config, const core::Reference& reference)
    : config_(config), reference_(reference), rng_(config.seed), noise_(0.0, 1.0) {
  sample_ = take(0.0);
  index_ = 0;
}

core::TargetSample TargetSensor::take(double t_taken) {
  core::TargetSample s;
  s.stamp = t_taken;
  s.position = reference_.at(t_taken).position;
  for (const TargetJump& jump : config_.jumps)
    if (t_taken >= jump.t) s.position += jump.offset;
  if (config_.noise_std > 0.0) s.position += config_.noise_std * Eigen::Vector2d(noise_(rng_), noise_(rng_));
  return s;
}

const core::TargetSample& TargetSensor::at(double t) {
  const double taken_by = t - config_.delay;
  if (taken_by <= 0.0) return sample_;
  if (config_.sample_period <= 0.0) {
    if (taken_by > sample_.stamp) sample_ = take(taken_by);
    return sample_;
  }
  // Small tolerance: steps that land on a sample time by summation must take it.
  const auto index = static_cast<std::int64_t>(std::floor(taken_by / config_.sample_period + 1e-9));
  if (index > index_) {
    index_ = index;
    sample_ = take(static_cast<double>(index) * config_.sample_period);
  }
  return sample_;
}

double TargetSensor::nextDelivery(double t) const {
  if (config_.sample_period <= 0.0) return std::numeric_limits<double>::infinity();
  const double taken_by = t - config_.delay;
  const double next_index = std::floor(taken_by / config_.sample_period + 1e-9) + 1.0;
  return std::max(0.0, next_index) * config_.sample_period + config_.delay;
}

std::string PoseSensorConfig::validate() const {
  std::ostringstream err;
  if (!std::isfinite(sample_period) || sample_period < 0.0)
    err << "pose_sample_period must be >= 0 (0 = continuous), got " << sample_period;
  else if (!std::isfinite(delay) || delay < 0.0)
    err << "pose_delay must be >= 0, got " << delay;
  return err.str();
}

void PoseSensor::record(double t, const core::Pose2& pose) { history_.push_back({t, pose, core::Twist2()}); }

void PoseSensor::hold(const core::Twist2& u) {
  if (!history_.empty()) history_.back().u = u;
}

core::PoseSample PoseSensor::at(double t) {
  if (history_.empty()) return {};
  double stamp = t - config_.delay;
  if (config_.sample_period > 0.0)  // same tolerance as the target sensor
    stamp = std::floor(stamp / config_.sample_period + 1e-9) * config_.sample_period;
  stamp = std::clamp(stamp, history_.front().t, t);
  // Stamps only grow: records before the one that holds this stamp are no longer needed.
  while (history_.size() > 1 && history_[1].t <= stamp) history_.pop_front();
  const Record& r = history_.front();
  return {stamp, stamp > r.t ? core::integrateUnicycle(r.pose, r.u, stamp - r.t) : r.pose};
}

double PoseSensor::nextDelivery(double t) const {
  if (config_.sample_period <= 0.0) return std::numeric_limits<double>::infinity();
  const double next_index = std::floor((t - config_.delay) / config_.sample_period + 1e-9) + 1.0;
  return std::max(0.0, next_index) * config_.sample_period + config_.delay;
}

}  // namespace sim
}  // namespace amigobot_tracking
