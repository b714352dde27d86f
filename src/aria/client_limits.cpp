// AriaClient's limits changed at run time: checked on the caller's thread, applied on the
// I/O thread between two commands so a command is never judged against half a change.
#include <cmath>

#include "amigobot_tracking/aria/client.h"
#include "amigobot_tracking/aria/commands.h"

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

}  // namespace

void AriaClient::sendAccelerations() {
  const auto sendInt = [&](Command c, double value) { send(commandPacket(c, static_cast<int>(std::lround(value)))); };
  if (config_.trans_accel > 0) sendInt(Command::kSetA, config_.trans_accel * 1e3);
  if (config_.trans_decel > 0) sendInt(Command::kSetA, -config_.trans_decel * 1e3);
  if (config_.rot_accel > 0) sendInt(Command::kSetRA, config_.rot_accel * kRadToDeg);
  if (config_.rot_decel > 0) sendInt(Command::kSetRA, -config_.rot_decel * kRadToDeg);
}

std::string AriaClient::setMotionLimits(const ClientConfig& limits) {
  std::lock_guard<std::mutex> lock(mutex_);
  ClientConfig candidate = config_;
  core::copyLiveFields(clientFields(), limits, &candidate);
  const std::string error = candidate.validate();
  if (error.empty()) {
    pending_limits_.reset();
    // Nothing to send for what already holds.
    if (!core::sameLiveFields(clientFields(), candidate, config_)) pending_limits_ = candidate;
  }
  return error;
}

ClientConfig AriaClient::motionLimits() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return pending_limits_ ? *pending_limits_ : config_;
}

void AriaClient::applyPendingLimits() {
  std::optional<ClientConfig> limits;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    limits.swap(pending_limits_);
    if (!limits) return;
    core::copyLiveFields(clientFields(), *limits, &config_);  // command_timeout is read under this mutex
  }
  diamond_ = limits->diamond();
  sent_.reset();  // the next command is re-judged against the new diamond and sent
  sendAccelerations();
  log(LogLevel::kInfo, "motion limits changed: " + core::describeLiveFields(clientFields(), *limits));
}

}  // namespace aria
}  // namespace amigobot_tracking
