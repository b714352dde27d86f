// cmd_vel arbitration for the driver (issue 25: a second 100 Hz publisher silently overrode
// tracking). One source drives at a time, twist_mux-style but without priorities:
// - `source` configured (a node name): only its commands are taken, ever;
// - `source` empty: the first publisher takes the lock and keeps it while it keeps sending;
//   after `release_after` seconds of its silence the next publisher may take it.
// Commands from any other publisher are refused; the caller warns (throttled) naming it.
// Std only; times are plain seconds on the receiver's clock.
#pragma once

#include <string>
#include <utility>

namespace amigobot_tracking {
namespace core {

class CommandLock {
 public:
  CommandLock(std::string source, double release_after) : source_(std::move(source)), release_after_(release_after) {}

  // True when the command of `publisher` arriving at `now` is to be driven.
  bool accept(const std::string& publisher, double now);

  // Who drives: the configured source, or the publisher holding the lock ("" while free).
  const std::string& owner() const { return source_.empty() ? holder_ : source_; }
  bool configured() const { return !source_.empty(); }

 private:
  std::string source_;
  double release_after_;
  std::string holder_;
  double last_ = 0.0;  // [s] the holder's last command
};

}  // namespace core
}  // namespace amigobot_tracking
