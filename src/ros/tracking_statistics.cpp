#include "amigobot_tracking/ros/tracking_statistics.h"

#include <algorithm>

namespace amigobot_tracking {
namespace ros_layer {

void TrackingStatistics::addStep(bool saturated) {
  ++window_steps_;
  if (saturated) ++window_saturated_;
}

void TrackingStatistics::endCycle(double t, Clock::time_point start) {
  ++cycles_.cycles;
  if (t - window_start_ >= 1.0) {
    saturation_ratio_ = window_steps_ ? static_cast<double>(window_saturated_) / window_steps_ : 0.0;
    window_steps_ = window_saturated_ = 0;
    window_start_ = t;
  }
  const double us = std::chrono::duration<double, std::micro>(Clock::now() - start).count();
  cycles_.last_us = us;
  cycles_.max_us = std::max(cycles_.max_us, us);
  cycles_.sum_us += us;
}

}  // namespace ros_layer
}  // namespace amigobot_tracking
