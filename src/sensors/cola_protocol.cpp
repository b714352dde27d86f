// CoLa-A (SICK TiM5xx, LMS1xx): the geometry of the scan telegram, the driver's CoLa-A client
// (cola_device.cpp), the emulator's session (cola_session.cpp). ASCII, no checksum.
#include <cmath>

#include "amigobot_tracking/sensors/cola_protocol.h"

namespace amigobot_tracking {
namespace sensors {
namespace {

constexpr double kTenThousandthDegree = M_PI / 180.0 / 10000.0;

class ColaProtocol : public LaserProtocol {
 public:
  std::string name() const override { return "CoLa-A"; }
  // Beam i at start + i step, turned by -90 deg from SICK's frame (0 deg = +y) to REP 103.
  int beams(const LaserModel& m) const override { return m.cola.beams; }
  double angleMin(const LaserModel& m) const override { return m.cola.start_angle * kTenThousandthDegree - M_PI / 2.0; }
  double angleIncrement(const LaserModel& m) const override { return m.cola.angular_step * kTenThousandthDegree; }

  std::unique_ptr<LaserDevice> open(const std::string& model, const std::string& port, int /*baud*/) const override {
    return openCola(model, port);
  }

  std::unique_ptr<LaserSession> session(const LaserModel& model, const std::string& serial) const override {
    return makeColaSession(model, serial);
  }
  std::uint32_t noMeasurementCode(float /*r*/) const override { return 0; }  // 0 for every beam without a measurement
  bool samplesAsItTurns() const override { return false; }
  std::string malformed(std::string telegram) const override {  // a range that is not a number
    const std::size_t at = afterNth(telegram, ' ', 26);
    if (at != std::string::npos && at < telegram.size()) telegram.replace(at, 1, "Z");
    return telegram;
  }
  bool hasChecksum() const override { return false; }

  bool hasMotor() const override { return false; }
};

}  // namespace

const LaserProtocol& colaProtocol() {
  static const ColaProtocol protocol;
  return protocol;
}

}  // namespace sensors
}  // namespace amigobot_tracking
