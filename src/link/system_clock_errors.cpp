#include "amigobot_tracking/link/system_clock_errors.h"

#include <cerrno>
#include <chrono>
#include <cstring>

namespace amigobot_tracking {
namespace link {

std::runtime_error systemError(const std::string& what) { return std::runtime_error(what + ": " + std::strerror(errno)); }

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace link
}  // namespace amigobot_tracking
