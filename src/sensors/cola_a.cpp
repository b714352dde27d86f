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

// Header fields up to the measurement frequency (index 17); the encoder count follows.
constexpr std::size_t kEncoderCountIndex = 18;

std::uint32_t floatBits(float value) {
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  return bits;
}

float bitsFloat(std::uint32_t bits) {
  float value;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

// Appends one channel: name, scale factor, offset, start angle, step, count, values.
void appendChannel(std::ostringstream& out, const char* name, float scale, float offset, std::int32_t start,
                   std::uint32_t step, const std::vector<std::uint32_t>& values) {
  out << ' ' << name << ' ' << hex(floatBits(scale)) << ' ' << hex(floatBits(offset)) << ' ' << hexSigned(start) << ' '
      << hex(step) << ' ' << hex(static_cast<std::uint32_t>(values.size()));
  for (std::uint32_t v : values) out << ' ' << hex(v);
}

// Reads fields one at a time; throws std::invalid_argument naming what ran out.
class FieldReader {
 public:
  FieldReader(const std::vector<std::string>& fields, std::size_t at) : f_(fields), at_(at) {}
  const std::string& text(const char* what) {
    if (at_ >= f_.size()) {
      throw std::invalid_argument("scan telegram: ends at field " + std::to_string(at_) + ", expected " + what);
    }
    return f_[at_++];
  }
  std::uint32_t number(const char* what) { return parseHex(text(what), what); }
  void skip(std::size_t count, const char* what) {
    require(count, what);
    at_ += count;
  }
  void require(std::size_t count, const char* what) const {
    if (at_ + count > f_.size()) {
      throw std::invalid_argument(std::string("scan telegram: ") + std::to_string(count) + " " + what + " announced, " +
                                  std::to_string(f_.size() - at_) + " fields follow");
    }
  }
  std::size_t at() const { return at_; }

 private:
  const std::vector<std::string>& f_;
  std::size_t at_;
};

// One channel block ("number of channels", then each channel) into *s; DIST1 and RSSI1 kept.
void readChannels(FieldReader& in, const char* block, ScanTelegram* s, bool* dist) {
  const std::uint32_t channels = in.number(block);
  for (std::uint32_t c = 0; c < channels; ++c) {
    const std::string name = in.text("channel name");
    const float scale = bitsFloat(in.number("scale factor"));
    const float offset = bitsFloat(in.number("scale factor offset"));
    const auto start = static_cast<std::int32_t>(in.number("starting angle"));
    const std::uint32_t step = in.number("angular step");
    const std::uint32_t count = in.number("number of data");
    std::vector<std::uint32_t>* values = nullptr;
    if (name == "DIST1" && !*dist) {
      *dist = true;
      s->scale_factor = scale;
      s->scale_offset = offset;
      s->start_angle = start;
      s->angular_step = step;
      values = &s->ranges;
    } else if (name == "RSSI1" && s->rssi.empty()) {
      values = &s->rssi;
    }
    if (values == nullptr) {
      in.skip(count, (name + " values").c_str());
      continue;
    }
    in.require(count, name == "DIST1" ? "ranges" : "RSSI1 values");
    values->clear();
    values->reserve(count);
    for (std::uint32_t i = 0; i < count; ++i) values->push_back(in.number(name == "DIST1" ? "range" : "RSSI1 value"));
  }
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
      << " 0 0 0 0 0 " << hex(s.scan_frequency) << ' ' << hex(s.measurement_frequency) << ' '
      << hex(static_cast<std::uint32_t>(s.encoder_positions.size()));
  for (std::size_t i = 0; i < s.encoder_positions.size(); ++i) {
    out << ' ' << hex(s.encoder_positions[i]) << ' ' << hex(i < s.encoder_speeds.size() ? s.encoder_speeds[i] : 0u);
  }
  const bool rssi16 = !s.rssi.empty() && !s.rssi_8bit, rssi8 = !s.rssi.empty() && s.rssi_8bit;
  out << ' ' << (rssi16 ? 2 : 1);
  appendChannel(out, "DIST1", s.scale_factor, s.scale_offset, s.start_angle, s.angular_step, s.ranges);
  if (rssi16) appendChannel(out, "RSSI1", 1.0f, 0.0f, s.start_angle, s.angular_step, s.rssi);
  out << ' ' << (rssi8 ? 1 : 0);
  if (rssi8) appendChannel(out, "RSSI1", 1.0f, 0.0f, s.start_angle, s.angular_step, s.rssi);
  out << " 0 0 0 0 0";  // position, name, comment, time, event
  return out.str();
}

std::string decodeScan(const std::string& body, ScanTelegram* scan) {
  std::istringstream in(body);
  std::vector<std::string> f;
  for (std::string field; in >> field;) f.push_back(field);
  if (f.size() < kEncoderCountIndex + 2) return "scan telegram: only " + std::to_string(f.size()) + " fields";
  if ((f[0] != "sRA" && f[0] != "sSN") || f[1] != "LMDscandata") return "not a scan telegram: " + f[0] + " " + f[1];
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
    FieldReader fields(f, kEncoderCountIndex);
    const std::uint32_t encoders = fields.number("number of encoders");
    fields.require(2 * static_cast<std::size_t>(encoders), "encoder fields");
    for (std::uint32_t i = 0; i < encoders; ++i) {
      s.encoder_positions.push_back(fields.number("encoder position"));
      s.encoder_speeds.push_back(fields.number("encoder speed"));
    }
    bool dist = false;
    readChannels(fields, "number of 16-bit channels", &s, &dist);
    readChannels(fields, "number of 8-bit channels", &s, &dist);
    if (!dist) return "scan telegram: no DIST1 channel";
    if (!s.rssi.empty() && s.rssi.size() != s.ranges.size()) {
      return "scan telegram: " + std::to_string(s.rssi.size()) + " RSSI1 values for " + std::to_string(s.ranges.size()) +
             " ranges";
    }
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
