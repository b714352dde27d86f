// The age of a stamped input on the receiver's clock (issue 25: a stamp of 0 read as
// "current" and a stamp 30 s ahead clamped to age 0 kept a dead stream fresh for 30 s).
//
// - A stamp of 0, or one further ahead of the receiver's clock than `future_tolerance`, is not
//   trusted: the age is +inf and `problem` says why.
// - Otherwise age = max(now - stamp, now - arrival): a stream that stops goes stale however
//   it was stamped, since arrival is when the receiver last saw a new stamp.
// Times are plain seconds on one clock (ros::Time::toSec() in the ROS layer). Std only.
#pragma once

#include <string>

namespace amigobot_tracking {
namespace core {

struct InputAge {
  bool have = false;  // something was received
  double age = 0.0;   // [s]; +inf when the stamp is not trusted
  std::string problem;  // "" when the stamp is usable: "stamp is 0", "stamped 30.000 s in the future"
};

class InputAgeTracker {
 public:
  explicit InputAgeTracker(double future_tolerance = 0.1) : future_tolerance_(future_tolerance) {}

  // A message with `stamp` arrived at `now` (a subscriber's callback).
  void arrived(double stamp, double now);
  // A polled stream (tf lookups) shows `stamp` at `now`: it counts as an arrival only when
  // the stamp changed, so a frozen transform ages on the receiver's clock.
  void seen(double stamp, double now);
  void clear() { have_ = false; }

  InputAge at(double now) const;

 private:
  double future_tolerance_;
  bool have_ = false;
  double stamp_ = 0.0, arrival_ = 0.0;  // [s]
};

}  // namespace core
}  // namespace amigobot_tracking
