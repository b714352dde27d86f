// The RPLIDAR side of the emulator, from Slamtec's protocol description: GET_INFO,
// GET_HEALTH, GET_SAMPLERATE answer with a descriptor and their data; SCAN (and FORCE_SCAN)
// answer with a "multiple" descriptor and then stream each revolution's measurement nodes;
// STOP ends the stream without an answer; RESET ends it and prints the boot banner, as the
// device does. Firmware 1.29 (>= 1.24) makes Slamtec's SDK 2.x ask GET_LIDAR_CONF for the
// scan modes before any scan: two are reported, Standard (SCAN, 5-byte nodes) and Express
// (EXPRESS_SCAN, 84-byte capsules), Express the typical one. Other commands with a payload
// (size, bytes, XOR checksum) are skipped whole, as the device ignores what it does not know.
// SET_MOTOR_PWM 0 stops the motor: no node is streamed until a PWM above 0 restarts it (a
// SCAN meanwhile is acknowledged, its nodes wait for the motor), as a stopped A2 sends none.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "amigobot_tracking/sensors/laser_session.h"
#include "amigobot_tracking/sensors/rplidar.h"
#include "amigobot_tracking/sensors/rplidar_protocol.h"

namespace amigobot_tracking {
namespace sensors {
namespace {

struct ScanMode {
  const char* name;
  std::uint8_t answer_type;
};
// Both modes carry the samples the emulator casts (its sample rate): the per-mode
// microseconds per sample say so, so a driver's timing stays right.
constexpr ScanMode kModes[] = {{"Standard", rplidar::kMeasurementType}, {"Express", rplidar::kCapsuledType}};
constexpr std::uint16_t kModeCount = 2, kTypicalMode = 1;
constexpr std::uint32_t kPwmReference = 660;  // the A1's usual motor PWM

std::string littleEndian(std::uint32_t value, int bytes) {
  std::string out;
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xFF));
  return out;
}

std::uint32_t readLittleEndian(const std::string& bytes, std::size_t at, int count) {
  std::uint32_t value = 0;
  for (int i = 0; i < count && at + i < bytes.size(); ++i) value |= static_cast<std::uint32_t>(static_cast<std::uint8_t>(bytes[at + i])) << (8 * i);
  return value;
}

class RplidarSession : public LaserSession {
 public:
  RplidarSession(LaserModel model, std::string serial) : model_(std::move(model)), serial_(std::move(serial)) {}

  std::string receive(const std::string& bytes, const EmulatedScan& /*latest: no single scans*/) override {
    buffer_ += bytes;
    std::string out;
    for (;;) {
      const std::size_t sync = buffer_.find(static_cast<char>(rplidar::kSync));
      if (sync == std::string::npos) {
        buffer_.clear();
        break;
      }
      buffer_.erase(0, sync);
      if (buffer_.size() < 2) break;
      const auto command = static_cast<std::uint8_t>(buffer_[1]);
      std::string payload;
      std::size_t length = 2;
      if (command & 0x80) {  // size, payload, checksum
        if (buffer_.size() < 3) break;
        length = 3 + static_cast<std::uint8_t>(buffer_[2]) + 1;
        if (buffer_.size() < length) break;
        payload = buffer_.substr(3, length - 4);
      }
      buffer_.erase(0, length);
      requests_.push_back(std::string(1, static_cast<char>(command)) + payload);
      out += answer(command, payload);
    }
    return out;
  }

  std::string stream(const EmulatedScan& scan) override {
    if (mode_ == Mode::kIdle || !motor_on_) return "";
    return mode_ == Mode::kExpress ? capsules(scan) : nodes(scan);
  }

 private:
  enum class Mode { kIdle, kStandard, kExpress };

  static std::uint16_t distanceQ2(float r) {
    return std::isfinite(r) ? static_cast<std::uint16_t>(std::min(65535L, std::lround(r * 4000.0))) : 0;
  }

  std::string nodes(const EmulatedScan& scan) const {
    std::string out;
    out.reserve(scan.ranges.size() * rplidar::kNodeSize);
    for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
      rplidar::Node node;
      node.start = i == 0;
      node.angle_q6 = rplidar::angleQ6(scan.angles[i]);
      node.distance_q2 = distanceQ2(scan.ranges[i]);  // NaN, +-inf: no measurement, distance 0
      node.quality = node.distance_q2 > 0 ? 15 : 0;   // an A1 sends quality 15 or 0 (byte 0x3E/0x3D or 0x02/0x01)
      out += rplidar::encodeNode(node);
    }
    return out;
  }

  // The revolution's samples in capsules of 32; the rest waits for the next revolution, since
  // a capsule's samples span from its start angle to the next capsule's.
  std::string capsules(const EmulatedScan& scan) {
    for (std::size_t i = 0; i < scan.ranges.size(); ++i) pending_.push_back({scan.angles[i], scan.ranges[i]});
    std::string out;
    std::size_t used = 0;
    for (; pending_.size() - used >= rplidar::kCapsuleSamples; used += rplidar::kCapsuleSamples) {
      rplidar::Capsule c;
      c.start = first_capsule_;
      first_capsule_ = false;
      c.start_angle_q6 = rplidar::angleQ6(pending_[used].angle);
      for (std::size_t k = 0; k < rplidar::kCapsuleSamples; ++k) {
        c.distance_mm[k] = static_cast<std::uint16_t>(std::min<long>(16383, (distanceQ2(pending_[used + k].range) + 2) / 4));
      }
      out += rplidar::encodeCapsule(c);
    }
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<long>(used));
    return out;
  }

  std::string conf(std::uint32_t key, const std::string& payload) const {
    using namespace rplidar;
    const std::uint32_t mode = payload.size() >= 6 ? readLittleEndian(payload, 4, 2) : 0;
    const bool known = mode < kModeCount;
    std::string value;
    switch (key) {
      case kConfScanModeCount: value = littleEndian(kModeCount, 2); break;
      case kConfScanModeTypical: value = littleEndian(kTypicalMode, 2); break;
      case kConfScanModeUsPerSample:
        if (known) value = littleEndian(static_cast<std::uint32_t>(std::lround(256e6 / sampleRate())), 4);
        break;
      case kConfScanModeMaxDistance:
        if (known) value = littleEndian(static_cast<std::uint32_t>(std::lround(model_.range_max * 256.0)), 4);
        break;
      case kConfScanModeAnsType:
        if (known) value = std::string(1, static_cast<char>(kModes[mode].answer_type));
        break;
      case kConfScanModeName:
        if (known) value = std::string(kModes[mode].name) + '\0';
        break;
      case kConfDesiredRotFreq:
        value = littleEndian(static_cast<std::uint32_t>(std::lround(model_.rate * 60.0)), 2) + littleEndian(kPwmReference, 2);
        break;
      default: return "";  // unknown keys go unanswered: the SDK times out and falls back
    }
    if (value.empty()) return "";  // a per-mode key for a mode that does not exist
    return encodeDescriptor({static_cast<std::uint32_t>(4 + value.size()), false, kLidarConfType}) + littleEndian(key, 4) + value;
  }

  std::string answer(std::uint8_t command, const std::string& payload) {
    using namespace rplidar;
    switch (command) {
      case kGetInfo: {
        Info info;
        info.model = 0x18;  // A1M8
        info.firmware_major = 1;
        info.firmware_minor = 29;
        info.hardware = 7;
        for (std::size_t i = 0; i < info.serial.size() && i < serial_.size(); ++i) info.serial[i] = static_cast<std::uint8_t>(serial_[i]);
        return encodeDescriptor({kInfoSize, false, kInfoType}) + encodeInfo(info);
      }
      case kGetHealth: return encodeDescriptor({kHealthSize, false, kHealthType}) + encodeHealth({0, 0});
      case kGetSampleRate: {
        const auto standard = static_cast<std::uint16_t>(std::lround(1e6 / sampleRate()));
        const auto express = static_cast<std::uint16_t>(standard / 2);
        return encodeDescriptor({kSampleRateSize, false, kSampleRateType}) +
               std::string{static_cast<char>(standard & 0xFF), static_cast<char>(standard >> 8),
                           static_cast<char>(express & 0xFF), static_cast<char>(express >> 8)};
      }
      case kGetLidarConf:
        if (payload.size() < 4) return "";
        return conf(readLittleEndian(payload, 0, 4), payload);
      case kScan:
      case kForceScan:
        mode_ = Mode::kStandard;
        return encodeDescriptor({kNodeSize, true, kMeasurementType});
      case kExpressScan: {
        // working_mode 0 (the legacy express scan) or a mode id from GET_LIDAR_CONF.
        const std::uint8_t working_mode = payload.empty() ? 0 : static_cast<std::uint8_t>(payload[0]);
        if (working_mode >= kModeCount) return "";
        mode_ = Mode::kExpress;
        first_capsule_ = true;
        pending_.clear();
        return encodeDescriptor({kCapsuleSize, true, kCapsuledType});
      }
      case kSetMotorPwm:
        if (payload.size() >= 2) motor_on_ = readLittleEndian(payload, 0, 2) > 0;
        return "";
      case kStop: mode_ = Mode::kIdle; return "";
      case kReset:
        mode_ = Mode::kIdle;
        motor_on_ = true;
        return "RP LIDAR System.\r\nFirmware Ver 1.29 - rc4, HW Ver 7\r\nModel: 24\r\n";
      default: return "";  // the device ignores what it does not know
    }
  }

  struct PendingSample {
    float angle, range;
  };
  // [1/s] the model's, as the RPLIDAR's own numbers say (GET_SAMPLERATE, GET_LIDAR_CONF).
  double sampleRate() const { return model_.protocolGeometry<RplidarGeometry>().sample_rate; }

  LaserModel model_;
  std::string serial_, buffer_;
  Mode mode_ = Mode::kIdle;
  bool motor_on_ = true;  // spinning from power-up
  bool first_capsule_ = false;
  std::vector<PendingSample> pending_;
};

}  // namespace

std::unique_ptr<LaserSession> makeRplidarSession(const LaserModel& model, const std::string& serial) {
  return std::make_unique<RplidarSession>(model, serial);
}

}  // namespace sensors
}  // namespace amigobot_tracking
