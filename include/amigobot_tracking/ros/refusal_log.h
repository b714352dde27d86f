// When to log that an input was refused: at once when the reason changes (a second kind of
// bad input must not hide behind the first one's throttle), else every `period` [s] while
// it lasts. The caller logs (its own logger, file and line) and serialises the calls.
#pragma once

#include <string>

#include <ros/time.h>

namespace amigobot_tracking {
namespace ros_layer {

class RefusalLog {
 public:
  explicit RefusalLog(double period = 5.0) : period_(period) {}
  // Records `why`; true when it should be logged now.
  bool due(const std::string& why) { return due(why, why); }
  // The same, throttled by `kind`: reasons of one kind whose figures change from one input
  // to the next (beam counts, a measured rate) are logged once per period.
  bool due(const std::string& why, const std::string& kind) {
    const ros::WallTime now = ros::WallTime::now();
    const bool log = kind != kind_ || (now - logged_).toSec() >= period_;
    if (log) logged_ = now;
    last_ = why;
    kind_ = kind;
    return log;
  }
  void clear() { last_.clear(), kind_.clear(); }  // the input was used
  const std::string& last() const { return last_; }  // the current refusal, or ""

 private:
  const double period_;
  std::string last_, kind_;
  ros::WallTime logged_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
