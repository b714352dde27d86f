#include "amigobot_tracking/aria/commands.h"

#include <algorithm>
#include <stdexcept>

namespace amigobot_tracking {
namespace aria {

std::vector<std::uint8_t> commandPacket(Command command) {
  return encodePacket(static_cast<std::uint8_t>(command), {});
}

std::vector<std::uint8_t> commandPacket(Command command, int value) {
  return encodePacket(static_cast<std::uint8_t>(command), ArgumentWriter().typedInt(value).bytes());
}

std::vector<std::uint8_t> commandPacket(Command command, const std::string& text) {
  return encodePacket(static_cast<std::uint8_t>(command), ArgumentWriter().typedString(text).bytes());
}

std::vector<std::uint8_t> syncPacket(int n) {
  if (n < 0 || n > 2) throw std::invalid_argument("SYNC number must be 0, 1 or 2, got " + std::to_string(n));
  return encodePacket(static_cast<std::uint8_t>(n), {});
}

int packVel2(int left_units, int right_units) {
  const int left = std::clamp(left_units, -128, 127);
  const int right = std::clamp(right_units, -128, 127);
  const auto pattern = static_cast<std::uint16_t>(((left & 0xFF) << 8) | (right & 0xFF));
  return static_cast<std::int16_t>(pattern);
}

void unpackVel2(int value, int& left_units, int& right_units) {
  const auto pattern = static_cast<std::uint16_t>(value);
  left_units = static_cast<std::int8_t>(pattern >> 8);
  right_units = static_cast<std::int8_t>(pattern & 0xFF);
}

std::vector<std::uint8_t> vel2Packet(int left_units, int right_units) {
  return commandPacket(Command::kVel2, packVel2(left_units, right_units));
}

std::optional<int> intArgument(const Packet& packet) {
  if (packet.payload.size() < 3) return std::nullopt;
  const std::uint8_t type = packet.payload[0];
  const int magnitude = packet.payload[1] | (packet.payload[2] << 8);
  if (type == kArgPositive) return magnitude;
  if (type == kArgNegative) return -magnitude;
  return std::nullopt;
}

std::optional<std::string> stringArgument(const Packet& packet) {
  if (packet.payload.size() < 2 || packet.payload[0] != kArgString) return std::nullopt;
  const std::size_t length = packet.payload[1];
  if (packet.payload.size() < 2 + length) return std::nullopt;
  return std::string(packet.payload.begin() + 2, packet.payload.begin() + 2 + static_cast<std::ptrdiff_t>(length));
}

std::string commandName(std::uint8_t command) {
  switch (static_cast<Command>(command)) {
    case Command::kPulse: return "PULSE";
    case Command::kOpen: return "OPEN";
    case Command::kClose: return "CLOSE";
    case Command::kPolling: return "POLLING";
    case Command::kEnable: return "ENABLE";
    case Command::kSetA: return "SETA";
    case Command::kSetV: return "SETV";
    case Command::kSetO: return "SETO";
    case Command::kMove: return "MOVE";
    case Command::kRotate: return "ROTATE";
    case Command::kSetRV: return "SETRV";
    case Command::kVel: return "VEL";
    case Command::kHead: return "HEAD";
    case Command::kDHead: return "DHEAD";
    case Command::kSay: return "SAY";
    case Command::kJoyInfo: return "JOYINFO";
    case Command::kConfig: return "CONFIG";
    case Command::kEncoder: return "ENCODER";
    case Command::kSetRVDir: return "SETRVDIR";
    case Command::kRVel: return "RVEL";
    case Command::kDCHead: return "DCHEAD";
    case Command::kSetRA: return "SETRA";
    case Command::kSonar: return "SONAR";
    case Command::kStop: return "STOP";
    case Command::kDigOut: return "DIGOUT";
    case Command::kVel2: return "VEL2";
    case Command::kIoRequest: return "IOREQUEST";
    case Command::kBumpStall: return "BUMPSTALL";
    case Command::kJoyDrive: return "JOYDRIVE";
    case Command::kHostBaud: return "HOSTBAUD";
    case Command::kEStop: return "ESTOP";
    case Command::kBatteryInfo: return "BATTERYINFO";
    case Command::kRevCount: return "REVCOUNT";
    case Command::kDriftFactor: return "DRIFTFACTOR";
    case Command::kTicksMM: return "TICKSMM";
    case Command::kSimSetPose: return "SIM_SET_POSE";
    case Command::kSimReset: return "SIM_RESET";
    case Command::kSimStat: return "SIM_STAT";
    case Command::kSimExit: return "SIM_EXIT";
  }
  return "command " + std::to_string(command);
}

int hostBaudIndex(int baud) {
  for (int i = 0; i < 5; ++i) {
    if (kHostBauds[i] == baud) return i;
  }
  return -1;
}

}  // namespace aria
}  // namespace amigobot_tracking
