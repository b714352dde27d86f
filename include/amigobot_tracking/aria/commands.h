// Client command numbers (ArCommands.h) and builders for complete command packets, plus
// the robot-side decoding of their arguments (used by the emulator).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "amigobot_tracking/aria/packet.h"

namespace amigobot_tracking {
namespace aria {

enum class Command : std::uint8_t {
  kPulse = 0,
  kOpen = 1,
  kClose = 2,
  kPolling = 3,
  kEnable = 4,
  kSetA = 5,
  kSetV = 6,
  kSetO = 7,
  kMove = 8,
  kRotate = 9,
  kSetRV = 10,
  kVel = 11,
  kHead = 12,
  kDHead = 13,
  kSay = 15,
  kJoyInfo = 17,
  kConfig = 18,
  kEncoder = 19,
  kSetRVDir = 20,
  kRVel = 21,
  kDCHead = 22,
  kSetRA = 23,
  kSonar = 28,
  kStop = 29,
  kDigOut = 30,
  kVel2 = 32,
  kIoRequest = 40,
  kBumpStall = 44,
  kJoyDrive = 47,
  kHostBaud = 50,
  kEStop = 55,
  kBatteryInfo = 62,
  kRevCount = 88,
  kDriftFactor = 89,
  kTicksMM = 93,
  kSimSetPose = 224,
  kSimReset = 225,
  kSimStat = 237,
  kSimExit = 239,
};

// The line speeds HOSTBAUD selects, by its argument 0..4.
constexpr int kHostBauds[] = {9600, 19200, 38400, 57600, 115200};
// HOSTBAUD argument for a baud, or -1 when the firmware has no such rate.
int hostBaudIndex(int baud);
// The order ARIA sends CLOSE in to free a robot left open at an unknown baud.
constexpr int kRecoveryBauds[] = {9600, 38400, 115200, 19200, 57600};

// Robot-to-client packet types.
constexpr std::uint8_t kSync0 = 0;
constexpr std::uint8_t kSync1 = 1;
constexpr std::uint8_t kSync2 = 2;
constexpr std::uint8_t kSipStopped = 0x32;
constexpr std::uint8_t kSipMoving = 0x33;
constexpr std::uint8_t kConfigPacType = 0x20;
constexpr std::uint8_t kEncoderPacType = 0x90;  // answer to ENCODER: int32 left, int32 right ticks

inline bool isSipType(std::uint8_t type) { return type == kSipStopped || type == kSipMoving; }

// A command with no argument: FA FB 03 cmd cs cs.
std::vector<std::uint8_t> commandPacket(Command command);
// A command with one typed int (0x3B / 0x1B). |value| <= 65535, else std::invalid_argument.
std::vector<std::uint8_t> commandPacket(Command command, int value);
// A command with a typed string (0x2B, length, characters, ARIA's uncounted NUL).
std::vector<std::uint8_t> commandPacket(Command command, const std::string& text);
// SYNC0/1/2 (bare command bytes 0, 1, 2).
std::vector<std::uint8_t> syncPacket(int n);

// VEL2 argument: left wheel in the high byte, right in the low byte, each a signed byte
// of Vel2Divisor mm/s. Each is clamped to -128..127 (ARIA's +128 wrapped to -128) and the
// two bytes form one signed 16-bit value sent as a typed int.
int packVel2(int left_units, int right_units);
// Robot side: the signed 16-bit value back into wheel units.
void unpackVel2(int value, int& left_units, int& right_units);
std::vector<std::uint8_t> vel2Packet(int left_units, int right_units);

// Robot side: the int argument of a command (sign from the type byte); nullopt when the
// packet carries no (well-formed) int argument.
std::optional<int> intArgument(const Packet& packet);
std::optional<std::string> stringArgument(const Packet& packet);

std::string commandName(std::uint8_t command);

}  // namespace aria
}  // namespace amigobot_tracking
