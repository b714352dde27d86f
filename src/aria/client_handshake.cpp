// AriaClient's connection sequence (ArRobot::asyncConnectHandler): SYNC0/1/2 with the
// recoveries for a robot left open (at this baud or another), OPEN, CONFIG, the baud switch.
#include <stdexcept>

#include "amigobot_tracking/aria/client.h"
#include "amigobot_tracking/aria/commands.h"

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr double kDrainTime = 0.2;    // [s] input drained after opening the port
constexpr double kBaudSettle = 0.1;   // [s] a command's bytes leave (and reach the robot's
                                      // UART) before the line changes speed under them
constexpr double kBaudVerify = 0.9;   // [s] ARIA's wait for a packet at the new baud
constexpr int kCloseCycleEvery = 4;   // silent SYNCs: the CLOSE cycle at the 2nd, 6th, ...
constexpr int kDislodgeFrom = 4;      // silent SYNCs: OPEN from the 4th on

bool ignore(const Packet&) { return false; }

std::string recoveryBaudList() {
  std::string list;
  for (int baud : kRecoveryBauds) list += (list.empty() ? "" : ", ") + std::to_string(baud);
  return list;
}

}  // namespace

void AriaClient::closeAtEveryBaud() {
  const int home = transport_->baud();
  log(LogLevel::kInfo, "no reply to SYNC: sending CLOSE at " + recoveryBaudList() +
                           " baud (a session may have left the robot open at another baud)");
  for (int baud : kRecoveryBauds) {
    setLineBaud(baud);
    send(commandPacket(Command::kClose, 1));
    receiveFor(kBaudSettle, ignore);
  }
  setLineBaud(home);
  std::lock_guard<std::mutex> lock(mutex_);
  ++status_.baud_recoveries;
}

std::optional<RobotIdentity> AriaClient::synchronise() {
  receiveFor(kDrainTime, ignore);  // stale bytes from an earlier session
  const std::uint64_t garbage_before = parser_.stats().garbage_bytes;
  int stage = 0;
  int misses = 0;
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
      ++misses;
      if (transport_->isSerial() && misses % kCloseCycleEvery == 2) closeAtEveryBaud();
      // A robot that took SYNC2 but never OPEN answers nothing until it is opened.
      if (misses >= kDislodgeFrom) send(commandPacket(Command::kOpen, 1));
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
  std::string why = transport_->describe() + ": no SYNC0/1/2 handshake after " +
                    std::to_string(config_.max_sync_tries) + " tries";
  if (transport_->isSerial() && misses >= 2) why += ", CLOSE at " + recoveryBaudList() + " baud did not free the robot";
  const std::uint64_t garbage = parser_.stats().garbage_bytes - garbage_before;
  if (garbage > 0) {
    why += "; " + std::to_string(garbage) +
           " bytes arrived that formed no packet: the robot talks at a baud none of these (or the line is broken)";
  } else {
    why += " (robot off, wrong port or baud?)";
  }
  throw std::runtime_error(why);
}

void AriaClient::negotiateBaud(const std::optional<ConfigPac>& config) {
  // TCP carries no baud: a serial-to-TCP bridge or a simulator sets its own.
  if (!transport_->isSerial() || stop_requested_) return;
  const int current = transport_->baud();
  const int target = config_.robot.switch_to_baud;
  if (target <= current) return;
  if (!config || config->auto_baud.value_or(0) != 2) {
    log(LogLevel::kInfo, std::string(config ? "robot does not allow a baud switch (CONFIGpac AutoBaud " +
                                                  std::to_string(config->auto_baud.value_or(0)) + ")"
                                            : "no CONFIGpac") +
                             ": staying at " + std::to_string(current) + " baud");
    return;
  }
  send(commandPacket(Command::kHostBaud, hostBaudIndex(target)));
  receiveFor(kBaudSettle, ignore);
  setLineBaud(target);
  send(commandPacket(Command::kPulse));
  if (receiveFor(kBaudVerify, [](const Packet& p) { return isSipType(p.type); })) {
    log(LogLevel::kInfo, "link switched to " + std::to_string(target) + " baud");
    return;
  }
  setLineBaud(current);
  log(LogLevel::kWarn, "no SIP within 900 ms at " + std::to_string(target) + " baud after HOSTBAUD: back to " +
                           std::to_string(current) + " baud");
}

std::optional<ConfigPac> AriaClient::openRobot() {
  send(config_.open_with_argument ? commandPacket(Command::kOpen, 1) : commandPacket(Command::kOpen));
  send(commandPacket(Command::kSonar, config_.sonar ? 1 : 0));
  bool have_sip = false;
  std::optional<ConfigPac> config = requestConfig(have_sip);
  if (!config && config_.config_timeout > 0.0) {
    log(LogLevel::kWarn, "no CONFIGpac; using the parameter file's limits");
  }
  negotiateBaud(config);
  config = configureFirmware(std::move(config));
  sendAccelerations();
  if (!have_sip) {
    receiveFor(config_.link_timeout, [&](const Packet& p) { return have_sip = have_sip || isSipType(p.type); });
  }
  if (!have_sip && !stop_requested_) throw std::runtime_error(transport_->describe() + ": robot sent no SIP after OPEN");
  return config;
}

}  // namespace aria
}  // namespace amigobot_tracking
