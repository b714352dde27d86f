#include "amigobot_tracking/core/supervision/input_age.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace amigobot_tracking {
namespace core {

void InputAgeTracker::arrived(double stamp, double now) {
  have_ = true;
  stamp_ = stamp;
  arrival_ = now;
}

void InputAgeTracker::seen(double stamp, double now) {
  if (have_ && stamp == stamp_) return;  // the same sample: it keeps its arrival time
  arrived(stamp, now);
}

InputAge InputAgeTracker::at(double now) const {
  InputAge out;
  out.have = have_;
  if (!have_) return out;
  const double inf = std::numeric_limits<double>::infinity();
  if (!std::isfinite(stamp_) || !std::isfinite(now)) {
    out.age = inf;
    out.problem = "time is not finite";
  } else if (stamp_ == 0.0) {
    out.age = inf;
    out.problem = "stamp is 0";
  } else if (stamp_ - now > future_tolerance_) {
    std::ostringstream why;
    why.precision(3);
    why << std::fixed << "stamped " << stamp_ - now << " s in the future (tolerance " << future_tolerance_ << " s)";
    out.age = inf;
    out.problem = why.str();
  } else {
    out.age = std::max({now - stamp_, now - arrival_, 0.0});
  }
  return out;
}

}  // namespace core
}  // namespace amigobot_tracking
