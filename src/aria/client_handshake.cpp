// AriaClient's handshake: SYNC0/1/2 (recovering a robot left open), OPEN with the
// motion parameters, and the state reset of a new connection. The I/O loop: client.cpp.
#include "amigobot_tracking/aria/client.h"

#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

#include "amigobot_tracking/aria/commands.h"

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr double kDrainTime = 0.2;  // [s] input drained after opening the port
constexpr double kRadToDeg = 180.0 / M_PI;

}  // namespace

std::optional<RobotIdentity> AriaClient::synchronise() {
  const auto ignore = [](const Packet&) { return false; };
  receiveFor(kDrainTime, ignore);  // stale bytes from an earlier session
  int stage = 0;
  for (int tries = 0; tries < config_.max_sync_tries && !stop_requested_; ++tries) {
    send(syncPacket(stage));
    std::optional<Packet> reply;
    receiveFor(config_.sync_timeout, [&](const Packet& p) {
      reply = p;
      return true;
    });
    if (!reply) {
      log(LogLevel::kDebug, "no reply to SYNC" + std::to_string(stage) + "; restarting at SYNC0");
      stage = 0;
    } else if (reply->type == stage && stage < 2) {
      ++stage;
    } else if (reply->type == kSync2 && stage == 2) {
      std::string error;
      std::optional<RobotIdentity> identity = decodeSync2(*reply, &error);
      if (!identity) throw std::runtime_error(transport_->describe() + ": " + error);
      return identity;
    } else if (isSipType(reply->type)) {
      // The robot is still open from an earlier session: close it, then start again.
      log(LogLevel::kWarn, "robot still open from an earlier session: sending CLOSE and restarting the handshake");
      {
        std::lock_guard<std::mutex> lock(mutex_);
        ++status_.still_open_recoveries;
      }
      for (int i = 0; i < 3; ++i) {
        send(commandPacket(Command::kClose, 1));
        receiveFor(0.1, ignore);
      }
      receiveFor(0.3, ignore);
      stage = 0;
    } else {
      log(LogLevel::kDebug, "unexpected packet type " + std::to_string(reply->type) + " during SYNC" +
                                std::to_string(stage) + "; restarting at SYNC0");
      stage = 0;
    }
  }
  if (stop_requested_) return std::nullopt;
  throw std::runtime_error(transport_->describe() + ": no SYNC0/1/2 handshake after " +
                           std::to_string(config_.max_sync_tries) + " tries (robot off, wrong port or baud?)");
}

std::optional<ConfigPac> AriaClient::openRobot() {
  send(config_.open_with_argument ? commandPacket(Command::kOpen, 1) : commandPacket(Command::kOpen));
  send(commandPacket(Command::kSonar, config_.sonar ? 1 : 0));
  std::optional<ConfigPac> config;
  bool have_sip = false;
  const auto handle = [&](const Packet& p) {
    if (p.type == kConfigPacType) {
      std::string error;
      config = decodeConfigPac(p, &error);
      if (!config) log(LogLevel::kWarn, error);
    }
    have_sip = have_sip || isSipType(p.type);
    return false;
  };
  // CONFIGpac, re-requested every 200 ms as ARIA does.
  for (double waited = 0.0; !config && waited < config_.config_timeout && !stop_requested_; waited += 0.2) {
    send(commandPacket(Command::kConfig, 1));
    receiveFor(0.2, [&](const Packet& p) { return handle(p) || config.has_value(); });
  }
  if (!config && config_.config_timeout > 0.0) {
    log(LogLevel::kWarn, "no CONFIGpac; using the parameter file's limits");
  }
  const auto sendInt = [&](Command c, double value) { send(commandPacket(c, static_cast<int>(std::lround(value)))); };
  if (config_.trans_accel > 0) sendInt(Command::kSetA, config_.trans_accel * 1e3);
  if (config_.trans_decel > 0) sendInt(Command::kSetA, -config_.trans_decel * 1e3);
  if (config_.rot_accel > 0) sendInt(Command::kSetRA, config_.rot_accel * kRadToDeg);
  if (config_.rot_decel > 0) sendInt(Command::kSetRA, -config_.rot_decel * kRadToDeg);
  if (!have_sip) receiveFor(config_.link_timeout, [&](const Packet& p) { return handle(p) || have_sip; });
  if (!have_sip && !stop_requested_) throw std::runtime_error(transport_->describe() + ": robot sent no SIP after OPEN");
  return config;
}

bool AriaClient::connect() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    parser_.reset();
  }
  transport_ = makeTransport(config_.port, config_.baud);
  log(LogLevel::kInfo, "connecting to the robot over " + transport_->describe());
  transport_->open();
  const std::optional<RobotIdentity> identity = synchronise();
  if (!identity) return false;  // stop requested
  if (identity->subclass != config_.robot.model) {
    log(LogLevel::kWarn, "robot reports subclass '" + identity->subclass + "' but the parameters are for '" +
                             config_.robot.model + "'");
  }
  const std::optional<ConfigPac> config = openRobot();
  if (stop_requested_) {
    shutdownRobot();  // stopped halfway: do not leave the robot open
    return false;
  }

  odometry_.relink();
  sent_.reset();
  sip_times_.clear();
  last_sip_ = last_rx_ = Clock::now();
  last_motion_sent_ = last_enable_sent_ = Clock::time_point{};
  {
    std::lock_guard<std::mutex> lock(mutex_);
    status_.identity = identity;
    status_.config = config;
    ++status_.connections;
    status_.last_error.clear();
    if (config_.enable_motors) status_.motors_requested = true;
    motors_request_pending_ = true;  // re-assert the requested motor state on every connection
    status_.link = LinkState::kConnected;
  }
  log(LogLevel::kInfo, "connected to '" + identity->name + "' (" + identity->robot_class + " " + identity->subclass +
                           ") over " + transport_->describe());
  return true;
}

}  // namespace aria
}  // namespace amigobot_tracking
