// SICK CoLa-A ("Command Language A", ASCII), as TiM5xx and LMS1xx speak it over TCP port
// 2111: every telegram is STX (0x02), space-separated fields, ETX (0x03). Numbers are
// upper-case hexadecimal without leading zeros, signed ones in two's complement of 32 bits.
// The scan telegram (answer "sRA LMDscandata" to a poll, "sSN LMDscandata" while streamed)
// is laid out as in SICK's telegram listing; both ends of it live here: the emulator encodes
// it, the driver decodes it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace amigobot_tracking {
namespace sensors {
namespace cola {

constexpr char kStx = 0x02;
constexpr char kEtx = 0x03;

std::string hex(std::uint32_t value);    // 1388 for 5000
std::string hexSigned(std::int32_t value);  // FFF92230 for -450000
// Throws std::invalid_argument naming the field on an empty or non-hex field.
std::uint32_t parseHex(const std::string& field, const char* what);

std::string frame(const std::string& body);  // STX body ETX
// Takes the first complete telegram out of *buffer (bytes before its STX are dropped) and
// returns its body; false when none is complete yet.
bool nextTelegram(std::string* buffer, std::string* body);

struct ScanTelegram {
  std::string command = "sRA";       // sRA (polled) or sSN (streamed)
  std::uint32_t serial = 0;
  std::uint32_t telegram_counter = 0, scan_counter = 0;
  std::uint32_t time_since_start_us = 0, time_of_transmission_us = 0;
  std::uint32_t scan_frequency = 0;       // [1/100 Hz]
  std::uint32_t measurement_frequency = 0;  // [100 Hz] beams per second / 100
  // Encoder block (LMDscandatacfg with encoder output): one position [ticks] and speed each.
  std::vector<std::uint32_t> encoder_positions;
  std::vector<std::uint32_t> encoder_speeds;
  // The DIST1 channel, found among the 16-bit and 8-bit channels in any order.
  float scale_factor = 1.0f;              // range [mm] = value * scale_factor + scale_offset
  float scale_offset = 0.0f;              // [mm]
  std::int32_t start_angle = 0;           // [1/10000 deg] in SICK's frame: 0 deg is +y of the device
  std::uint32_t angular_step = 0;         // [1/10000 deg]
  std::vector<std::uint32_t> ranges;      // raw DIST1 values; 0 = no echo
  // RSSI1 (remission) when the device sends it: raw values, one per range; empty when not.
  std::vector<std::uint32_t> rssi;
  bool rssi_8bit = false;                 // encode: RSSI1 among the 8-bit channels (else 16-bit)
};

std::string encodeScan(const ScanTelegram& scan);
// Empty when `body` is a complete scan telegram with a usable geometry (then *scan holds
// it), else what is wrong. Reads the header, the encoder block, the 16-bit and the 8-bit
// channels as the telegram listing lays them out: DIST1 anywhere among them (RSSI1 kept,
// DIST2.., RSSI2.. skipped).
std::string decodeScan(const std::string& body, ScanTelegram* scan);
// Empty when the decoded geometry can be used, else "scan telegram: <field>: ..." (a NaN, zero
// or negative scale factor, a step of 0 or over 360 deg, a span over 360 deg): such a scan
// is an error, never an empty "fresh" scan that hides a blind laser (issue 25).
std::string validateScanGeometry(const ScanTelegram& scan);

}  // namespace cola
}  // namespace sensors
}  // namespace amigobot_tracking
