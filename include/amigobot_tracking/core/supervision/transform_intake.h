// Judges each incoming tf sample before it reaches the transform buffer (the ROS wiring is
// ros/guarded_tf_listener.h), and keeps per child frame an estimate of its publisher's clock.
//
// - A NaN/inf coordinate or a non-unit quaternion is refused (transform_check.h).
// - A dynamic sample stamped further ahead of its arrival than `future_tolerance` is dropped:
//   a buffer keeps the newest stamp as "latest", so one sample stamped 30 s ahead would
//   otherwise hide every good sample after it for 30 s. Not remembered: the next good sample
//   is used at once.
// - Every dynamic sample (dropped ones too) feeds the frame's ClockOffsetEstimator; with at
//   least `min_samples` in the window, an offset beyond `future_tolerance` either way names
//   the frame's clock (a single stray stamp does not).
// Static samples (tf_static) are only checked for NaN: their stamps carry no time. A stamp of
// 0 is left to the reader's age check (core/supervision/input_age.h names it). Not thread-safe.
#pragma once

#include <cstddef>
#include <map>
#include <string>

#include "amigobot_tracking/core/supervision/clock_offset.h"
#include "amigobot_tracking/core/supervision/transform_check.h"

namespace amigobot_tracking {
namespace core {

struct IntakeVerdict {
  bool accept = true;
  std::string problem;  // why not: "translation x is nan", "stamped 30.000 s ahead of its arrival (tolerance 0.100 s)"
};

struct FrameClock {
  bool known = false;           // enough samples in the window to judge
  double offset = 0.0;          // [s] ClockOffset::offset: > 0 behind this machine, < 0 ahead
  double since_arrival = -1.0;  // [s] since its last sample arrived (dropped ones too), -1: never
  std::string problem;          // clockOffsetText(...) when |offset| > future_tolerance, else ""
};

class TransformIntake {
 public:
  explicit TransformIntake(double future_tolerance = 0.1, double window = 2.0, std::size_t min_samples = 5)
      : future_tolerance_(future_tolerance), window_(window), min_samples_(min_samples) {}

  IntakeVerdict judge(const std::string& child_frame, double stamp, double arrival, const Translation3& translation,
                      const Quaternion4& rotation, bool is_static);
  FrameClock clock(const std::string& frame, double now) const;

 private:
  double future_tolerance_, window_;
  std::size_t min_samples_;
  std::map<std::string, ClockOffsetEstimator> clocks_;  // by child frame, dynamic samples only
};

}  // namespace core
}  // namespace amigobot_tracking
