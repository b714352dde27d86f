// A rate (control cycles, cmd_vel, SIPs) measured by diagnostic_updater::FrequencyStatus and
// reported inside another task's status: the node's own status keeps one summary, and the
// rate's warning is merged into it only when it counts (e.g. cmd_vel while enabled).
// Header-only: used by both the tracking and the driver libraries.
#pragma once

#include <string>
#include <utility>

#include <diagnostic_updater/diagnostic_updater.h>
#include <diagnostic_updater/update_functions.h>

namespace amigobot_tracking {
namespace ros_layer {

class RateMonitor {
 public:
  // Acceptable rates [min_hz, max_hz] with FrequencyStatus's relative tolerance, measured over
  // `window` diagnostic updates. `label` prefixes the summary and the FrequencyStatus's keys;
  // the measured rate is also added as `measured_key`.
  RateMonitor(std::string label, std::string measured_key, double min_hz, double max_hz, double tolerance,
              int window)
      : label_(std::move(label)),
        measured_key_(std::move(measured_key)),
        min_hz_(min_hz),
        max_hz_(max_hz),
        frequency_(diagnostic_updater::FrequencyStatusParam(&min_hz_, &max_hz_, tolerance, window), label_) {}

  void tick() { frequency_.tick(); }
  // Restarts the window (e.g. when the events start again after a deliberate pause).
  void clear() { frequency_.clear(); }

  // Runs the FrequencyStatus (advancing its window); merges its summary into `status` when
  // `counts`, and adds its values.
  void report(diagnostic_updater::DiagnosticStatusWrapper& status, bool counts) {
    diagnostic_updater::DiagnosticStatusWrapper rate;
    frequency_.run(rate);
    double measured = 0.0;  // FrequencyStatus leaves the rate out for an empty window
    for (const auto& kv : rate.values) {
      if (kv.key == "Actual frequency (Hz)") measured = std::stod(kv.value);
    }
    if (counts) status.mergeSummary(rate.level, label_ + ": " + rate.message);
    status.add(measured_key_, measured);
    for (const auto& kv : rate.values) status.add(label_ + ": " + kv.key, kv.value);
  }

 private:
  std::string label_, measured_key_;
  double min_hz_, max_hz_;  // FrequencyStatus keeps pointers to them
  diagnostic_updater::FrequencyStatus frequency_;
};

}  // namespace ros_layer
}  // namespace amigobot_tracking
