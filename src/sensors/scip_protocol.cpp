// SCIP 2.0 (Hokuyo URG-04LX): the geometry PP gives, MRPT's CHokuyoURG as the driver's device
// (hokuyo_device.cpp), the emulator's session (scip_session.cpp). Its data lines carry a sum.
#include <cmath>

#include "amigobot_tracking/sensors/scip_protocol.h"

namespace amigobot_tracking {
namespace sensors {
namespace {

class ScipProtocol : public LaserProtocol {
 public:
  std::string name() const override { return "SCIP 2.0"; }
  std::unique_ptr<LaserDevice> open(const std::string& model, const std::string& port, int /*baud*/) const override {
    return openHokuyo(model, port);
  }

  std::unique_ptr<LaserSession> session(const LaserModel& model, const std::string& serial) const override {
    return makeScipSession(model, serial);
  }
  // The URG reports no echo within DMAX as 0, a dropout or a beam closer than DMIN as 1.
  std::uint32_t noMeasurementCode(float r) const override { return r > 0.0f ? 0u : 1u; }
  bool samplesAsItTurns() const override { return false; }
  std::string malformed(std::string telegram) const override {  // a data line one character short
    const std::size_t at = afterNth(telegram, '\n', 3);
    if (at != std::string::npos && at < telegram.size()) telegram.erase(at, 1);
    return telegram;
  }
  bool hasChecksum() const override { return true; }
  std::string badChecksum(std::string telegram) const override {  // the last data line's sum
    telegram[telegram.size() - 3] ^= 0x01;
    return telegram;
  }

  bool hasMotor() const override { return false; }
};

}  // namespace

int ScipGeometry::beams() const { return amax - amin + 1; }
double ScipGeometry::angleMin() const { return (amin - afrt) * 2.0 * M_PI / ares; }
double ScipGeometry::angleIncrement() const { return 2.0 * M_PI / ares; }

const LaserProtocol& scipProtocol() {
  static const ScipProtocol protocol;
  return protocol;
}

std::size_t afterNth(const std::string& text, char c, int n) {
  std::size_t at = 0;
  for (int i = 0; i < n; ++i) {
    at = text.find(c, at);
    if (at == std::string::npos) return at;
    ++at;
  }
  return at;
}

}  // namespace sensors
}  // namespace amigobot_tracking
