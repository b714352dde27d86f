// AriaClient's settings for the firmware after OPEN: the CONFIGpac request, the sonar
// POLLING order and the odometry calibration (read back and logged).
#include <string>

#include "amigobot_tracking/aria/client.h"
#include "amigobot_tracking/aria/commands.h"

namespace amigobot_tracking {
namespace aria {
namespace {

constexpr double kConfigRetry = 0.2;  // [s] ARIA re-requests CONFIGpac this often

std::string valueOrNone(const std::optional<std::uint16_t>& value) {
  return value ? std::to_string(*value) : std::string("not reported");
}

}  // namespace

std::optional<ConfigPac> AriaClient::requestConfig(bool& have_sip) {
  std::optional<ConfigPac> config;
  for (double waited = 0.0; !config && waited < config_.config_timeout && !stop_requested_; waited += kConfigRetry) {
    send(commandPacket(Command::kConfig, 1));
    receiveFor(kConfigRetry, [&](const Packet& p) {
      have_sip = have_sip || isSipType(p.type);
      if (p.type != kConfigPacType) return false;
      std::string error;
      config = decodeConfigPac(p, &error);
      if (!config) log(LogLevel::kWarn, error);
      return config.has_value();
    });
  }
  return config;
}

std::optional<ConfigPac> AriaClient::configureFirmware(std::optional<ConfigPac> config) {
  const std::vector<int>& polling = config_.robot.sonar_polling;
  if (!polling.empty()) {
    // POLLING's string holds transducer numbers counted from 1.
    std::string order;
    for (int index : polling) order.push_back(static_cast<char>(index + 1));
    send(commandPacket(Command::kPolling, order));
  }
  if (config_.ticks_mm == 0 && config_.drift_factor == 0 && config_.rev_count == 0) return config;
  if (config_.ticks_mm != 0) send(commandPacket(Command::kTicksMM, config_.ticks_mm));
  if (config_.drift_factor != 0) send(commandPacket(Command::kDriftFactor, config_.drift_factor));
  if (config_.rev_count != 0) send(commandPacket(Command::kRevCount, config_.rev_count));
  bool have_sip = false;
  std::optional<ConfigPac> after = requestConfig(have_sip);
  if (!after) {
    log(LogLevel::kWarn, "calibration sent, but no CONFIGpac came to read it back");
    return config;
  }
  const std::string text = "calibration read back from CONFIGpac: TicksMM " + valueOrNone(after->ticks_mm) +
                     ", DriftFactor " + (after->drift_factor ? std::to_string(*after->drift_factor) : "not reported") +
                     ", RevCount " + std::to_string(after->rev_count);
  const bool took = (config_.ticks_mm == 0 || after->ticks_mm == config_.ticks_mm) &&
                    (config_.drift_factor == 0 || after->drift_factor == config_.drift_factor) &&
                    (config_.rev_count == 0 || after->rev_count == config_.rev_count);
  log(took ? LogLevel::kInfo : LogLevel::kWarn, text + (took ? "" : " (the firmware ignored some of it)"));
  return after;
}

}  // namespace aria
}  // namespace amigobot_tracking
