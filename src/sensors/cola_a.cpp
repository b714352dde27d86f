#include "amigobot_tracking/sensors/cola_a.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace amigobot_tracking {
namespace sensors {
namespace cola {
namespace {

// Fields between the serial number and DIST1 that the emulator fills with zeros: device
// status (2), telegram and scan counters, two times, inputs (2), outputs (2), reserved,
// frequencies, encoders, 16-bit channel count.
constexpr std::size_t kDistIndex = 20;   // "DIST1"
constexpr std::size_t kCountIndex = 25;  // number of data

std::uint32_t floatBits(float value) {
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  return bits;
}

}  // namespace

std::string hex(std::uint32_t value) {
  std::ostringstream out;
  out << std::uppercase << std::hex << value;
  return out.str();
}

std::string hexSigned(std::int32_t value) { return hex(static_cast<std::uint32_t>(value)); }

std::uint32_t parseHex(const std::string& field, const char* what) {
  if (field.empty() || field.size() > 8 || field.find_first_not_of("0123456789ABCDEFabcdef") != std::string::npos) {
    throw std::invalid_argument(std::string("CoLa-A: ") + what + ": not a hex number: '" + field + "'");
  }
  return static_cast<std::uint32_t>(std::stoul(field, nullptr, 16));
}

std::string frame(const std::string& body) { return std::string(1, kStx) + body + kEtx; }

bool nextTelegram(std::string* buffer, std::string* body) {
  const std::size_t start = buffer->find(kStx);
  if (start == std::string::npos) {
    buffer->clear();
    return false;
  }
  const std::size_t end = buffer->find(kEtx, start + 1);
  if (end == std::string::npos) {
    buffer->erase(0, start);
    return false;
  }
  *body = buffer->substr(start + 1, end - start - 1);
  buffer->erase(0, end + 1);
  // A second STX inside means the first telegram was cut: keep only the last one.
  const std::size_t restart = body->rfind(kStx);
  if (restart != std::string::npos) body->erase(0, restart + 1);
  return true;
}

std::string encodeScan(const ScanTelegram& s) {
  std::ostringstream out;
  out << s.command << " LMDscandata 1 1 " << hex(s.serial) << " 0 0 " << hex(s.telegram_counter) << ' '
      << hex(s.scan_counter) << ' ' << hex(s.time_since_start_us) << ' ' << hex(s.time_of_transmission_us)
      << " 0 0 0 0 0 " << hex(s.scan_frequency) << ' ' << hex(s.measurement_frequency) << " 0 1 DIST1 "
      << hex(floatBits(s.scale_factor)) << " 0 " << hexSigned(s.start_angle) << ' ' << hex(s.angular_step) << ' '
      << hex(static_cast<std::uint32_t>(s.ranges.size()));
  for (std::uint32_t range : s.ranges) out << ' ' << hex(range);
  out << " 0 0 0 0 0 0";  // no 8-bit channels, position, name, comment, time, event
  return out.str();
}

std::string decodeScan(const std::string& body, ScanTelegram* scan) {
  std::istringstream in(body);
  std::vector<std::string> f;
  for (std::string field; in >> field;) f.push_back(field);
  if (f.size() < kCountIndex + 1) return "scan telegram: only " + std::to_string(f.size()) + " fields";
  if ((f[0] != "sRA" && f[0] != "sSN") || f[1] != "LMDscandata") return "not a scan telegram: " + f[0] + " " + f[1];
  if (f[kDistIndex] != "DIST1") return "scan telegram: first channel is '" + f[kDistIndex] + "', expected DIST1";
  ScanTelegram s;
  try {
    s.command = f[0];
    s.serial = parseHex(f[4], "serial number");
    s.telegram_counter = parseHex(f[7], "telegram counter");
    s.scan_counter = parseHex(f[8], "scan counter");
    s.time_since_start_us = parseHex(f[9], "time since start");
    s.time_of_transmission_us = parseHex(f[10], "time of transmission");
    s.scan_frequency = parseHex(f[16], "scan frequency");
    s.measurement_frequency = parseHex(f[17], "measurement frequency");
    const std::uint32_t bits = parseHex(f[21], "scale factor");
    std::memcpy(&s.scale_factor, &bits, sizeof(bits));
    s.start_angle = static_cast<std::int32_t>(parseHex(f[23], "starting angle"));
    s.angular_step = parseHex(f[24], "angular step");
    const std::uint32_t count = parseHex(f[kCountIndex], "number of data");
    if (f.size() < kCountIndex + 1 + count) {
      return "scan telegram: " + std::to_string(count) + " ranges announced, " +
             std::to_string(f.size() - kCountIndex - 1) + " fields follow";
    }
    s.ranges.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i) s.ranges.push_back(parseHex(f[kCountIndex + 1 + i], "range"));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  const std::string geometry = validateScanGeometry(s);
  if (!geometry.empty()) return geometry;
  *scan = std::move(s);
  return "";
}

std::string validateScanGeometry(const ScanTelegram& s) {
  constexpr std::int64_t kFullTurn = 3600000;  // 360 deg in 1/10000 deg
  if (!(std::isfinite(s.scale_factor) && s.scale_factor > 0.0f)) {
    return "scan telegram: scale factor: must be a finite number > 0, got " + std::to_string(s.scale_factor);
  }
  if (s.angular_step == 0 || s.angular_step > kFullTurn) {
    return "scan telegram: angular step: must be in (0, 360] deg, got " + std::to_string(s.angular_step / 1e4) +
           " deg";
  }
  if (std::llabs(static_cast<long long>(s.start_angle)) > kFullTurn) {
    return "scan telegram: starting angle: must be within +-360 deg, got " + std::to_string(s.start_angle / 1e4) +
           " deg";
  }
  const std::int64_t span = static_cast<std::int64_t>(s.angular_step) * static_cast<std::int64_t>(s.ranges.size());
  if (span > kFullTurn + static_cast<std::int64_t>(s.angular_step)) {  // n beams span (n - 1) steps
    return "scan telegram: angular step: " + std::to_string(s.ranges.size()) + " beams of " +
           std::to_string(s.angular_step / 1e4) + " deg span more than 360 deg";
  }
  return "";
}

}  // namespace cola
}  // namespace sensors
}  // namespace amigobot_tracking
