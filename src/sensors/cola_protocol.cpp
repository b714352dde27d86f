// CoLa-A (SICK TiM5xx, LMS1xx): the geometry of the scan telegram, the driver's CoLa-A client
// (cola_device.cpp), the emulator's session (cola_session.cpp). ASCII, no checksum.
#include <cmath>
#include <stdexcept>

#include "amigobot_tracking/sensors/cola_protocol.h"

namespace amigobot_tracking {
namespace sensors {
namespace {

constexpr double kTenThousandthDegree = M_PI / 180.0 / 10000.0;

class ColaProtocol : public LaserProtocol {
 public:
  std::string name() const override { return "CoLa-A"; }
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

double ColaGeometry::angleMin() const { return start_angle * kTenThousandthDegree - M_PI / 2.0; }
double ColaGeometry::angleIncrement() const { return angular_step * kTenThousandthDegree; }

const LaserProtocol& colaProtocol() {
  static const ColaProtocol protocol;
  return protocol;
}

void setLms1xxScanConfig(LaserModel* model, double frequency_hz, double resolution_deg) {
  if (frequency_hz != 25.0 && frequency_hz != 50.0) {
    throw std::invalid_argument("scan frequency: " + std::to_string(frequency_hz) + " Hz (LMS1xx: 25 or 50)");
  }
  if (resolution_deg != 0.25 && resolution_deg != 0.5) {
    throw std::invalid_argument("angular resolution: " + std::to_string(resolution_deg) + " deg (LMS1xx: 0.25 or 0.5)");
  }
  if (frequency_hz == 50.0 && resolution_deg == 0.25) {
    throw std::invalid_argument("angular resolution: 0.25 deg needs 25 Hz on an LMS1xx");
  }
  // A model's numbers are shared by its copies and never changed in place: a changed copy.
  ColaGeometry c = model->protocolGeometry<ColaGeometry>();
  c.scan_frequency = static_cast<int>(frequency_hz * 100.0);
  c.angular_step = static_cast<int>(resolution_deg * 10000.0);
  c.start_angle = -450000;  // -45 deg .. 225 deg in SICK's frame
  c.beam_count = 2700000 / c.angular_step + 1;
  model->setProtocolGeometry(c);
  model->rate = frequency_hz;
}

}  // namespace sensors
}  // namespace amigobot_tracking
