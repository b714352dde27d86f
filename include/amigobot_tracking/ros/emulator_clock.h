// The robot emulator's clock seen from ROS. The world file's people move on the emulator's
// clock (world/world.h); ground_truth_localization publishes on `ground_truth_clock`
// (sensor_msgs/TimeReference) the emulator's time at each ROS stamp, the same stamp as its
// `ground_truth` pose. A reader keeps the latest pair and carries it forward by the ROS time
// elapsed since (exact at the emulator's default --time-scale 1; at 20 Hz pairs a scaled
// clock is off by (scale - 1) x 50 ms at most).
#pragma once

namespace amigobot_tracking {
namespace ros_layer {

class EmulatorClock {
 public:
  // One pair: the emulator's time [s] at ROS time `stamp` [s].
  void add(double stamp, double emulator_time) {
    stamp_ = stamp;
    emulator_time_ = emulator_time;
    known_ = true;
  }
  bool known() const { return known_; }
  // [s] the emulator's time at ROS time `stamp` (0 before any pair: people stand at their start).
  double at(double stamp) const { return known_ ? emulator_time_ + (stamp - stamp_) : 0.0; }

 private:
  bool known_ = false;
  double stamp_ = 0.0, emulator_time_ = 0.0;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
