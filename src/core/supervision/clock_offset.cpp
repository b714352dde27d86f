#include "amigobot_tracking/core/supervision/clock_offset.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace amigobot_tracking {
namespace core {

namespace {
constexpr std::size_t kMaxSamples = 4096;  // 2 s of a 1 kHz stream: bounds the memory of a flood
}

void ClockOffsetEstimator::add(double stamp, double arrival) {
  if (!std::isfinite(stamp) || !std::isfinite(arrival)) return;
  samples_.push_back({arrival, arrival - stamp});
  while (!samples_.empty() && (samples_.front().arrival <= arrival - window_ || samples_.size() > kMaxSamples)) {
    samples_.pop_front();
  }
}

ClockOffset ClockOffsetEstimator::at(double now) const {
  ClockOffset out;
  for (const Sample& s : samples_) {
    if (s.arrival <= now - window_ || s.arrival > now) continue;
    out.offset = out.samples == 0 ? s.delta : std::min(out.offset, s.delta);
    ++out.samples;
  }
  return out;
}

std::string clockOffsetText(const std::string& source, double offset) {
  std::ostringstream text;
  text.precision(2);
  text << std::fixed << source << " clock " << std::abs(offset) << " s " << (offset >= 0.0 ? "behind" : "ahead of")
       << " this machine: synchronise the clocks (chrony)";
  return text.str();
}

}  // namespace core
}  // namespace amigobot_tracking
