// AriaClient's limits changed at run time: checked on the caller's thread, applied on the
// I/O thread between two commands so a command is never judged against half a change.
#include <cmath>

#include "amigobot_tracking/aria/client.h"
#include "amigobot_tracking/aria/commands.h"

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

void copyLimits(const MotionLimits& from, ClientConfig& to) {
  to.v_max = from.v_max;
  to.w_max = from.w_max;
  to.command_timeout = from.command_timeout;
  to.trans_accel = from.trans_accel;
  to.trans_decel = from.trans_decel;
  to.rot_accel = from.rot_accel;
  to.rot_decel = from.rot_decel;
}

}  // namespace

void AriaClient::sendAccelerations() {
  const auto sendInt = [&](Command c, double value) { send(commandPacket(c, static_cast<int>(std::lround(value)))); };
  if (config_.trans_accel > 0) sendInt(Command::kSetA, config_.trans_accel * 1e3);
  if (config_.trans_decel > 0) sendInt(Command::kSetA, -config_.trans_decel * 1e3);
  if (config_.rot_accel > 0) sendInt(Command::kSetRA, config_.rot_accel * kRadToDeg);
  if (config_.rot_decel > 0) sendInt(Command::kSetRA, -config_.rot_decel * kRadToDeg);
}

std::string AriaClient::setMotionLimits(const MotionLimits& limits) {
  std::lock_guard<std::mutex> lock(mutex_);
  ClientConfig candidate = config_;
  copyLimits(limits, candidate);
  const std::string error = candidate.validate();
  const bool same = candidate.v_max == config_.v_max && candidate.w_max == config_.w_max &&
                    candidate.command_timeout == config_.command_timeout &&
                    candidate.trans_accel == config_.trans_accel && candidate.trans_decel == config_.trans_decel &&
                    candidate.rot_accel == config_.rot_accel && candidate.rot_decel == config_.rot_decel;
  if (error.empty()) {
    pending_limits_.reset();
    if (!same) pending_limits_ = limits;  // nothing to send for what already holds
  }
  return error;
}

MotionLimits AriaClient::motionLimits() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (pending_limits_) return *pending_limits_;
  return {config_.v_max,       config_.w_max,     config_.command_timeout, config_.trans_accel,
          config_.trans_decel, config_.rot_accel, config_.rot_decel};
}

void AriaClient::applyPendingLimits() {
  std::optional<MotionLimits> limits;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    limits.swap(pending_limits_);
    if (!limits) return;
    copyLimits(*limits, config_);  // command_timeout is read under this mutex
  }
  diamond_ = core::DiamondSet(limits->v_max, limits->w_max);
  sent_.reset();  // the next command is re-judged against the new diamond and sent
  sendAccelerations();
  log(LogLevel::kInfo, "motion limits changed: v_max " + std::to_string(limits->v_max) + " m/s, w_max " +
                           std::to_string(limits->w_max) + " rad/s, command timeout " +
                           std::to_string(limits->command_timeout) + " s");
}

}  // namespace aria
}  // namespace amigobot_tracking
