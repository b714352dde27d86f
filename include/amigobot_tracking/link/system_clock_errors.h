// Two POSIX-side helpers every layer above std may use without taking a device link with them:
// one monotonic clock (the emulators' clock, the master watch's and XML-RPC calls' timeouts)
// and the errno text of the system call that just failed.
#pragma once

#include <stdexcept>
#include <string>

namespace amigobot_tracking {
namespace link {

// Monotonic seconds from an arbitrary start, for deadlines and ages the wall clock must not
// stretch (it may jump).
double steadySeconds();

// std::runtime_error "what: strerror(errno)", for the system call that just failed.
std::runtime_error systemError(const std::string& what);

}  // namespace link
}  // namespace amigobot_tracking
