#include "amigobot_tracking/core/perception/scan_health.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace amigobot_tracking {
namespace core {
namespace {

constexpr double kMinWindow = 2.0;       // [s] a hiccup of a few tenths under load is no rate
constexpr double kWindowPeriods = 20.0;  // promised periods per window: enough scans to count

}  // namespace

std::string blindScanProblem(const ScanGeometry& geometry, const float* ranges, std::size_t count) {
  std::size_t far = 0, nan = 0, near = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const float r = ranges[i];
    if (std::isnan(r)) {
      ++nan;
    } else if (r < geometry.range_min) {
      ++near;
    } else if (r >= geometry.range_max) {  // +inf included
      ++far;
    } else {
      return "";  // one return is enough: the laser sees
    }
  }
  std::ostringstream err;
  err << "laser sees nothing: " << count << " beams, ";
  if (far == count) {
    err << "all at or beyond range_max " << geometry.range_max << " m";
  } else {
    err << "none within [range_min " << geometry.range_min << ", range_max " << geometry.range_max << ") m (" << far
        << " at or beyond range_max, " << nan << " NaN, " << near << " below range_min)";
  }
  err << "; set ~open_space if the lab really is empty around the laser";
  return err.str();
}

double ScanRateJudge::promisedRate() const {
  if (config_.expected_rate > 0.0) return config_.expected_rate;
  return scan_time_ > 0.0 && std::isfinite(scan_time_) ? 1.0 / scan_time_ : 0.0;
}

double ScanRateJudge::window() const {
  const double promised = promisedRate();
  return promised > 0.0 ? std::max(kMinWindow, kWindowPeriods / promised) : kMinWindow;
}

void ScanRateJudge::arrived(double now, double scan_time) {
  if (!std::isfinite(now)) return;
  scan_time_ = std::isfinite(scan_time) && scan_time > 0.0 ? scan_time : 0.0;
  const double w = window();
  // A stall (or time going backwards) is not a rate: count again from here.
  if (arrivals_.empty() || now < arrivals_.back() || now - arrivals_.back() > 0.5 * w) {
    arrivals_.clear();
    since_ = now;
  }
  arrivals_.push_back(now);
  while (arrivals_.front() <= now - w) arrivals_.pop_front();
}

double ScanRateJudge::measuredRate() const {
  if (arrivals_.empty()) return 0.0;
  const double w = window();
  if (arrivals_.back() - since_ < w || arrivals_.size() < 2) return 0.0;  // not one full window yet
  // Intervals over their span: exact for a steady laser, whatever its phase in the window.
  return static_cast<double>(arrivals_.size() - 1) / (arrivals_.back() - arrivals_.front());
}

std::string ScanRateJudge::problem() const {
  const double promised = promisedRate();
  if (!(config_.min_fraction > 0.0) || !(promised > 0.0)) return "";
  const double measured = measuredRate();
  if (measured <= 0.0 || measured >= config_.min_fraction * promised) return "";
  char why[200];
  std::snprintf(why, sizeof(why),
                "scan rate %.1f Hz is below %.2f x the %.1f Hz the laser promises (%s): scans are being lost",
                measured, config_.min_fraction, promised,
                config_.expected_rate > 0.0 ? "expected_scan_rate" : "its scan_time");
  return why;
}

}  // namespace core
}  // namespace amigobot_tracking
