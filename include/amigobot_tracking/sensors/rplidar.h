// Slamtec RPLIDAR A1/A2 serial protocol ("RPLIDAR Interface Protocol and Application Notes"),
// both ends: a request is 0xA5 and a command byte (commands >= 0x80 add a size, a payload and
// an XOR checksum); a reply starts with the 7-byte descriptor 0xA5 0x5A, a 30-bit length and
// 2-bit send mode (little-endian), and a data type. SCAN streams 5-byte measurement nodes:
//   byte 0: quality (6 bits) << 2 | !S << 1 | S   (S: first node of a new revolution)
//   byte 1: angle_q6 bits 0..6 << 1 | C           (C: check bit, always 1)
//   byte 2: angle_q6 bits 7..14                   (angle = angle_q6 / 64 deg, clockwise)
//   byte 3-4: distance_q2, little-endian          (distance = distance_q2 / 4 mm, 0: none)
// Pure functions, no I/O.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace amigobot_tracking {
namespace sensors {
namespace rplidar {

constexpr std::uint8_t kSync = 0xA5, kSync2 = 0x5A;
enum Command : std::uint8_t {
  kStop = 0x25, kReset = 0x40, kScan = 0x20, kForceScan = 0x21,
  kGetInfo = 0x50, kGetHealth = 0x52, kGetSampleRate = 0x59,
};
enum DataType : std::uint8_t { kInfoType = 0x04, kHealthType = 0x06, kMeasurementType = 0x81, kSampleRateType = 0x15 };
constexpr std::size_t kDescriptorSize = 7, kNodeSize = 5, kInfoSize = 20, kHealthSize = 3, kSampleRateSize = 4;

std::string request(Command command);  // 0xA5 command

struct Descriptor {
  std::uint32_t length = 0;  // bytes per reply (per node while streaming)
  bool multiple = false;     // send mode: one reply or a stream of them
  std::uint8_t type = 0;
};
std::string encodeDescriptor(const Descriptor& d);
// Empty when `bytes` (7) is a descriptor (then *d holds it), else what is wrong.
std::string decodeDescriptor(const std::string& bytes, Descriptor* d);

struct Node {
  bool start = false;         // first node of a revolution
  int quality = 0;            // 0..63
  std::uint16_t angle_q6 = 0;     // [1/64 deg] clockwise from the device's front, < 360 * 64
  std::uint16_t distance_q2 = 0;  // [1/4 mm]; 0: no measurement
};
std::string encodeNode(const Node& node);
// Empty when the 5 bytes at `bytes` are a consistent node (S != !S, C = 1, angle < 360 deg),
// else what is wrong: the reader then drops one byte and looks again (resynchronises).
std::string decodeNode(const std::uint8_t* bytes, Node* node);

struct Info {
  std::uint8_t model = 0, firmware_minor = 0, firmware_major = 0, hardware = 0;
  std::array<std::uint8_t, 16> serial{};
};
std::string encodeInfo(const Info& info);
Info decodeInfo(const std::string& bytes);  // 20 bytes

struct Health {
  std::uint8_t status = 0;  // 0 good, 1 warning, 2 error
  std::uint16_t error_code = 0;
};
std::string encodeHealth(const Health& health);
Health decodeHealth(const std::string& bytes);  // 3 bytes

// The angle of a node in the sensor frame (REP 103: counter-clockwise), within [-pi, pi).
double nodeAngle(std::uint16_t angle_q6);
// The angle_q6 of a sensor-frame angle (the inverse of nodeAngle, rounded).
std::uint16_t angleQ6(double angle);

// One revolution's samples on a fixed grid of `bins` over [-pi, pi) (bin i at -pi + i 2 pi /
// bins): each bin takes the range of the sample nearest to its centre within half a bin,
// +inf where none fell (REP 117). Ranges are [m], +inf for a node without measurement.
struct Sample {
  double angle = 0.0;  // [rad] sensor frame
  float range = 0.0f;  // [m]
};
std::vector<float> binRevolution(const std::vector<Sample>& samples, int bins);

}  // namespace rplidar
}  // namespace sensors
}  // namespace amigobot_tracking
