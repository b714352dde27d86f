// The clock of a remote publisher against this machine's, estimated from its samples alone:
// each sample's arrival - stamp is the transport delay plus the clock offset, so the minimum
// over a sliding window (the sample that was delayed least) estimates the offset, plus the
// smallest delay (about a millisecond on a LAN). Positive: the publisher's clock is behind
// this machine's (its stamps look old); negative: ahead (its stamps look like the future).
// A stream that arrives at a healthy rate with stamps 1 s old is a clock problem, not a dead
// publisher, and says so. Times are plain seconds on this machine's clock. Std only.
#pragma once

#include <cstddef>
#include <deque>
#include <string>

namespace amigobot_tracking {
namespace core {

struct ClockOffset {
  std::size_t samples = 0;  // in the window
  double offset = 0.0;      // [s] min over the window of arrival - stamp; 0 without samples
};

class ClockOffsetEstimator {
 public:
  explicit ClockOffsetEstimator(double window = 2.0) : window_(window) {}
  // A sample stamped `stamp` arrived at `arrival` (arrivals in order; a non-finite pair is ignored).
  void add(double stamp, double arrival);
  // The samples that arrived in (now - window, now].
  ClockOffset at(double now) const;
  double lastArrival() const { return samples_.empty() ? -1.0 : samples_.back().arrival; }

 private:
  struct Sample {
    double arrival, delta;  // delta = arrival - stamp
  };
  double window_;
  std::deque<Sample> samples_;  // oldest first, pruned to the window on add
};

// "target clock 0.45 s behind this machine: synchronise the clocks (chrony)", or "ahead of".
std::string clockOffsetText(const std::string& source, double offset);

}  // namespace core
}  // namespace amigobot_tracking
