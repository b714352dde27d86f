// Lets a stamped message through only when its stamp is later than the last one let through.
// The localisation's map -> odom is re-sent at tf_rate with the clock's time: under
// use_sim_time a replayed clock stands still between /clock messages (or runs slower than the
// wall), and re-sending the same stamp makes tf2 warn TF_REPEATED_DATA for each. Thread-safe.
#pragma once

#include <mutex>

#include <ros/time.h>

namespace amigobot_tracking {
namespace ros_layer {

class StampGate {
 public:
  // True (and `stamp` becomes the last) when stamp is after the last passed one.
  bool pass(const ros::Time& stamp) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (passed_ && stamp <= last_) return false;
    passed_ = true;
    last_ = stamp;
    return true;
  }

 private:
  std::mutex mutex_;
  bool passed_ = false;
  ros::Time last_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
