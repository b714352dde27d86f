// Seconds on the monotonic clock: for deadlines, timeouts and ages that a wall-clock step
// (NTP, a user setting the date) must not stretch or cut. One home for the layers above core;
// link/ (below core) keeps its own milliseconds in serial_port.cpp.
#pragma once

#include <chrono>

namespace amigobot_tracking {
namespace core {

inline double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace core
}  // namespace amigobot_tracking
