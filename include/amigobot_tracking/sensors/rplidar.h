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
  kExpressScan = 0x82, kGetLidarConf = 0x84,  // firmware >= 1.17, >= 1.24
  kSetMotorPwm = 0xF0,  // payload: u16 PWM duty, 0 stops the motor (A2/A3; the A1's USB adapter: DTR)
};
constexpr std::uint16_t kDefaultMotorPwm = 660;  // Slamtec's SDK's default duty
enum DataType : std::uint8_t {
  kInfoType = 0x04, kHealthType = 0x06, kMeasurementType = 0x81, kCapsuledType = 0x82, kSampleRateType = 0x15,
  kLidarConfType = 0x20,
};
constexpr std::size_t kDescriptorSize = 7, kNodeSize = 5, kInfoSize = 20, kHealthSize = 3, kSampleRateSize = 4;
constexpr std::size_t kCapsuleSize = 84, kCapsuleSamples = 32;

// GET_LIDAR_CONF keys (request payload: the u32 key, little-endian, then for the per-mode
// keys the u16 mode id; answer: the u32 key then the value).
enum ConfKey : std::uint32_t {
  kConfDesiredRotFreq = 0x01,       // u16 rpm, u16 PWM reference (the SDK's startMotor asks it)
  kConfScanModeCount = 0x70,        // u16
  kConfScanModeUsPerSample = 0x71,  // u32, microseconds * 256
  kConfScanModeMaxDistance = 0x74,  // u32, metres * 256
  kConfScanModeAnsType = 0x75,      // u8: the data type the mode streams (0x81, 0x82, ...)
  kConfScanModeTypical = 0x7C,      // u16: the mode id a driver should use
  kConfScanModeName = 0x7F,         // NUL-terminated string
};

std::string request(Command command);  // 0xA5 command
// 0xA5 command size payload checksum (XOR of every byte before it), for commands >= 0x80.
std::string request(Command command, const std::string& payload);

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

// EXPRESS_SCAN's "capsuled" answer: 84 bytes, sync nibbles 0xA and 0x5 carrying the XOR of
// bytes 2..83, the u16 start angle [1/64 deg] with bit 15 set on the first capsule after the
// request, then 16 cabins of two u16 distances (mm << 2; the low 2 bits and a nibble of the
// fifth byte: an angle correction in 1/8 deg, sent as 0). The 32 samples of a capsule lie
// evenly from its start angle to the next capsule's, as Slamtec's SDK interpolates them.
struct Capsule {
  bool start = false;
  std::uint16_t start_angle_q6 = 0;
  std::array<std::uint16_t, kCapsuleSamples> distance_mm{};  // 0: none, < 16384
};
std::string encodeCapsule(const Capsule& capsule);
// Empty when the 84 bytes at `bytes` are a capsule with a good checksum, else what is wrong.
std::string decodeCapsule(const std::uint8_t* bytes, Capsule* capsule);

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
