// What the tracking node counts for its diagnostics and the benchmark: whole control cycles
// (steady clock) and how often the diamond clipped the command.
#pragma once

#include <chrono>
#include <cstdint>

namespace amigobot_tracking {
namespace ros_layer {

// Timing of whole control cycles (steady clock), for diagnostics and the benchmark.
struct CycleStats {
  std::uint64_t cycles = 0;
  double last_us = 0.0;
  double max_us = 0.0;
  double sum_us = 0.0;
};

class TrackingStatistics {
 public:
  using Clock = std::chrono::steady_clock;

  // A controller step whose command was sent; `saturated`: the diamond clipped it.
  void addStep(bool saturated);
  // The end of a cycle that started (wall clock) at `start`, at node time t [s]: the
  // saturation ratio is taken over windows of about one second.
  void endCycle(double t, Clock::time_point start);

  const CycleStats& cycles() const { return cycles_; }
  double meanCycleUs() const { return cycles_.cycles ? cycles_.sum_us / cycles_.cycles : 0.0; }
  double saturationRatio() const { return saturation_ratio_; }  // of the last full window

 private:
  CycleStats cycles_;
  std::uint64_t window_steps_ = 0, window_saturated_ = 0;
  double window_start_ = 0.0;  // [s]
  double saturation_ratio_ = 0.0;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
