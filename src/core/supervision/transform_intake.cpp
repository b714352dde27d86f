#include "amigobot_tracking/core/supervision/transform_intake.h"

#include <sstream>

namespace amigobot_tracking {
namespace core {

IntakeVerdict TransformIntake::judge(const std::string& child_frame, double stamp, double arrival,
                                     const Translation3& translation, const Quaternion4& rotation, bool is_static) {
  IntakeVerdict verdict;
  verdict.problem = transformProblem(translation, rotation);
  if (is_static || stamp == 0.0) {
    verdict.accept = verdict.problem.empty();
    return verdict;
  }
  auto it = clocks_.find(child_frame);
  if (it == clocks_.end()) it = clocks_.emplace(child_frame, ClockOffsetEstimator(window_)).first;
  it->second.add(stamp, arrival);
  if (verdict.problem.empty() && stamp - arrival > future_tolerance_) {
    std::ostringstream why;
    why.precision(3);
    why << std::fixed << "stamped " << stamp - arrival << " s ahead of its arrival (tolerance " << future_tolerance_
        << " s)";
    verdict.problem = why.str();
  }
  verdict.accept = verdict.problem.empty();
  return verdict;
}

FrameClock TransformIntake::clock(const std::string& frame, double now) const {
  FrameClock out;
  const auto it = clocks_.find(frame);
  if (it == clocks_.end()) return out;
  const double last = it->second.lastArrival();
  out.since_arrival = last < 0.0 ? -1.0 : now - last;
  const ClockOffset c = it->second.at(now);
  out.known = c.samples >= min_samples_;
  out.offset = c.offset;
  if (out.known && (c.offset > future_tolerance_ || c.offset < -future_tolerance_)) {
    out.problem = clockOffsetText(frame, c.offset);
  }
  return out;
}

}  // namespace core
}  // namespace amigobot_tracking
