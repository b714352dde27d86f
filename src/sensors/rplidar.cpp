#include "amigobot_tracking/sensors/rplidar.h"

#include <cmath>
#include <limits>

namespace amigobot_tracking {
namespace sensors {
namespace rplidar {
namespace {

constexpr int kFullTurnQ6 = 360 * 64;

std::uint8_t byte(const std::string& s, std::size_t i) { return static_cast<std::uint8_t>(s[i]); }

}  // namespace

std::string request(Command command) { return {static_cast<char>(kSync), static_cast<char>(command)}; }

std::string request(Command command, const std::string& payload) {
  std::string out{static_cast<char>(kSync), static_cast<char>(command), static_cast<char>(payload.size())};
  out += payload;
  std::uint8_t sum = 0;
  for (char c : out) sum ^= static_cast<std::uint8_t>(c);
  out.push_back(static_cast<char>(sum));
  return out;
}

std::string encodeDescriptor(const Descriptor& d) {
  const std::uint32_t word = (d.length & 0x3FFFFFFFu) | (d.multiple ? 0x40000000u : 0u);
  std::string out{static_cast<char>(kSync), static_cast<char>(kSync2)};
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((word >> (8 * i)) & 0xFF));
  out.push_back(static_cast<char>(d.type));
  return out;
}

std::string decodeDescriptor(const std::string& bytes, Descriptor* d) {
  if (bytes.size() != kDescriptorSize) return "descriptor of " + std::to_string(bytes.size()) + " bytes";
  if (byte(bytes, 0) != kSync || byte(bytes, 1) != kSync2) return "descriptor without its A5 5A start";
  std::uint32_t word = 0;
  for (int i = 0; i < 4; ++i) word |= static_cast<std::uint32_t>(byte(bytes, 2 + i)) << (8 * i);
  d->length = word & 0x3FFFFFFFu;
  d->multiple = (word >> 30) == 1;
  d->type = byte(bytes, 6);
  return "";
}

std::string encodeNode(const Node& n) {
  std::string out(kNodeSize, '\0');
  out[0] = static_cast<char>(((n.quality & 0x3F) << 2) | (n.start ? 0x01 : 0x02));
  out[1] = static_cast<char>(((n.angle_q6 & 0x7F) << 1) | 0x01);
  out[2] = static_cast<char>((n.angle_q6 >> 7) & 0xFF);
  out[3] = static_cast<char>(n.distance_q2 & 0xFF);
  out[4] = static_cast<char>(n.distance_q2 >> 8);
  return out;
}

std::string decodeNode(const std::uint8_t* b, Node* n) {
  const bool s = b[0] & 0x01, not_s = b[0] & 0x02;
  if (s == not_s) return "measurement node: start flag and its inverse agree";
  if (!(b[1] & 0x01)) return "measurement node: check bit is 0";
  const int angle = (b[1] >> 1) | (b[2] << 7);
  if (angle >= kFullTurnQ6) return "measurement node: angle " + std::to_string(angle / 64.0) + " deg";
  n->start = s;
  n->quality = b[0] >> 2;
  n->angle_q6 = static_cast<std::uint16_t>(angle);
  n->distance_q2 = static_cast<std::uint16_t>(b[3] | (b[4] << 8));
  return "";
}

std::string encodeCapsule(const Capsule& c) {
  std::string out(kCapsuleSize, '\0');
  const std::uint16_t angle = static_cast<std::uint16_t>((c.start_angle_q6 & 0x7FFF) | (c.start ? 0x8000 : 0));
  out[2] = static_cast<char>(angle & 0xFF);
  out[3] = static_cast<char>(angle >> 8);
  for (std::size_t i = 0; i < kCapsuleSamples; ++i) {
    const std::uint16_t d = static_cast<std::uint16_t>((c.distance_mm[i] & 0x3FFF) << 2);
    const std::size_t at = 4 + 5 * (i / 2) + 2 * (i % 2);  // cabin: distance 1, distance 2, offsets
    out[at] = static_cast<char>(d & 0xFF);
    out[at + 1] = static_cast<char>(d >> 8);
  }
  std::uint8_t sum = 0;
  for (std::size_t i = 2; i < kCapsuleSize; ++i) sum ^= static_cast<std::uint8_t>(out[i]);
  out[0] = static_cast<char>(0xA0 | (sum & 0x0F));
  out[1] = static_cast<char>(0x50 | (sum >> 4));
  return out;
}

std::string decodeCapsule(const std::uint8_t* b, Capsule* c) {
  if ((b[0] >> 4) != 0xA || (b[1] >> 4) != 0x5) return "capsule: sync nibbles are not A and 5";
  std::uint8_t sum = 0;
  for (std::size_t i = 2; i < kCapsuleSize; ++i) sum ^= b[i];
  if (sum != static_cast<std::uint8_t>((b[0] & 0x0F) | (b[1] << 4))) return "capsule: checksum mismatch";
  const std::uint16_t angle = static_cast<std::uint16_t>(b[2] | (b[3] << 8));
  c->start = angle & 0x8000;
  c->start_angle_q6 = angle & 0x7FFF;
  for (std::size_t i = 0; i < kCapsuleSamples; ++i) {
    const std::size_t at = 4 + 5 * (i / 2) + 2 * (i % 2);
    c->distance_mm[i] = static_cast<std::uint16_t>((b[at] | (b[at + 1] << 8)) >> 2);
  }
  return "";
}

std::string encodeInfo(const Info& info) {
  std::string out{static_cast<char>(info.model), static_cast<char>(info.firmware_minor),
                  static_cast<char>(info.firmware_major), static_cast<char>(info.hardware)};
  for (std::uint8_t c : info.serial) out.push_back(static_cast<char>(c));
  return out;
}

Info decodeInfo(const std::string& bytes) {
  Info info;
  if (bytes.size() < kInfoSize) return info;
  info.model = byte(bytes, 0);
  info.firmware_minor = byte(bytes, 1);
  info.firmware_major = byte(bytes, 2);
  info.hardware = byte(bytes, 3);
  for (std::size_t i = 0; i < info.serial.size(); ++i) info.serial[i] = byte(bytes, 4 + i);
  return info;
}

std::string encodeHealth(const Health& h) {
  return {static_cast<char>(h.status), static_cast<char>(h.error_code & 0xFF), static_cast<char>(h.error_code >> 8)};
}

Health decodeHealth(const std::string& bytes) {
  Health h;
  if (bytes.size() < kHealthSize) return h;
  h.status = byte(bytes, 0);
  h.error_code = static_cast<std::uint16_t>(byte(bytes, 1) | (byte(bytes, 2) << 8));
  return h;
}

double nodeAngle(std::uint16_t angle_q6) {
  // Clockwise degrees from the front -> counter-clockwise radians, wrapped into [-pi, pi).
  double a = -angle_q6 / 64.0 * M_PI / 180.0;
  if (a < -M_PI) a += 2.0 * M_PI;
  return a;
}

std::uint16_t angleQ6(double angle) {
  long q = std::lround(-angle * 180.0 / M_PI * 64.0) % kFullTurnQ6;
  if (q < 0) q += kFullTurnQ6;
  return static_cast<std::uint16_t>(q);
}

std::vector<float> binRevolution(const std::vector<Sample>& samples, int bins) {
  std::vector<float> ranges(static_cast<std::size_t>(bins), std::numeric_limits<float>::infinity());
  std::vector<double> offset(static_cast<std::size_t>(bins), std::numeric_limits<double>::infinity());
  const double width = 2.0 * M_PI / bins;
  for (const Sample& s : samples) {
    const double position = (s.angle + M_PI) / width;  // bin centres at whole numbers
    long bin = std::lround(position);
    const double off = std::abs(position - static_cast<double>(bin));
    bin %= bins;
    if (bin < 0) bin += bins;
    const auto i = static_cast<std::size_t>(bin);
    if (off < offset[i]) {
      offset[i] = off;
      ranges[i] = s.range;
    }
  }
  return ranges;
}

}  // namespace rplidar
}  // namespace sensors
}  // namespace amigobot_tracking
