#include "amigobot_tracking/core/supervision/command_lock.h"

namespace amigobot_tracking {
namespace core {

bool CommandLock::accept(const std::string& publisher, double now) {
  if (!source_.empty()) return publisher == source_;
  // Free, or the holder has been silent long enough (a NaN time never releases the lock).
  if (holder_.empty() || now - last_ > release_after_) holder_ = publisher;
  if (publisher != holder_) return false;
  last_ = now;
  return true;
}

}  // namespace core
}  // namespace amigobot_tracking
