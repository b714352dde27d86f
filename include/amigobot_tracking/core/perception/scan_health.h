// Is the laser still seeing? Two judgements on the scans the tracking node receives, pure so
// every rule is unit-tested (the node only wires them). Std only.
//
// - Blind: a scan with no return inside the sensor's real range (every beam at or beyond
//   range_max, +inf, NaN, or below range_min) looks exactly like an empty room. A laser that
//   lost its echo (dirty window, tilted mount, a failing receiver, a driver reporting "no
//   return" everywhere) gives it too, and the robot would drive through a pole it no longer
//   sees. Unless the lab declares an open space, such a scan is refused like a broken one:
//   it does not refresh the scan's age, so the robot stops after scan_timeout. The rule holds
//   from the first scan: a laser blind from power-on is as dangerous as one that goes blind.
// - Rate: every LaserScan promises the next one after scan_time. When the measured rate falls
//   below min_fraction of the promised one (every other scan lost on a saturated link, an
//   overloaded driver), the obstacles the robot avoids are older than the laser's data sheet
//   says: the robot stops, naming both rates.
#pragma once

#include <cstddef>
#include <deque>
#include <string>

#include "amigobot_tracking/core/perception/scan_obstacles.h"

namespace amigobot_tracking {
namespace core {

// "" when at least one beam returns within [range_min, range_max) of `geometry`, else
// "laser sees nothing: ..." counting the beams by kind. The geometry is checked before
// (scanBeamsProblem).
std::string blindScanProblem(const ScanGeometry& geometry, const float* ranges, std::size_t count);

struct ScanRateConfig {
  double min_fraction = 0.7;   // [-] measured / promised below this is a fault; 0 = off
  double expected_rate = 0.0;  // [Hz] > 0: the laser's rate, instead of each scan's scan_time
};

// The measured scan rate against the promised one. The rate is counted over a window of
// max(2 s, 20 promised periods) ending at the latest arrival: a laser that stops altogether
// is the scan_timeout's fault, not a rate, and its last rate stays as it was. A gap longer
// than half the window restarts the count (the scans came back after a stall). No verdict
// until the scans have come for one full window, nor when nothing promises a rate
// (scan_time 0 and no expected_rate).
class ScanRateJudge {
 public:
  explicit ScanRateJudge(const ScanRateConfig& config = ScanRateConfig()) : config_(config) {}

  // A scan arrived at `now` [s] promising the next one `scan_time` [s] later (0: unknown).
  void arrived(double now, double scan_time);
  // "" while the rate is good or not judged, else "scan rate 7.5 Hz is below 0.7 x the 15.0 Hz
  // the laser promises (...)".
  std::string problem() const;
  double promisedRate() const;  // [Hz], 0 when unknown
  double measuredRate() const;  // [Hz] over the window, 0 before a full window

 private:
  double window() const;  // [s]

  ScanRateConfig config_;
  std::deque<double> arrivals_;  // [s], within one window of the latest
  double since_ = 0.0;           // [s] first arrival of the current count
  double scan_time_ = 0.0;       // [s] the latest scan's promise
};

}  // namespace core
}  // namespace amigobot_tracking
