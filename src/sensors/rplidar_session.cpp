// The RPLIDAR side of the emulator, from Slamtec's protocol description: GET_INFO,
// GET_HEALTH, GET_SAMPLERATE answer with a descriptor and their data; SCAN (and FORCE_SCAN)
// answer with a "multiple" descriptor and then stream each revolution's measurement nodes;
// STOP ends the stream without an answer; RESET ends it and prints the boot banner, as the
// device does. Commands >= 0x80 carry a payload (size, bytes, XOR checksum): skipped.
#include <cmath>
#include <memory>

#include "amigobot_tracking/sensors/laser_session.h"
#include "amigobot_tracking/sensors/rplidar.h"

namespace amigobot_tracking {
namespace sensors {
namespace {

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
      std::size_t length = 2;
      if (command & 0x80) {  // size, payload, checksum
        if (buffer_.size() < 3) break;
        length = 3 + static_cast<std::uint8_t>(buffer_[2]) + 1;
        if (buffer_.size() < length) break;
      }
      buffer_.erase(0, length);
      requests_.push_back(std::string(1, static_cast<char>(command)));
      out += answer(command);
    }
    return out;
  }

  std::string stream(const EmulatedScan& scan) override {
    if (!scanning_) return "";
    std::string out;
    out.reserve(scan.ranges.size() * rplidar::kNodeSize);
    for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
      rplidar::Node node;
      node.start = i == 0;
      node.angle_q6 = rplidar::angleQ6(scan.angles[i]);
      const float r = scan.ranges[i];
      if (std::isfinite(r)) {  // NaN, +-inf: no measurement, distance 0, quality 0
        node.distance_q2 = static_cast<std::uint16_t>(std::min(65535L, std::lround(r * 4000.0)));
        node.quality = 47;
      }
      out += rplidar::encodeNode(node);
    }
    return out;
  }

 private:
  std::string answer(std::uint8_t command) {
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
        const auto standard = static_cast<std::uint16_t>(std::lround(1e6 / model_.rplidar.sample_rate));
        const auto express = static_cast<std::uint16_t>(standard / 2);
        return encodeDescriptor({kSampleRateSize, false, kSampleRateType}) +
               std::string{static_cast<char>(standard & 0xFF), static_cast<char>(standard >> 8),
                           static_cast<char>(express & 0xFF), static_cast<char>(express >> 8)};
      }
      case kScan:
      case kForceScan:
        scanning_ = true;
        return encodeDescriptor({kNodeSize, true, kMeasurementType});
      case kStop: scanning_ = false; return "";
      case kReset: scanning_ = false; return "RP LIDAR System.\r\nFirmware Ver 1.29 - rc4, HW Ver 7\r\nModel: 24\r\n";
      default: return "";  // the device ignores what it does not know
    }
  }

  LaserModel model_;
  std::string serial_, buffer_;
  bool scanning_ = false;
};

}  // namespace

std::unique_ptr<LaserSession> makeRplidarSession(const LaserModel& model, const std::string& serial) {
  return std::make_unique<RplidarSession>(model, serial);
}

}  // namespace sensors
}  // namespace amigobot_tracking
