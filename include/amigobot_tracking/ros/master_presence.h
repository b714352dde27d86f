// What a process knows about its ROS master from polling it, without ROS: reachable or not
// (and for how long not), and whether the master that answers is a new one (another pid),
// which has never heard of this process's topics and services. Fed by ros/master_watch.h.
#pragma once

#include <optional>
#include <string>

namespace amigobot_tracking {
namespace ros_layer {

class MasterPresence {
 public:
  enum class Change { kNone, kLost, kBack, kNewMaster };

  // One poll at `now` [s]: the master's identity (its pid) when it answered, nullopt when
  // it did not. Returns what changed: kLost at the second failed poll in a row after an
  // answer, kNewMaster when an identity other than the last known answers (restarted), kBack
  // when the same one answers again after it was lost (a network hiccup: nothing to redo).
  // One failed poll is not a lost master: a poll that times out (ros/master_watch.h: 0.3 s)
  // has already made the last answer 0.5 s old, and a master busy with registrations missed
  // one poll once in a loaded end-to-end run, which stopped the robot for good. A master that
  // is gone refuses at once, so two polls in a row cost it nothing; one that hangs is
  // lost after two call timeouts.
  Change observe(double now, const std::optional<std::string>& identity) {
    if (!identity) {
      const bool was_reachable = reachable_;
      if (++misses_ >= 2) reachable_ = false;
      return was_reachable && !reachable_ ? Change::kLost : Change::kNone;
    }
    const bool was_reachable = reachable_;
    reachable_ = true;
    misses_ = 0;
    last_answer_ = now;
    if (!identity_) {
      identity_ = identity;
      return Change::kNone;  // the master the process started with
    }
    if (*identity_ != *identity) {
      identity_ = identity;
      return Change::kNewMaster;
    }
    return was_reachable ? Change::kNone : Change::kBack;
  }

  bool everReached() const { return identity_.has_value(); }
  bool reachable() const { return reachable_; }
  // [s] since the last answer; 0 while reachable or before the first answer (a process
  // that never reached its master has other problems, and ROS itself waits for it).
  double unreachableFor(double now) const { return reachable_ || !identity_ ? 0.0 : now - last_answer_; }
  const std::optional<std::string>& identity() const { return identity_; }

 private:
  std::optional<std::string> identity_;
  bool reachable_ = false;
  int misses_ = 0;  // failed polls in a row
  double last_answer_ = 0.0;
};

// What a user of the watch (the driver's motors, the tracking loop) does about an outage of the
// master, from the watch's state at each of its own checks: stop when the master has been
// unreachable longer than the user's timeout; when a master answers again, resume if it is the
// one that answered before the stop (it was busy or a link hiccuped: it still knows every
// topic and service, so the robot can be stopped through ROS again), stay stopped if it is a
// new one (restarted: whoever commanded the robot must say so again). Before, every outage
// latched: a master that missed polls for 1 s while three stacks started at once on 2 cores
// left a robot whose motors stayed off until someone called enable_motors.
class MasterOutage {
 public:
  enum class Action { kNone, kStop, kResume, kStayStopped };

  Action check(bool reachable, double unreachable_for, const std::optional<std::string>& identity, double timeout) {
    if (!stopped_) {
      if (!(unreachable_for > timeout)) return Action::kNone;
      stopped_ = true;
      identity_at_stop_ = identity;
      return Action::kStop;
    }
    if (!reachable) return Action::kNone;
    stopped_ = false;
    return identity && identity == identity_at_stop_ ? Action::kResume : Action::kStayStopped;
  }
  bool stopped() const { return stopped_; }

 private:
  bool stopped_ = false;
  std::optional<std::string> identity_at_stop_;  // the master that answered last before the stop
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
